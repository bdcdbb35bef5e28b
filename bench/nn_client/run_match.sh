#!/usr/bin/env bash
# Issue 14's acceptance run: RCSSServerMJ's own example agent with its trained T1 locomotion policy
# (`example/nn_client` of the RCSSServerMJ repository: nn_client.py and locomotion_nn.pth; Python with numpy, scipy
# and torch, Debian's python3-numpy, python3-scipy, python3-torch), run unchanged against turf-sim's RCSSServerMJ
# port. The client is not part of turf: give the directory holding it. Each agent goes through
# measure_proxy.py, which reads its torso's ground-truth pose from the perceptions. Everything runs on a private
# DDS domain, prefix and ports and is stopped at the end (also on Ctrl-C). Prints one Markdown table row:
#   | label | agents | upright % (mean) | falls | walked m (mean) | forward m (mean) |
# usage: run_match.sh --client-dir DIR [--agents 1] [--seconds 60] [--realtime] [--label TEXT] [--keep DIR]
#   default sync mode: turf waits for every agent, so results do not depend on the machine's load
set -euo pipefail
cd "$(dirname "$0")/../.."
BUILD_DIR=${TURF_BUILD_DIR:-build}
PYTHON=${PYTHON:-/usr/bin/python3}  # Debian's, where apt puts numpy, scipy and torch
CLIENT_DIR="" AGENTS=1 SECONDS_SIM=60 SYNC=--rcssservermj-sync MODE=sync LABEL="" KEEP=""
while [[ $# -gt 0 ]]; do
  case $1 in
    --client-dir) CLIENT_DIR=$2; shift 2 ;;
    --agents) AGENTS=$2; shift 2 ;;
    --seconds) SECONDS_SIM=$2; shift 2 ;;
    --realtime) SYNC="" MODE="real time"; shift ;;
    --label) LABEL=$2; shift 2 ;;
    --keep) KEEP=$2; shift 2 ;;
    -h|--help) sed -n '2,12p' "$0"; exit 0 ;;
    *) echo "unknown argument: $1" >&2; exit 2 ;;
  esac
done
[[ -f "$CLIENT_DIR/nn_client.py" && -f "$CLIENT_DIR/locomotion_nn.pth" ]] || {
  echo "--client-dir must hold RCSSServerMJ's example/nn_client (nn_client.py, locomotion_nn.pth)" >&2; exit 2; }
"$PYTHON" -c "import numpy, scipy, torch" 2>/dev/null || {
  echo "the client needs python3-numpy, python3-scipy and python3-torch (apt-get install them)" >&2; exit 2; }
LABEL=${LABEL:-"nn_client T1, $MODE"}
WORK=$(mktemp -d /tmp/turf-nn.XXXXXX)
PORT=$((24000 + RANDOM % 2000)) DOMAIN=$((100 + RANDOM % 50)) PREFIX="nn$$"
PIDS=() PROXIES=()
cleanup() {
  for p in "${PIDS[@]}"; do kill "$p" 2>/dev/null || true; done
  wait 2>/dev/null || true
  if [[ -n "$KEEP" ]]; then mkdir -p "$KEEP" && cp -r "$WORK"/. "$KEEP"/; fi
  rm -rf "$WORK"
}
trap cleanup EXIT INT TERM

"$BUILD_DIR/participants/sim/turf-sim" --scene configs/scenes/rcssservermj_fifa.yaml -d "$DOMAIN" -p "$PREFIX" \
  --rcssservermj --rcssservermj-agent-port "$PORT" --rcssservermj-monitor-port $((PORT + 1)) $SYNC \
  --log-level warn > "$WORK/turf-sim.log" 2>&1 &
PIDS+=($!)
for _ in $(seq 1 300); do  # up to 30 s for the port
  python3 - "$PORT" <<'PY' && break
import socket, sys
try:
    socket.create_connection(("127.0.0.1", int(sys.argv[1])), timeout=0.2).close()
except OSError:
    sys.exit(1)
PY
  sleep 0.1
done
for i in $(seq 1 "$AGENTS"); do
  python3 bench/nn_client/measure_proxy.py $((PORT + 10 + i)) "$PORT" "$WORK/agent$i.json" --seconds "$SECONDS_SIM" \
    > "$WORK/proxy$i.log" 2>&1 &
  PIDS+=($!)
  PROXIES+=($!)
done
sleep 0.5  # the proxies' listen sockets (a failed connect makes the client exit, and the row says so)
for i in $(seq 1 "$AGENTS"); do
  (cd "$CLIENT_DIR" && exec "$PYTHON" nn_client.py -s 127.0.0.1 -p $((PORT + 10 + i)) -t turf -n "$i" -r T1) \
    > "$WORK/client$i.log" 2>&1 &
  PIDS+=($!)
done
for p in "${PROXIES[@]}"; do wait "$p" || true; done
python3 - "$WORK" "$AGENTS" "$LABEL" <<'PY'
import json, sys, os
work, n, label = sys.argv[1], int(sys.argv[2]), sys.argv[3]
rows = []
for i in range(1, n + 1):
    path = os.path.join(work, f"agent{i}.json")
    rows.append(json.load(open(path)) if os.path.exists(path) else None)
ok = [r for r in rows if r and r["perceptions"] > 0]
if not ok:
    print(f"| {label} | {n} | no perceptions (see the logs with --keep) | | | |")
    sys.exit(0)
mean = lambda k: sum(r[k] for r in ok) / len(ok)
print(f"| {label} | {len(ok)}/{n} | {mean('upright_pct'):.1f} | {sum(r['falls'] for r in ok)} | "
      f"{mean('walked_m'):.2f} | {mean('forward_m'):.2f} |")
PY
