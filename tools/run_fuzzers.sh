#!/usr/bin/env bash
# Builds the libFuzzer targets (the `fuzz` preset: clang, ASan + UBSan) and runs them.
#
#   tools/run_fuzzers.sh --replay     every input of the committed corpus once, nothing new: the
#                                     deterministic regression check ./test.sh runs (each past
#                                     finding is in the corpus)
#   tools/run_fuzzers.sh [SECONDS]    explore: each target SECONDS seconds (default 60) with a
#                                     random seed on a copy of its corpus, so the committed corpus
#                                     never grows. Not in ./test.sh: a random search can find a
#                                     new input on any run, and CI must only fail on a change.
#   build/fuzz/tests/fuzz/fuzz_obj CRASH_FILE     # reproduce one input
#
# Exits non-zero if any target crashes, leaks, runs out of memory or times out; the reproducer
# and the log are kept in build/fuzz/runs/<time>/. Add a finding to tests/fuzz/corpus/<target>/.
set -euo pipefail
cd "$(dirname "$0")/.."

replay=""
if [ "${1:-}" = "--replay" ]; then
  replay=1
  shift
fi
run_seconds="${1:-60}"
if ! [[ "$run_seconds" =~ ^[0-9]+$ ]] || [ "$run_seconds" -lt 1 ]; then
  echo "usage: $0 [SECONDS]  (a whole number of seconds per target, default 60)" >&2
  exit 2
fi

echo "== configure and build (preset fuzz)"
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz

# target:corpus folder under tests/fuzz/corpus:dictionary under tests/fuzz
targets=("fuzz_obj:obj:obj.dict" "fuzz_png:png:png.dict" "fuzz_scene:scene:scene.dict")

run_dir="build/fuzz/runs/$(date +%Y%m%d-%H%M%S)"
mkdir -p "$run_dir"
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:symbolize=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"

failed=()
summary=()
for entry in "${targets[@]}"; do
  IFS=: read -r target corpus dict <<<"$entry"
  work="$run_dir/$target"
  mkdir -p "$work/corpus" "$work/artifacts"
  cp tests/fuzz/corpus/"$corpus"/* "$work/corpus/"
  if [ -n "$replay" ]; then
    echo "== $target: the $(find "$work/corpus" -type f | wc -l) corpus inputs once (log: $work/log.txt)"
    limits=(-runs=0)
  else
    echo "== $target for ${run_seconds}s (log: $work/log.txt)"
    limits=(-max_total_time="$run_seconds")
  fi
  status=0
  "build/fuzz/tests/fuzz/$target" "$work/corpus" \
    "${limits[@]}" -rss_limit_mb=2048 -detect_leaks=1 -timeout=10 \
    -dict="tests/fuzz/$dict" -artifact_prefix="$work/artifacts/" -print_final_stats=1 \
    >"$work/log.txt" 2>&1 || status=$?
  runs=$(grep -oE 'stat::number_of_executed_units: [0-9]+' "$work/log.txt" | tail -1 | grep -oE '[0-9]+$' || true)
  coverage=$(grep -oE 'cov: [0-9]+' "$work/log.txt" | tail -1 | tail -1 | grep -oE '[0-9]+$' || true)
  artifacts=$(find "$work/artifacts" -type f | wc -l)
  if [ "$status" -ne 0 ] || [ "$artifacts" -ne 0 ]; then
    failed+=("$target")
    summary+=("$target: FAILED (exit $status, ${runs:-?} runs); artifacts in $work/artifacts")
    grep -E '^==[0-9]+==ERROR|SUMMARY:|runtime error|invariant broken|Test unit written' "$work/log.txt" | head -20 || true
  else
    summary+=("$target: ok, ${runs:-?} runs, coverage ${coverage:-?} edges, corpus $(find "$work/corpus" -type f | wc -l) files")
  fi
done

echo "== summary"
printf '%s\n' "${summary[@]}"
if [ "${#failed[@]}" -ne 0 ]; then
  echo "fuzzers that failed: ${failed[*]}" >&2
  exit 1
fi
