#!/usr/bin/env bash
# Runs turf's benchmarks and prints tables.
#   bench/run.sh [sim seconds]           all of them
#   bench/run.sh ssl [sim seconds]       turf-sim alone, SSL scenes
#   bench/run.sh simspark [sim seconds]  SimSpark agents through turf-simspark-bridge
#   bench/run.sh rcssservermj [sim seconds]  RCSSServerMJ agents (T1) served by turf-sim --rcssservermj
#   bench/run.sh rcssservermj-nn --client-dir DIR
#                                        RCSSServerMJ's example T1 walking policy (example/nn_client, kept outside
#                                        turf) on turf: distance walked, falls (issue 14's acceptance run)
#   bench/run.sh engine [--reference-mujoco DIR --reference-robot DIR]
#                                        the physics engine alone with 1, 2, 11 and 22 T1 holding a standing pose:
#                                        turf's legged kernel, and the reference's engine (MuJoCo 3 from npm with
#                                        RCSSServerMJ's robot file, both kept outside turf) in the same run if given
#   bench/run.sh snapshot                kernel snapshots: size, Save and Restore next to a step
#   bench/run.sh codecs                  the agent protocols' text: an RCSSServerMJ action message parsed, a
#                                        perception formatted, per message
#   bench/run.sh sync [requests]         SSL sync port round trip: separate bridge over DDS vs in turf-sim's process,
#                                        on all cores, then all on one core
#   bench/run.sh python [sim seconds]    `import turf`: env-steps/s of Sim, the Gymnasium-shaped envs and VectorSim
#                                        against the SSL sync port, in one run (bench/python_bench.py)
#   bench/run.sh security [sim seconds]  what DDS Security costs: the SSL bench and the DDS hop latency, off and on
#   bench/run.sh render [sim seconds]    camera rendering (issue 16): frames/s for 1, 4, 10 cameras at 320x240 and
#                                        640x480 (turf-bench-render), and turf-sim's speed alone and next to a
#                                        turf-render drawing 4 cameras
#   bench/run.sh record [sim seconds]    recording cost (SSL 2x11 and 22 Naos): turf-sim free-running alone and with turf-record on its
#                                        domain; the recorder's CPU, peak memory and MB per simulated minute
#   bench/run.sh ut-agents --ut-agent PATH --agent-dir DIR
#                                        real 3D-league agents (UT Austin Villa's base agent, built outside turf)
#                                        play on turf: upright share, falls, approach to the ball (issue 12)
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${TURF_BUILD_DIR:-build}
WHAT=all
if [[ "${1:-}" =~ ^(ssl|simspark|rcssservermj|rcssservermj-nn|engine|snapshot|sync|python|security|render|record|ut-agents)$ ]]; then
  WHAT=$1
  shift
fi
SECONDS_SIM=${1:-20}
if [[ "$WHAT" == record ]]; then  # needs only turf-sim and turf-record
  [ -x "$BUILD_DIR/participants/recorder/turf-record" ] || bash scripts/build.sh
else
  [ -x "$BUILD_DIR/bench/turf-bench-simspark" ] || bash scripts/build.sh
fi

ssl() {
  local bin="$BUILD_DIR/bench/turf-bench-sim"
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
}

# One run: turf-sim (simspark_match scene) and turf-simspark-bridge as their
# own processes on a private DDS domain and ports, then the scripted agents.
# where=in-process: turf-sim serves the agents itself (--simspark), no bridge process.
simspark_run() {
  local agents=$1 mode=$2 motion=$3 header=${4:-} where=${5:-bridge}
  local domain=$((90 + RANDOM % 9)) port=$((23100 + RANDOM % 500))
  local prefix="bench$$" scene=${TURF_BENCH_SIMSPARK_SCENE:-configs/scenes/simspark_match.yaml}
  local sync_flag="" label="$agents agents, $mode, $motion"
  if [[ "$where" == in-process ]]; then
    [[ "$mode" == sync ]] && sync_flag="--simspark-sync"
    "$BUILD_DIR/participants/sim/turf-sim" --scene "$scene" -d "$domain" -p "$prefix" \
      --lockstep --simspark --simspark-agent-port "$port" --simspark-monitor-port $((port + 1)) $sync_flag \
      --log-level warn &
    local sim=$!
    "$BUILD_DIR/bench/turf-bench-simspark" --port "$port" --agents "$agents" --seconds "$SECONDS_SIM" \
      --motion "$motion" --label "$label, in turf-sim" --server-pid "$sim" $header || true
    kill -INT "$sim" 2>/dev/null || true
    wait "$sim" 2>/dev/null || true
    return
  fi
  "$BUILD_DIR/participants/sim/turf-sim" --scene "$scene" -d "$domain" -p "$prefix" \
    --lockstep --log-level warn &
  local sim=$!
  [[ "$mode" == sync ]] && sync_flag="--sync"
  "$BUILD_DIR/participants/simspark_bridge/turf-simspark-bridge" -d "$domain" -p "$prefix" --listen 127.0.0.1 \
    --agent-port "$port" --monitor-port $((port + 1)) $sync_flag --log-level warn &
  local bridge=$!
  # The agents connect as soon as the bridge listens and wait for turf-sim to be ready (no fixed sleep).
  "$BUILD_DIR/bench/turf-bench-simspark" --port "$port" --agents "$agents" --seconds "$SECONDS_SIM" \
    --motion "$motion" --label "$label" $header || true
  kill -INT "$bridge" "$sim" 2>/dev/null || true
  wait "$bridge" "$sim" 2>/dev/null || true
}

