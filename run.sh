#!/usr/bin/env bash
# Builds the web bundle (Emscripten -> wasm + WebGL2) and serves the demo on
# http://127.0.0.1:${PORT:-8080}/ . Installs what is missing first.
set -euo pipefail
cd "$(dirname "$0")"
source tools/setup.sh
ensure_debian_packages "${WEB_PACKAGES[@]}"
ensure_npm_packages  # lil-gui for the page (and Playwright, unused here)

cmake --preset web >/dev/null
cmake --build --preset web

PORT="${PORT:-8080}"
echo
echo "Open http://127.0.0.1:${PORT}/ in a browser with WebGL2 (Ctrl+C stops the server)."
exec node tools/serve.mjs build/web/site "$PORT"
