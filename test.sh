#!/usr/bin/env bash
# Checks the C++ formatting, builds native and web and runs every test: ctest (unit, headless
# GL, reference, extremes, the 100,000-frame run, the fuzz corpus replayed), then under
# AddressSanitizer + UndefinedBehaviorSanitizer what those find (the loaders, parsers, planner,
# BVH and CLI, the fuzz corpus, and one GL smoke test per renderer path and GL lifetime), then
# Playwright in Debian's Chromium. Every check is deterministic: random fuzzing is
# tools/run_fuzzers.sh SECONDS, run by hand. Prints each stage's time.
# Installs what is missing first. Exits non-zero on any failure.
#   SKIP_SANITIZERS=1 for a quicker local run
set -euo pipefail
cd "$(dirname "$0")"

stage_names=()
stage_seconds=()
stage_started=$SECONDS
stage() {  # ends the stage running (printing its time) and starts the next one, if named
  if [ ${#stage_names[@]} -gt 0 ]; then
    local took=$((SECONDS - stage_started))
    stage_seconds+=("$took")
    printf '== %s: %dm%02ds\n' "${stage_names[-1]}" $((took / 60)) $((took % 60))
  fi
  stage_started=$SECONDS
  if [ $# -gt 0 ]; then
    stage_names+=("$1")
    echo "== $1"
  fi
}
summary() {
  echo "== stage times"
  for i in "${!stage_seconds[@]}"; do
    printf '  %-44s %3dm%02ds\n' "${stage_names[$i]}" $((stage_seconds[i] / 60)) \
      $((stage_seconds[i] % 60))
  done
  printf '  %-44s %3dm%02ds\n' "total" $((SECONDS / 60)) $((SECONDS % 60))
}

stage "install what is missing"
source tools/setup.sh
ensure_debian_packages "${NATIVE_PACKAGES[@]}" "${WEB_PACKAGES[@]}" "${BROWSER_PACKAGES[@]}"
ensure_npm_packages

stage "C++ formatting (.clang-format)"
find src tests \( -name '*.cpp' -o -name '*.h' \) -print0 | xargs -0 clang-format --dry-run --Werror

stage "native build"
cmake --preset native >/dev/null
cmake --build --preset native

stage "native ctest"
ctest --preset native

if [ -z "${SKIP_SANITIZERS:-}" ]; then
  # What the sanitizers can find: memory and undefined behaviour in code that takes input or
  # manages memory (unit and CLI tests, the fuzz corpus), and one GL frame per renderer path
  # (traced, captured and searched, the course's file, glass, rough, steps, the error view),
  # plus GL object lifetime and lost contexts. The golden, reference and extreme suites run
  # natively above: under ASan they would repeat the same pixels at several times the cost.
  stage "ASan + UBSan build"
  cmake --preset asan >/dev/null
  cmake --build --preset asan --target unit_tests cli_tests gl_tests fuzz_replay_obj \
    fuzz_replay_png fuzz_replay_scene
  stage "ASan + UBSan ctest"
  ctest --preset asan -L 'unit|fuzz'
  ctest --preset asan -R "$(grep -v '^#' tests/asan_gl_smoke.txt | paste -sd'|')"
fi

stage "web build"
cmake --preset web >/dev/null
cmake --build --preset web

stage "Playwright"
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

stage
summary