simspark() {
  echo "SimSpark agents -> turf-simspark-bridge -> turf-sim (22 Naos, one 20 ms step per cycle, as the reference);"
  echo "each agent answers every perception with 22 hinge velocities and (syn): 'all' sways every joint (the"
  echo "robots fall and lie, many contacts), 'upper' only head and arms (they stand); $(nproc) cores"
  simspark_run 22 sync all --header
  simspark_run 22 sync upper
  simspark_run 11 sync all
  simspark_run 22 real-time all
  simspark_run 22 sync all "" in-process
  simspark_run 22 sync upper "" in-process
  echo "RTF: simulated seconds per wall second over the measured stretch (sync: as fast as the agents"
  echo "answer). Reference rcssserver3d 0.7.3 on this machine: 0.72x with 22 agents, 1.9x with 11."
}

# One run: turf-sim serving RCSSServerMJ agents (rcssservermj_fifa scene, 22 T1, or the one named) on a private domain
# and port, then the scripted agents.
rcssservermj_run() {
  local agents=$1 mode=$2 motion=$3 header=${4:-} scene=${5:-rcssservermj_fifa} label="$1 agents, $2, $3"
  [[ "$scene" == rcssservermj_fifa ]] || label="$label, 1v1 scene"
  local domain=$((90 + RANDOM % 9)) port=$((24100 + RANDOM % 500))
  local flags=(--rcssservermj-no-realtime)
  [[ "$mode" == sync ]] || flags=(--rcssservermj-realtime)
  local log
  log=$(mktemp)
  "$BUILD_DIR/participants/sim/turf-sim" --scene "configs/scenes/$scene.yaml" -d "$domain" -p "bench$$" \
    --lockstep --rcssservermj --rcssservermj-agent-port "$port" --rcssservermj-monitor-port $((port + 1)) \
    "${flags[@]}" --log-level info >"$log" 2>&1 &
  local sim=$!
  "$BUILD_DIR/bench/turf-bench-rcssservermj" --port "$port" --agents "$agents" --seconds "$SECONDS_SIM" \
    --motion "$motion" --label "$label" --server-pid "$sim" $header || true
  kill -INT "$sim" 2>/dev/null || true
  wait "$sim" 2>/dev/null || true
  # turf-sim's own account of the run's cycles (its status line's split, printed as it stops).
  SPLITS+=("$label: $(grep -o 'per cycle: .*' "$log" | tail -1)")
  grep -E '\[(error|critical)\]' "$log" >&2 || true
  rm -f "$log"
}

rcssservermj() {
  SPLITS=()
  echo "RCSSServerMJ agents -> turf-sim --rcssservermj (22 T1 in the scene, 4 steps of 5 ms per 20 ms cycle); each"
  echo "agent answers every perception with PD commands for its 23 joints: 'upper' sways head, arms and waist with"
  echo "the legs held, 'all' sways every joint; $(nproc) cores"
  rcssservermj_run 22 sync upper --header
  rcssservermj_run 2 sync upper
  rcssservermj_run 2 sync upper "" rcssservermj_fifa_1v1
  rcssservermj_run 22 sync all
  rcssservermj_run 22 real-time upper
  printf '%s\n' "${SPLITS[@]}"
  echo "RTF: simulated seconds per wall second over the measured stretch (sync: as fast as the agents answer)."
  echo "per cycle: turf-sim's split of the run's cycles (its last 10 s of wall time at most): world = its 4 physics"
  echo "steps with the perceptions sent meanwhile, front-end = the session's work after them, waiting = for the agents."
  echo "server / agents ms/cyc: CPU time (user + system) per 20 ms cycle of turf-sim (all its threads) and of the"
  echo "agents' process, over the same stretch: steadier than RTF on a loaded machine."
  echo "The parked robots of the scene are simulated too (22 T1; the 1v1 scene, rcssservermj_fifa_1v1.yaml, has 2, as"
  echo "RCSSServerMJ's world holds one robot per connected agent). Target (issue 14): >= 5x with 22 agents."
}

