#!/usr/bin/env bash
# One measured match of real SimSpark agents (UT Austin Villa's base agent, `agentspark`) on turf (issue 12):
# `turf launch simspark` and turf-viewer on a private DDS domain, prefix and ports; N agents; measure.py from the
# kick-off for SECONDS of sim time; everything stopped at the end (also on Ctrl-C). Prints one Markdown table row:
#   | label | seed | mean upright % | falls | best approach m | ball moved |
# The agent is not part of turf: build it from its public repository (LARG/utaustinvilla3d; see issue 12 for the
# steps) and give the binary and its source directory (it reads ./skills and ./paramfiles from there).
#
# usage: run_match.sh --ut-agent PATH --agent-dir DIR [--agents 4] [--layout split|one] [--realtime]
#                     [--type 0..4] [--seconds 60] [--label TEXT] [--keep DIR] [--trace] [--scene FILE] [--seed N]
#   split: unums 1..N/2 on team UTA (left), 1..N/2 on UTB (right); one: 1..N on UTA
#   default sync mode (turf waits for every agent: results do not depend on the machine's load)
#   --keep DIR: keep the logs and measure.py's CSVs (torso and ball; feet) and JSON there
#   --trace: each agent through proxy.py, its messages kept as trace_<team>_<unum>.jsonl (with --keep)
#   --scene FILE: a variant of configs/scenes/simspark_match.yaml to measure (same robots; default that file)
#   --seed N: the SimSpark league's seed (vision and beam noise, each agent's calibration error, the game's draws);
#     default a fresh one per run, as rcssserver3d draws its own (randomServer.seed(0)): with one fixed seed every
#     run repeats the same noise and the runs are not independent samples. The row names it, to repeat a run.
set -euo pipefail
cd "$(dirname "$0")/../.."
BUILD_DIR=${TURF_BUILD_DIR:-build}
scene=configs/scenes/simspark_match.yaml agent="" agent_dir="" n=4 layout=split sync=true type=0 seconds=60 label="" keep="" trace=false
seed=$(( (RANDOM << 15 | RANDOM) + 1 ))
while [[ $# -gt 0 ]]; do
  case "$1" in
    --ut-agent) agent=$2; shift 2 ;;
    --agent-dir) agent_dir=$2; shift 2 ;;
    --agents) n=$2; shift 2 ;;
    --layout) layout=$2; shift 2 ;;
    --realtime) sync=false; shift ;;
    --type) type=$2; shift 2 ;;
    --seconds) seconds=$2; shift 2 ;;
    --label) label=$2; shift 2 ;;
    --keep) keep=$2; shift 2 ;;
    --trace) trace=true; shift ;;
    --scene) scene=$2; shift 2 ;;
    --seed) seed=$2; shift 2 ;;
    -h|--help) sed -n '2,15p' "$0"; exit 0 ;;
    *) echo "run_match.sh: unknown argument $1 (--help)" >&2; exit 2 ;;
  esac
done
[[ -x "$agent" ]] || { echo "run_match.sh: --ut-agent PATH: not an executable: '$agent'" >&2; exit 2; }
[[ -d "$agent_dir/skills" ]] || { echo "run_match.sh: --agent-dir: no skills/ in '$agent_dir'" >&2; exit 2; }
[[ -n "$label" ]] || label="$n agents, type $type, $([[ $sync == true ]] && echo sync || echo real time)"

work=$(mktemp -d)
domain=$((90 + RANDOM % 9)) port=$((23600 + RANDOM % 400 * 2)) viewer_port=$((24500 + RANDOM % 400))
prefix="ut$$"
pids=()
cleanup() {
  for p in "${pids[@]}"; do kill -INT "$p" 2>/dev/null || true; done
  for _ in $(seq 1 20); do
    alive=0
    for p in "${pids[@]}"; do kill -0 "$p" 2>/dev/null && alive=1; done
    [[ $alive == 0 ]] && break
    sleep 0.5
  done
  for p in "${pids[@]}"; do kill -9 "$p" 2>/dev/null || true; done
  if [[ -n "$keep" ]]; then mkdir -p "$keep" && cp -r "$work"/. "$keep"/; fi
  rm -rf "$work"
}
trap cleanup EXIT

