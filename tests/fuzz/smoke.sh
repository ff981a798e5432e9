#!/usr/bin/env bash
# A short fuzzing run of every target (CI): builds with clang, seeds each corpus from assets/,
# the protocol examples (tests/protocol/examples) and tests/fuzz/seeds, replays the regression inputs, runs each target for
# FUZZ_SECONDS and prints its figures (executions, corpus size, crashes).
# FUZZ_BUILD names the build directory (default build-fuzz), FUZZ_TARGETS the targets to run.
set -euo pipefail
cd "$(dirname "$0")/../.."
seconds=${FUZZ_SECONDS:-20}
build=${FUZZ_BUILD:-build-fuzz}
targets=${FUZZ_TARGETS:-protocol scene expression script}
jobs=$(nproc 2>/dev/null || echo 2)
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S . -B "$build" -DISOPARM_FUZZ=ON -DCMAKE_CXX_COMPILER=clang++ "${launcher[@]}" \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$build" -j"$jobs" --target $(for t in $targets; do printf 'fuzz_%s ' "$t"; done) >/dev/null

# A sanitizer report is a failure, not a line in the log: UBSan must stop the run too.
export ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=0
export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1

corpus=$build/corpus
rm -rf "$corpus" && mkdir -p "$corpus"/{protocol,scene,expression,script}
cp assets/requests/*.json "$corpus/protocol/" 2>/dev/null || true
cp tests/protocol/examples/*.request.json "$corpus/protocol/"
cp assets/scenes/*.json "$corpus/scene/" 2>/dev/null || true
cp tests/scripts/*.json "$corpus/script/" 2>/dev/null || true
for t in protocol scene expression script; do
  cp tests/fuzz/seeds/$t/* "$corpus/$t/" 2>/dev/null || true
done

# Crashes found earlier stay as regression inputs: each must now run clean.
regressions=0
for t in $targets; do
  for f in tests/fuzz/regressions/$t/*; do
    [ -f "$f" ] || continue
    regressions=$((regressions + 1))
    "$build/tests/fuzz/fuzz_$t" -timeout=10 -rss_limit_mb=2048 "$f" >"$build/regression.log" 2>&1 || {
      echo "fuzz_$t: regression input $f fails"; tail -40 "$build/regression.log"; exit 1; }
  done
done
echo "fuzz: $regressions regression inputs replayed clean"

status=0
for t in $targets; do
  log=$build/fuzz_$t.log
  seeds=$(ls "$corpus/$t" | wc -l)
  dict=()
  [ -f "tests/fuzz/$t.dict" ] && dict=(-dict="tests/fuzz/$t.dict")
  if ! "$build/tests/fuzz/fuzz_$t" "$corpus/$t" "${dict[@]}" -max_total_time="$seconds" \
      -max_len=65536 -rss_limit_mb=2048 -malloc_limit_mb=1024 -timeout=10 -print_final_stats=1 \
      -artifact_prefix="$build/crash-$t-" >"$log" 2>&1; then
    echo "fuzz_$t: FAILED (see $log; the input is $build/crash-$t-*)"; tail -40 "$log"; status=1
  elif grep -q 'runtime error' "$log"; then
    echo "fuzz_$t: FAILED: a sanitizer reported an error (see $log)"; grep -m5 'runtime error' "$log"
    status=1
  fi
  runs=$(grep -m1 'stat::number_of_executed_units' "$log" | awk '{print $2}')
  rate=$(grep -m1 'stat::average_exec_per_sec' "$log" | awk '{print $2}')
  echo "fuzz_$t: ${runs:-?} executions in ${seconds}s (${rate:-?}/s), corpus ${seeds} seeds -> $(ls "$corpus/$t" | wc -l) inputs"
done
exit $status
