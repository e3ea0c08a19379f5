#!/usr/bin/env bash
# Runs every libFuzzer target of a fuzz build over its seed corpus (tests/fuzz/corpus/<target>).
#   scripts/run-fuzzers.sh [build-fuzz] [runs=N | time=SECONDS]
# runs=N (CI; default runs=2000) is a fixed amount of work per target, so CI stays in time on a
# cold 2-core machine; time=600 is the ten-minute run a release wants. New inputs go to a
# scratch folder, never into the committed corpus; a crash leaves its input in
# <build>/fuzz-artifacts/<target>/ and fails the script. Then make that input a regression
# fixture (tests/fuzz/corpus/<target>/ and a test of the failure class).
set -uo pipefail
cd "$(dirname "$0")/.."
build=${1:-build-fuzz}
mode=${2:-runs=2000}
case "$mode" in
  runs=*) limit=(-runs="${mode#runs=}") ;;
  time=*) limit=(-max_total_time="${mode#time=}") ;;
  *) echo "usage: $0 [build-dir] [runs=N|time=SECONDS]" >&2; exit 2 ;;
esac
status=0
for corpus in tests/fuzz/corpus/*/; do
  target=$(basename "$corpus")
  exe="$build/bin/$target"
  if [ ! -x "$exe" ]; then
    echo "run-fuzzers: $exe is missing (cmake --build --preset fuzz)" >&2
    status=1; continue
  fi
  scratch=$(mktemp -d)
  artifacts="$build/fuzz-artifacts/$target"
  mkdir -p "$artifacts"
  log="$build/fuzz-artifacts/$target.log"
  QT_QPA_PLATFORM=offscreen ASAN_OPTIONS=detect_leaks=0:abort_on_error=1 \
    UBSAN_OPTIONS=print_stacktrace=1 \
    "$exe" "${limit[@]}" -seed=1 -max_len=65536 -timeout=60 -rss_limit_mb=2560 -print_final_stats=1 \
    -artifact_prefix="$artifacts/" "$scratch" "$corpus" > "$log" 2>&1
  rc=$?
  execs=$(grep -m1 'stat::number_of_executed_units' "$log" | awk '{print $2}')
  cov=$(grep -E '^#[0-9]+.*(DONE|INITED)' "$log" | tail -1 | grep -oE 'cov: [0-9]+' | awk '{print $2}')
  echo "run-fuzzers: $target: exit $rc, ${execs:-?} executions, coverage ${cov:-?} edges"
  if [ $rc -ne 0 ]; then
    status=1
    tail -40 "$log" >&2
  fi
  rm -rf "$scratch"
done
exit $status
