#!/usr/bin/env bash
# The run command: sets up, builds and starts the default SSL match (profile
# configs/launch/ssl_div_a.yaml: turf-sim, the grSim, SSL-Vision and SSL
# simulation-protocol bridges and the web viewer) on this machine until Ctrl-C. Extra arguments go
# to `turf launch` (try --help, --print, --domain N, --realism ideal,
# --set sim.speed=max).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
BUILD_DIR=${TURF_BUILD_DIR:-build}
exec "$BUILD_DIR/participants/launcher/turf" launch ssl_div_a "$@"