# DDS Security off, on without encryption (authentication and access control), on with encryption: the SSL bench
# with a driving client, then the DDS hop latency, each variant in this one run.
security() {
  local dir
  dir=$(mktemp -d)
  "$BUILD_DIR/participants/launcher/turf" security init "$dir/no-encryption" --prefix '*' --no-encryption >/dev/null
  "$BUILD_DIR/participants/launcher/turf" security init "$dir/encrypted" --prefix '*' >/dev/null
  local scene=configs/scenes/ssl_div_a.yaml
  echo "turf-sim free-running with a driving client, DDS Security off / on without encryption / on; $(nproc) cores"
  "$BUILD_DIR/bench/turf-bench-sim" --header --seconds "$SECONDS_SIM" --scene "$scene" --drive
  for variant in no-encryption encrypted; do
    "$BUILD_DIR/bench/turf-bench-sim" --seconds "$SECONDS_SIM" --scene "$scene" --drive --security "$dir/$variant"
  done
  echo
  "$BUILD_DIR/bench/turf-bench-latency"
  for variant in no-encryption encrypted; do
    echo
    "$BUILD_DIR/bench/turf-bench-latency" --security "$dir/$variant"
  done
  rm -rf "$dir"
}

# turf-sim's speed (free-running, simspark_3d.yaml: 2 Naos with 2 cameras each) alone, then with turf-render drawing
# all 4 cameras at 30 Hz of sim time: turf-sim never waits for the renderer, but on 2 cores they share the CPU.
render_sim_speed() {
  local domain=$((150 + RANDOM % 50)) prefix="bench_render_$$" scene=configs/scenes/simspark_3d.yaml
  local sim=("$BUILD_DIR/participants/sim/turf-sim" --scene "$scene" --speed max --duration "$SECONDS_SIM"
             --domain "$domain" --prefix "$prefix")
  # Wall seconds of a whole turf-sim run (including its 1.5 s discovery wait at start-up).
  run_sim() {
    local start end
    start=$(date +%s.%N)
    "${sim[@]}" >/dev/null 2>&1
    end=$(date +%s.%N)
    awk -v a="$start" -v b="$end" 'BEGIN { printf "%.2f", b - a }'
  }
  echo "| turf-sim, $SECONDS_SIM s of sim time, free-running (simspark_3d.yaml) | wall s, start-up included |"
  echo "| --- | --- |"
  echo "| no renderer | $(run_sim) |"
  "$BUILD_DIR/participants/render/turf-render" --scene "$scene" --domain "$domain" --prefix "$prefix" --cameras off \
    --status-every 3600 >/dev/null 2>&1 &
  local off=$!
  sleep 3  # the renderer's start-up, as below
  echo "| turf-render --cameras off on the domain | $(run_sim) |"
  kill -TERM "$off"
  wait "$off" || true
  "$BUILD_DIR/participants/render/turf-render" --scene "$scene" --domain "$domain" --prefix "$prefix" \
    --status-every 3600 >/tmp/turf_bench_render_$$.log 2>&1 &
  local render=$!
  sleep 3  # the renderer's start-up (EGL, model, DDS discovery), so it renders from turf-sim's first state
  echo "| turf-render drawing its 4 cameras at 30 Hz of sim time | $(run_sim) |"
  kill -TERM "$render"
  wait "$render" || true
  grep "status:" /tmp/turf_bench_render_$$.log | tail -1
  rm -f /tmp/turf_bench_render_$$.log
}

render() {
  echo "offscreen camera rendering, $(nproc) cores, load average $(cut -d' ' -f1 /proc/loadavg) at the start"
  "$BUILD_DIR/bench/turf-bench-render"
  echo
  render_sim_speed
}

