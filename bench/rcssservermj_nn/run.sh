#!/usr/bin/env bash
# Optional: RCSSServerMJ's example agent with its trained T1 locomotion policy (example/nn_client of the public
# RCSSServerMJ repository, kept outside turf; Python with numpy, scipy and torch: Debian's python3-numpy,
# python3-scipy, python3-torch) walks on turf-sim --rcssservermj, unchanged, through a proxy that watches its torso
# (pose_proxy.py). Issue 14's acceptance run: the T1 must walk where the client commands (0.5 m/s forward after
# 1 s) and stay upright for 60 s of simulated time.
#   bench/rcssservermj_nn/run.sh --client-dir DIR [--seconds 60] [--players "1 2 3"] [--python /usr/bin/python3]
#                                [--realtime] [--reference-mujoco DIR --reference-robot DIR [--open-loop]]
# --players: the client's player numbers, one run each (each beams to its own spot: the same walk from other
# places, so the spread shows how sensitive the walk is). --reference-mujoco (the unpacked @mujoco/mujoco npm
# package, with mujoco.js) and --reference-robot (RCSSServerMJ's src/rcsssmj/resources/robots/T1, with robot.xml
# and meshes/), both kept outside turf: each player also walks on MuJoCo 3 with the reference's own robot file
# (reference_server.mjs, run by Debian's nodejs), in the same table. --open-loop instead: the first player's
# answers on the reference, captured, are sent again unchanged (replay_agent.py) to turf and to the reference, and
# compare_traces.py prints how far the two torsos are apart second by second (the model, the engine and the
# protocol's timing compared, without the policy's feedback).
set -euo pipefail
cd "$(dirname "$0")/../.."
BUILD_DIR=${TURF_BUILD_DIR:-build}
CLIENT_DIR="" SECONDS_SIM=60 PYTHON=/usr/bin/python3 REALTIME=0 PLAYERS=1 REF_MUJOCO="" REF_ROBOT="" OPEN_LOOP=0
while [ $# -gt 0 ]; do
  case "$1" in
    --client-dir) CLIENT_DIR=$2; shift 2 ;;
    --seconds) SECONDS_SIM=$2; shift 2 ;;
    --players) PLAYERS=$2; shift 2 ;;
    --python) PYTHON=$2; shift 2 ;;
    --realtime) REALTIME=1; shift ;;
    --open-loop) OPEN_LOOP=1; shift ;;
    --reference-mujoco) REF_MUJOCO=$(realpath "$2"); shift 2 ;;
    --reference-robot) REF_ROBOT=$(realpath "$2"); shift 2 ;;
    *) echo "unknown argument $1 (see the comment at the top)" >&2; exit 2 ;;
  esac
done
[ -f "$CLIENT_DIR/nn_client.py" ] || { echo "--client-dir must hold nn_client.py and locomotion_nn.pth" >&2; exit 2; }
if [ -n "$REF_MUJOCO$REF_ROBOT" ]; then
  [ -f "$REF_MUJOCO/mujoco.js" ] || { echo "--reference-mujoco must hold mujoco.js (@mujoco/mujoco)" >&2; exit 2; }
  [ -f "$REF_ROBOT/robot.xml" ] || { echo "--reference-robot must hold robot.xml and meshes/" >&2; exit 2; }
  command -v node > /dev/null || { echo "the reference needs node (Debian: nodejs)" >&2; exit 2; }
fi
[ "$OPEN_LOOP" = 0 ] || [ -n "$REF_MUJOCO" ] || { echo "--open-loop needs the reference" >&2; exit 2; }
work=$(mktemp -d /tmp/turf-nn.XXXXXX)
trap 'rm -rf "$work"' EXIT
mode=(--rcssservermj-no-realtime) label="sync, as fast as possible"
[ "$REALTIME" = 1 ] && mode=() label="real time"

# Waits (with a deadline) until something listens on port $1.
wait_port() {
  for _ in $(seq 1 600); do
    (exec 3<>/dev/tcp/127.0.0.1/"$1") 2>/dev/null && return 0
    sleep 0.1
  done
  echo "nothing listens on port $1" >&2
  return 1
}

# Starts turf-sim's RCSSServerMJ front-end (sim) or the reference (ref) on a free port: sets $port and $server.
start_server() {
  if [ "$1" = sim ]; then
    port=$((25100 + RANDOM % 400))
    "$BUILD_DIR/participants/sim/turf-sim" --scene configs/scenes/rcssservermj_fifa.yaml -d $((90 + RANDOM % 9)) \
      -p "nn$$" --lockstep --rcssservermj --rcssservermj-agent-port "$port" \
      --rcssservermj-monitor-port $((port + 1)) "${mode[@]}" --log-level warn &
  else
    port=$((26100 + RANDOM % 400))
    node bench/rcssservermj_nn/reference_server.mjs "$port" "$REF_MUJOCO" "$REF_ROBOT" 2> "$work/reference.log" &
  fi
  server=$!
  wait_port "$port"
}

stop_server() {
  kill -INT "$server" 2>/dev/null || true
  wait "$server" 2>/dev/null || true
}

# One walk of the client: player $1, row label $2, extra pose_proxy.py arguments after them.
walk() {
  local proxy=$((25600 + RANDOM % 400)) player=$1 label=$2
  shift 2
  "$PYTHON" bench/rcssservermj_nn/pose_proxy.py --listen "$proxy" --server "$port" --seconds "$SECONDS_SIM" \
    --label "$label" "$@" &
  local watcher=$!
  wait_port "$proxy"  # the proxy skips a probe's connection (it sends nothing)
  (cd "$CLIENT_DIR" && exec "$PYTHON" nn_client.py -s 127.0.0.1 -p "$proxy" -t turfA -n "$player" -r T1 \
    >/dev/null 2>&1) &
  local client=$!
  wait "$watcher" || true
  kill "$client" 2>/dev/null || true
}

reference_label() { echo "reference ($(grep -o 'MuJoCo [0-9.]*' "$work/reference.log"))"; }

if [ "$OPEN_LOOP" = 1 ]; then
  player=${PLAYERS%% *}
  start_server ref
  walk "$player" "$(reference_label), player $player, captured" --capture "$work/answers.txt" > /dev/null
  label=$(reference_label)
  stop_server
  for side in sim ref; do
    start_server "$side"
    "$PYTHON" bench/rcssservermj_nn/replay_agent.py --port "$port" --capture "$work/answers.txt" \
      --trace "$work/$side.txt"
    stop_server
  done
  "$PYTHON" bench/rcssservermj_nn/compare_traces.py "$work/sim.txt" "$work/ref.txt" turf "$label"
  exit 0
fi

echo "| run | sim s | distance m | forward (x) m | falls | lowest torso m | mean torso m | final yaw deg |"
echo "| --- | --- | --- | --- | --- | --- | --- | --- |"
for player in $PLAYERS; do
  start_server sim
  walk "$player" "turf, player $player, $label"
  stop_server
  [ -n "$REF_MUJOCO" ] || continue
  start_server ref
  walk "$player" "$(reference_label), player $player"
  stop_server
done
