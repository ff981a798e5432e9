#!/usr/bin/env bash
# A short fuzzing run of every target (CI): builds with clang, seeds each corpus from assets/,
# the shared examples and the tests, runs each target for FUZZ_SECONDS and prints its figures.
set -euo pipefail
cd "$(dirname "$0")/../.."
seconds=${FUZZ_SECONDS:-20}
build=build-fuzz
cmake -S . -B "$build" -DISOPARM_FUZZ=ON -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$build" -j"$(nproc)" --target fuzz_protocol fuzz_scene fuzz_expression >/dev/null

corpus=$build/corpus
rm -rf "$corpus" && mkdir -p "$corpus"/{protocol,scene,expression}
cp assets/requests/*.json "$corpus/protocol/" 2>/dev/null || true
cp ../shared/spec/examples/*.request.json "$corpus/protocol/" 2>/dev/null || true
cp assets/scenes/*.json "$corpus/scene/" 2>/dev/null || true
cp tests/fuzz/seeds/expression/* "$corpus/expression/" 2>/dev/null || true
# Crashes found earlier stay as regression inputs: each must now run clean.
for t in protocol scene expression; do
  for f in tests/fuzz/regressions/$t/*; do
    [ -f "$f" ] || continue
    "$build/tests/fuzz/fuzz_$t" "$f" >/dev/null 2>&1 || { echo "fuzz_$t: regression input $f fails"; exit 1; }
  done
done

status=0
for t in protocol scene expression; do
  log=$build/fuzz_$t.log
  if ! ASAN_OPTIONS=detect_leaks=1 "$build/tests/fuzz/fuzz_$t" "$corpus/$t" -max_total_time="$seconds" \
      -max_len=65536 -rss_limit_mb=2048 -timeout=10 -print_final_stats=1 -artifact_prefix="$build/crash-$t-" >"$log" 2>&1; then
    echo "fuzz_$t: FAILED (see $log)"; tail -40 "$log"; status=1
  fi
  runs=$(grep -m1 'stat::number_of_executed_units' "$log" | awk '{print $2}')
  echo "fuzz_$t: ${runs:-?} executions in ${seconds}s, corpus $(ls "$corpus/$t" | wc -l) inputs"
done
exit $status
