#!/usr/bin/env bash
# Optional: RCSSServerMJ's example agent with its trained T1 locomotion policy (example/nn_client of the public
# RCSSServerMJ repository, kept outside turf; Python with numpy, scipy and torch: Debian's python3-numpy,
# python3-scipy, python3-torch) walks on turf-sim --rcssservermj, unchanged, through a proxy that watches its torso
# (pose_proxy.py). Issue 14's acceptance run: the T1 must walk where the client commands (0.5 m/s forward after
# 1 s) and stay upright for 60 s of simulated time.
#   bench/rcssservermj_nn/run.sh --client-dir DIR [--seconds 60] [--python /usr/bin/python3] [--realtime]
set -euo pipefail
cd "$(dirname "$0")/../.."
BUILD_DIR=${TURF_BUILD_DIR:-build}
CLIENT_DIR="" SECONDS_SIM=60 PYTHON=/usr/bin/python3 REALTIME=0
while [ $# -gt 0 ]; do
  case "$1" in
    --client-dir) CLIENT_DIR=$2; shift 2 ;;
    --seconds) SECONDS_SIM=$2; shift 2 ;;
    --python) PYTHON=$2; shift 2 ;;
    --realtime) REALTIME=1; shift ;;
    *) echo "unknown argument $1 (see the comment at the top)" >&2; exit 2 ;;
  esac
done
[ -f "$CLIENT_DIR/nn_client.py" ] || { echo "--client-dir must hold nn_client.py and locomotion_nn.pth" >&2; exit 2; }
port=$((25100 + RANDOM % 400)) proxy=$((25600 + RANDOM % 400))
mode=(--rcssservermj-no-realtime) label="1 T1, sync, as fast as possible"
[ "$REALTIME" = 1 ] && mode=() label="1 T1, real time"
"$BUILD_DIR/participants/sim/turf-sim" --scene configs/scenes/rcssservermj_fifa.yaml -d $((90 + RANDOM % 9)) \
  -p "nn$$" --lockstep --rcssservermj --rcssservermj-agent-port "$port" --rcssservermj-monitor-port $((port + 1)) \
  "${mode[@]}" --log-level warn &
sim=$!
"$PYTHON" bench/rcssservermj_nn/pose_proxy.py --listen "$proxy" --server "$port" --seconds "$SECONDS_SIM" \
  --label "$label" &
watcher=$!
# The proxy needs turf-sim listening before the client connects through it: wait for the port (with a deadline).
for _ in $(seq 1 600); do
  (exec 3<>/dev/tcp/127.0.0.1/"$port") 2>/dev/null && break
  sleep 0.1
done
echo "| run | sim s | distance m | forward (x) m | falls | lowest torso m | final yaw deg |"
echo "| --- | --- | --- | --- | --- | --- | --- |"
(cd "$CLIENT_DIR" && exec "$PYTHON" nn_client.py -s 127.0.0.1 -p "$proxy" -t turfA -n 1 -r T1 >/dev/null 2>&1) &
client=$!
wait "$watcher" || true
kill "$client" 2>/dev/null || true
kill -INT "$sim" 2>/dev/null || true
wait "$sim" 2>/dev/null || true
