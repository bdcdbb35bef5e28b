#!/usr/bin/env bash
# Runs the whole test suite N times in a row on a clean clone of HEAD while
# every core is kept busy by another process, and prints a pass/fail table per
# test. A test that passes only on a quiet machine fails CI at random: this is
# the check to run before declaring the suite trustworthy.
#
# Usage: scripts/soak-tests.sh [N] [options]
#   N                 runs (default 10)
#   --here            use this work tree's build (./build) instead of a clean clone
#   --load K          busy processes while the tests run (default: number of cores)
#   --filter REGEX    only tests matching REGEX (ctest -R)
#   --keep            keep the clone afterwards (its path is printed)
# Exit status: 0 when every run of every test passed.
set -euo pipefail
cd "$(dirname "$0")/.."
repo=$(pwd)

runs=10
here=false
load=$(nproc)
filter=""
keep=false
while [ $# -gt 0 ]; do
  case "$1" in
    --here) here=true ;;
    --load) load=$2; shift ;;
    --filter) filter=$2; shift ;;
    --keep) keep=true ;;
    -h|--help) sed -n '2,14p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    [0-9]*) runs=$1 ;;
    *) echo "soak: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
  shift
done

if $here; then
  tree=$repo
else
  tree=$(mktemp -d /tmp/turf-soak.XXXXXX)
  git clone -q --no-hardlinks "$repo" "$tree"
  git -C "$tree" checkout -q "$(git rev-parse HEAD)"
  echo "soak: clean clone of $(git rev-parse --short HEAD) in $tree"
fi
build=$tree/build
logs=$tree/soak-logs
mkdir -p "$logs"

echo "soak: building (quiet machine)"
(cd "$tree" && bash scripts/build.sh >"$logs/build.log" 2>&1) || { echo "soak: build failed, see $logs/build.log"; exit 1; }

load_pids=()
stop_load() {
  for p in "${load_pids[@]:-}"; do [ -n "$p" ] && kill "$p" 2>/dev/null || true; done
  load_pids=()
}
cleanup() {
  stop_load
  if ! $here && ! $keep && [ "${failed_runs:-1}" -eq 0 ]; then rm -rf "$tree"; fi
}
trap cleanup EXIT INT TERM

echo "soak: $load busy process(es) on $(nproc) core(s) while the tests run"
for _ in $(seq "$load"); do
  bash -c 'while :; do :; done' &
  load_pids+=($!)
done

ctest_args=(--test-dir "$build" -j "$(nproc)" --timeout 300 --output-on-failure)
[ -n "$filter" ] && ctest_args+=(-R "$filter")
failed_runs=0
start=$(date +%s)
for i in $(seq "$runs"); do
  t0=$(date +%s)
  if ctest "${ctest_args[@]}" >"$logs/run-$i.log" 2>&1; then result=passed; else result=FAILED; failed_runs=$((failed_runs + 1)); fi
  summary=$(grep -E "tests passed|tests failed" "$logs/run-$i.log" | tail -1)
  echo "soak: run $i/$runs $result in $(( $(date +%s) - t0 )) s: $summary"
done
stop_load

# One line per test: how often it passed and failed over all runs.
echo
printf '%-90s %6s %6s\n' "test" "passed" "failed"
cat "$logs"/run-*.log |
  sed -n -E 's/^ *[0-9]+\/[0-9]+ Test +#[0-9]+: ([^ ]+) \.+.*(Passed|Failed|\*\*\*Failed|\*\*\*Timeout|\*\*\*Exception|Not Run).*/\1 \2/p' |
  awk '{ if ($2 == "Passed") p[$1]++; else f[$1]++; seen[$1] = 1 }
       END { for (t in seen) printf "%-90s %6d %6d\n", t, p[t], f[t] }' |
  sort -k3,3nr -k1,1
echo
echo "soak: $runs run(s) in $(( $(date +%s) - start )) s under load $load; $failed_runs run(s) with failures; logs in $logs"
[ "$failed_runs" -eq 0 ]
