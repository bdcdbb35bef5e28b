#!/usr/bin/env bash
# Runs turf's benchmarks and prints a table. Usage: bench/run.sh [sim seconds]
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${TURF_BUILD_DIR:-build}
SECONDS_SIM=${1:-20}
bin="$BUILD_DIR/bench/turf-bench-sim"
[ -x "$bin" ] || bash scripts/build.sh
echo "turf-sim free-running (2 ms step), world state 100 Hz + cameras 60 Hz published; $(nproc) cores"
"$bin" --header --seconds "$SECONDS_SIM" --scene configs/scenes/ssl_div_a.yaml
"$bin" --seconds "$SECONDS_SIM" --scene configs/scenes/ssl_div_a_2x16.yaml
"$bin" --seconds "$SECONDS_SIM" --scene configs/scenes/ssl_div_a.yaml --subscribe
"$bin" --seconds "$SECONDS_SIM" --scene configs/scenes/ssl_div_a_2x16.yaml --subscribe
"$bin" --seconds "$SECONDS_SIM" --scene configs/scenes/ssl_div_a.yaml --drive
"$bin" --seconds "$SECONDS_SIM" --scene configs/scenes/ssl_div_a_2x16.yaml --drive
echo "RTF: simulated seconds per wall second; the physics loop is one thread. client process: a second"
echo "process that receives world states / camera frames ('listen'), and also commands every robot at"
echo "each world state ('drive'). sim CPU: user+sys of the simulator process (incl. Fast DDS threads)."