# Every parked robot of the match scene built as the agents' type (the shipped scene has 14 of type 0, 2 of each
# other type), through a copy of the profile naming a copy of the scene.
sed -e "s/nao_type: [0-4]/nao_type: $type/" -e "s|\.\./robots/nao\.xml|$PWD/configs/robots/nao.xml|" \
  "$scene" > "$work/scene.yaml"
sed "s|^scene: .*|scene: $work/scene.yaml|" configs/launch/simspark.yaml > "$work/simspark.yaml"
"$BUILD_DIR/participants/launcher/turf" launch "$work/simspark.yaml" --domain "$domain" --prefix "$prefix" \
  --set simspark.listen=127.0.0.1 --set simspark.agent-port="$port" --set simspark.monitor-port=$((port + 1)) \
  --set simspark.sync="$sync" --set simspark.seed="$seed" > "$work/turf.log" 2>&1 &
pids+=($!)
"$BUILD_DIR/participants/viewer/turf-viewer" --domain "$domain" --prefix "$prefix" --port "$viewer_port" \
  --rate 50 > "$work/viewer.log" 2>&1 &
pids+=($!)
# Ready when the bridge says where agents connect (a log file has no notification: poll it, with a deadline).
for _ in $(seq 1 120); do grep -q "agents: TCP" "$work/turf.log" && break; sleep 0.5; done
grep -q "agents: TCP" "$work/turf.log" || { echo "run_match.sh: turf did not start (log: $work/turf.log)" >&2; exit 1; }

python3 bench/ut_agents/measure.py --viewer-port "$viewer_port" --monitor-port $((port + 1)) --expect "$n" \
  --settle 5 --duration "$seconds" --csv "$work/samples.csv" --feet-csv "$work/samples_feet.csv" --json "$work/result.json" > "$work/measure.log" 2>&1 &
measure=$!
half=$(( (n + 1) / 2 ))
for ((i = 1; i <= n; ++i)); do
  team=UTA unum=$i
  if [[ $layout == split && $i -gt $half ]]; then team=UTB unum=$((i - half)); fi
  agent_port=$port
  if [[ $trace == true ]]; then
    agent_port=$((port + 100 + i))
    python3 bench/ut_agents/proxy.py "$agent_port" "$port" "$work/trace_${team}_$unum.jsonl" &
    pids+=($!)
    # Listening before the agent connects (the proxy takes one connection: poll the socket table, not the port).
    for _ in $(seq 1 40); do ss -ltn "sport = :$agent_port" | grep -q LISTEN && break; sleep 0.25; done
  fi
  (cd "$agent_dir" && exec "$agent" --host=127.0.0.1 --port "$agent_port" --team "$team" --unum "$unum" --type "$type" \
     --paramsfile paramfiles/defaultParams.txt --paramsfile "paramfiles/defaultParams_t$type.txt" \
     > "$work/agent_${team}_$unum.log" 2>&1) &
  pids+=($!)
  sleep 1  # the reference server needs agents one by one; turf does not, but the agents' scripts do it so
done
wait "$measure" || { echo "run_match.sh: measure.py failed:" >&2; cat "$work/measure.log" >&2; exit 1; }
python3 - "$work/result.json" "$label" "$seed" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
rows = r["robots"]
up = sum(x["upright_pct"] for x in rows) / len(rows)
print(f"| {sys.argv[2]} | {sys.argv[3]} | {up:.1f} | {sum(x['falls'] for x in rows)} | "
      f"{min(x['closest'] for x in rows):.2f} | {'yes' if r['ball_moved'] else 'no'} ({r['ball_max_disp']:.2f} m) |")
PY