# One turf-sim run of SCENE (realistic sensors) at --speed max on a private domain; prints its wall seconds without
# the 1.5 s discovery window it waits at start.
record_sim() {
  local domain=$1 prefix=$2 scene=$3 t0 t1
  t0=$(date +%s.%N)
  "$BUILD_DIR/participants/sim/turf-sim" --scene "$scene" --realism realistic -d "$domain" \
    -p "$prefix" --speed max --duration "$SECONDS_SIM" --log-level warn
  t1=$(date +%s.%N)
  awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.2f", b - a - 1.5 }'
}

# turf-viewer --recording FILE: its peak resident MiB after the page's requests for 100 slider times across the
# recording (the chunk cache bounds it, participants/viewer/recording.h).
viewer_peak() {
  local file=$1 port=$((20000 + RANDOM % 20000)) viewer info start end i
  "$BUILD_DIR/participants/viewer/turf-viewer" --recording "$file" --port "$port" --log-level warn &
  viewer=$!
  for i in $(seq 1 300); do  # up to 60 s to read the file and listen
    info=$(curl -sf "http://127.0.0.1:$port/recording/info") && break
    sleep 0.2
  done
  start=$(printf '%s' "$info" | /usr/bin/python3 -c 'import json,sys; print(json.load(sys.stdin).get("start", 0))')
  end=$(printf '%s' "$info" | /usr/bin/python3 -c 'import json,sys; print(json.load(sys.stdin).get("end", 0))')
  for i in $(seq 0 99); do
    curl -sf -o /dev/null "http://127.0.0.1:$port/recording/state?t=$(awk -v a="$start" -v b="$end" -v i="$i" \
      'BEGIN { printf "%.3f", a + (b - a) * i / 99 }')" || true
  done
  awk '/VmHWM/ { printf "%.0f", $2 / 1024 }' "/proc/$viewer/status"
  kill -INT "$viewer"
  wait "$viewer" || true
}

# One row: turf-sim free-running on SCENE alone, then with turf-record on its domain (zstd, the default).
record_row() {
  local label=$1 scene=$2 domain=$((100 + RANDOM % 50)) prefix="bench$$" dir alone with rec tck stat cpu hwm bytes
  dir=$(mktemp -d)
  tck=$(getconf CLK_TCK)
  alone=$(record_sim "$domain" "$prefix" "$scene")
  "$BUILD_DIR/participants/recorder/turf-record" "$dir/match.mcap" -d "$domain" -p "$prefix" --log-level warn &
  rec=$!
  with=$(record_sim "$domain" "$prefix" "$scene")
  # The recorder's CPU (user + system) and peak resident memory so far, then Ctrl-C closes its file.
  stat=$(cut -d' ' -f14,15 "/proc/$rec/stat")
  cpu=$(awk -v s="$stat" -v t="$tck" 'BEGIN { split(s, f, " "); printf "%.2f", (f[1] + f[2]) / t }')
  hwm=$(awk '/VmHWM/ { printf "%.0f", $2 / 1024 }' "/proc/$rec/status")
  kill -INT "$rec"
  wait "$rec" || true
  bytes=$(stat -c %s "$dir/match.mcap")
  view=$(viewer_peak "$dir/match.mcap")
  awk -v l="$label" -v a="$alone" -v w="$with" -v c="$cpu" -v m="$hwm" -v b="$bytes" -v s="$SECONDS_SIM" -v v="$view" \
    'BEGIN { printf "| %s | %.2f | %.2f | %.1f | %.1f | %s | %s | %.2f | %s |\n", l, a, w, s / a, s / w, c, m,
             b / 1e6 / s * 60, v }'
  rm -rf "$dir"
}

# Recording cost (issue 17): the SSL 2x11 match and a 22-robot legged match, each alone and recorded.
record() {
  echo "Recording cost: realistic sensors, ${SECONDS_SIM} s of sim time at --speed max; $(nproc) cores"
  echo "| match | turf-sim alone s | turf-sim with recorder s | RTF alone | RTF recorded | recorder CPU s | recorder MiB (peak) | MB per sim minute | turf-viewer --recording MiB (peak) |"
  echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- |"
  record_row "SSL division A 2x11" configs/scenes/ssl_div_a.yaml
  record_row "SimSpark 22 Naos (legged)" configs/scenes/simspark_match.yaml
  echo "turf-sim's wall time without its 1.5 s discovery window; RTF: simulated s per wall s. One run each; the file"
  echo "is zstd-compressed (the recorder's default)."
}

