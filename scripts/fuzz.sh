#!/usr/bin/env bash
# Runs every libFuzzer target (tests/fuzz.cmake: clang, ASan + UBSan) for SECONDS each, on demand, and prints a
# table: executions, executions per second, corpus size and findings per target. A finding is a crash, leak,
# timeout or sanitizer report; its input is saved in build/tests/fuzz_findings/<target>/ and the script exits 1.
#   scripts/fuzz.sh [SECONDS]      (default 60)
set -euo pipefail
cd "$(dirname "$0")/.."
SECONDS_EACH=${1:-60}
if ! [[ "$SECONDS_EACH" =~ ^[1-9][0-9]*$ ]]; then
  echo "usage: scripts/fuzz.sh [SECONDS] (a whole number of seconds > 0)" >&2
  exit 2
fi
BUILD_DIR=${TURF_BUILD_DIR:-build}
[ -d "$BUILD_DIR" ] || bash scripts/build.sh
cmake --build "$BUILD_DIR" -j "$(nproc)" >/dev/null
mapfile -t targets < <(find "$BUILD_DIR/tests" -maxdepth 1 -type f -name 'fuzz_*' -perm -u+x | sort)
if [ "${#targets[@]}" -eq 0 ]; then
  echo "no fuzz targets in $BUILD_DIR/tests (clang++ not installed? run scripts/setup.sh)" >&2
  exit 1
fi
echo "libFuzzer, ${SECONDS_EACH} s per target, $(nproc) cores"
echo "| target | executions | per second | corpus | findings |"
echo "| --- | --- | --- | --- | --- |"
failed=0
for bin in "${targets[@]}"; do
  name=$(basename "$bin")
  corpus="$BUILD_DIR/tests/fuzz_corpus/${name#fuzz_}"
  seeds="tests/fuzz/seeds/${name#fuzz_}"
  findings="$BUILD_DIR/tests/fuzz_findings/${name#fuzz_}"
  mkdir -p "$corpus" "$seeds" "$findings"
  log=$(mktemp)
  status=0
  "$bin" -max_total_time="$SECONDS_EACH" -max_len=65536 -rss_limit_mb=2048 -print_final_stats=1 \
    -artifact_prefix="$findings/" \
    "$corpus" "$seeds" >"$log" 2>&1 || status=$?
  execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || true)
  if [ -z "$execs" ]; then
    execs=$(grep -o '#[0-9]*' "$log" | tail -1 | tr -d '#' || true)
  fi
  execs=${execs:-0}
  rate=$((execs / SECONDS_EACH))
  units=$(find "$corpus" -type f | wc -l)
  found=$(find "$findings" -type f | wc -l)
  if [ "$status" -ne 0 ] || [ "$found" -gt 0 ]; then
    failed=1
    echo "| $name | $execs | $rate | $units | $found (exit $status; log: $log) |"
  else
    echo "| $name | $execs | $rate | $units | 0 |"
    rm -f "$log"
  fi
done
exit $failed
