#!/usr/bin/env bash
# Builds native and web and runs every test: ctest (unit + headless GL), then Playwright in
# Debian's Chromium. Installs what is missing first. Exits non-zero on any failure.
set -euo pipefail
cd "$(dirname "$0")"
source tools/setup.sh
ensure_debian_packages "${NATIVE_PACKAGES[@]}" "${WEB_PACKAGES[@]}" "${BROWSER_PACKAGES[@]}"
ensure_npm_packages

echo "== native build and ctest"
cmake --preset native >/dev/null
cmake --build --preset native
ctest --preset native

echo "== web build and Playwright"
cmake --preset web >/dev/null
cmake --build --preset web
npx playwright test