# Optional: only with the agent's binary and source directory (bench/ut_agents/run_match.sh --help).
ut_agents() {
  echo "UT Austin Villa base agents on turf (turf launch simspark), 60 s of sim time from the kick-off"
  echo "| match | seed | mean upright % | falls | best approach m | ball moved |"
  echo "| --- | --- | --- | --- | --- | --- |"
  bench/ut_agents/run_match.sh "$@" --agents 4 --label "4 agents (2 v 2), type 0, sync mode"
  bench/ut_agents/run_match.sh "$@" --agents 4 --realtime --label "4 agents (2 v 2), type 0, real time"
  for type in 1 2 3 4; do
    bench/ut_agents/run_match.sh "$@" --agents 4 --type "$type" --label "4 agents (2 v 2), type $type, sync mode"
  done
  echo "Reference (issue 12, rcssserver3d 0.7.3 built from source, the same agent, sync, 60 s, 2026-11-26/27): type 0"
  echo "91.9-100 % upright (mean 96.6 over ten runs, 4.0 falls a run), types 1-4 77.1-99.3 %; the ball moved in 18 of 19 runs."
}

# turf's engine with N T1 robots standing, then (if given) the reference's engine with the same world: the physics
# alone, no agents and no protocol, the ceiling of the RCSSServerMJ bench's RTF.
engine() {
  local mujoco="" robot=""
  while [[ $# -gt 0 ]]; do
    case "$1" in
      --reference-mujoco) mujoco=$2; shift 2 ;;
      --reference-robot) robot=$2; shift 2 ;;
      *) echo "bench/run.sh engine: unknown argument $1" >&2; exit 2 ;;
    esac
  done
  echo "N Booster T1 in a row 2 m apart, each holding configs/scenes/t1_stand.yaml's pose with its PD gains, in"
  echo "RCSSServerMJ's air; 5 ms steps after 200 of settling; $(nproc) cores, one thread each"
  "$BUILD_DIR/bench/turf-bench-engine" --header --island-threads 1,2
  if [[ -n "$mujoco" ]]; then
    [[ -n "$robot" ]] || { echo "bench/run.sh engine: --reference-mujoco needs --reference-robot" >&2; exit 2; }
    node bench/rcssservermj_nn/reference_speed.mjs "$mujoco" "$robot" configs/scenes/t1_stand.yaml
  fi
  echo "us/step: wall time of one physics step (turf: its legged kernel's every stage); RTF: 5 ms over it, the"
  echo "ceiling of bench/run.sh rcssservermj's RTF for as many robots. solver its: the constraint solver's mean"
  echo "iterations (per island where islands are on); rows: constraint rows. Islands: MuJoCo >= 3.3.6 (RCSSServerMJ's"
  echo "3.4.0) solves each group of touching bodies on its own; Debian's 2.2.2 solves the world at once. 'two"
  echo "kernels of N/2 on two threads': the ceiling of stepping the robots as two worlds on the 2 cores (joined every"
  echo "step; no contact between the halves, so not a turf mode)."
}

# The sync port twice: where the scheduler puts each thread, then everything on one core (a lockstep loop never
# runs the client and turf-sim at once; across cores each request pays two cross-core wake-ups).
sync_bench() {
  "$BUILD_DIR/bench/turf-bench-sync" --requests "${1:-1000}"
  echo
  "$BUILD_DIR/bench/turf-bench-sync" --requests "${1:-1000}" --cpu 0
}

case "$WHAT" in
  ssl) ssl ;;
  simspark) simspark ;;
  rcssservermj) rcssservermj ;;
  rcssservermj-nn) bench/rcssservermj_nn/run.sh "$@" ;;
  engine) engine "$@" ;;
  snapshot) "$BUILD_DIR/bench/turf-bench-snapshot" ;;
  codecs) "$BUILD_DIR/bench/turf-bench-codecs" ;;
  sync) sync_bench "$@" ;;
  python) PYTHONPATH="$BUILD_DIR/python" TURF_BUILD_DIR="$BUILD_DIR" /usr/bin/python3 bench/python_bench.py \
            --seconds "$SECONDS_SIM" ;;
  security) security ;;
  render) render ;;
  record) record ;;
  ut-agents) ut_agents "$@" ;;
  all)
    ssl
    echo
    simspark
    echo
    "$BUILD_DIR/bench/turf-bench-snapshot"
    echo
    sync_bench
    echo
    PYTHONPATH="$BUILD_DIR/python" TURF_BUILD_DIR="$BUILD_DIR" /usr/bin/python3 bench/python_bench.py
    ;;
esac
