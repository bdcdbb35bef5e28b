#!/usr/bin/env bash
# The run command: sets up, builds and starts the default SSL match on this
# machine, paced in real time, until Ctrl-C. Extra arguments go to turf-sim
# (try --help).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
BUILD_DIR=${TURF_BUILD_DIR:-build}
exec "$BUILD_DIR/participants/sim/turf-sim" --scene configs/scenes/ssl_div_a.yaml "$@"
