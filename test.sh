#!/usr/bin/env bash
# Checks the C++ formatting, builds native and web and runs every test: ctest (unit, headless
# GL, reference, extremes, the 100,000-frame run), the same suite under AddressSanitizer +
# UndefinedBehaviorSanitizer, the libFuzzer targets over their committed corpus (every past
# finding, replayed once), then Playwright in Debian's Chromium. Every check is deterministic:
# random fuzzing is tools/run_fuzzers.sh SECONDS, run by hand.
# Installs what is missing first. Exits non-zero on any failure.
#   SKIP_SANITIZERS=1 / SKIP_FUZZ=1 for a quicker local run
set -euo pipefail
cd "$(dirname "$0")"
source tools/setup.sh
ensure_debian_packages "${NATIVE_PACKAGES[@]}" "${WEB_PACKAGES[@]}" "${BROWSER_PACKAGES[@]}"
ensure_npm_packages

echo "== C++ formatting (.clang-format)"
find src tests \( -name '*.cpp' -o -name '*.h' \) -print0 | xargs -0 clang-format --dry-run --Werror

echo "== native build and ctest"
cmake --preset native >/dev/null
cmake --build --preset native
ctest --preset native

if [ -z "${SKIP_SANITIZERS:-}" ]; then
  echo "== the ctest suite under ASan + UBSan (the long run is left out: it is slow there)"
  cmake --preset asan >/dev/null
  cmake --build --preset asan
  ctest --preset asan -LE longrun
fi

if [ -z "${SKIP_FUZZ:-}" ]; then
  echo "== fuzz targets over their committed corpus"
  tools/run_fuzzers.sh --replay
fi

echo "== web build and Playwright"
cmake --preset web >/dev/null
cmake --build --preset web
# The page's server on a port the system picks (0): it writes the port it got once listening.
port_file="build/test-server.port"
rm -f "$port_file"
node tools/serve.mjs build/web/site 0 --port-file "$port_file" >/dev/null &
server=$!
trap 'kill "$server" 2>/dev/null || true' EXIT
for _ in $(seq 100); do [ -s "$port_file" ] && break; sleep 0.1; done
[ -s "$port_file" ] || { echo "test.sh: the test server did not start"; exit 1; }
export TEST_BASE_URL="http://127.0.0.1:$(cat "$port_file")/"
npx playwright test
