// Runs a launch plan's processes and keeps them running.
//
// - Each process starts with its argv and environment, in its own process
//   group (a terminal's Ctrl-C reaches only `turf`, which then stops the
//   children once, cleanly) and with SIGTERM as its parent-death signal (if
//   `turf` itself is killed, the children stop too).
// - Every line a process prints (stdout and stderr) is printed prefixed with
//   its name: "vision   | ...".
// - A process that exits with status 2 refused its configuration (every turf
//   participant's exit code for bad flags or files): it is not restarted, the
//   others are stopped and `turf` exits 2 at once (its message is in its output).
// - A process that crashes (killed by a signal, or another non-zero exit) is
//   restarted after a backoff that doubles with each quick crash (one within
//   `stable_after` of its start) up to `backoff_max`. After `max_restarts`
//   quick crashes in a row `turf` gives up on it: a bridge or the viewer is left
//   stopped and the match goes on (SIGUSR1 to `turf` tries every such process
//   again); turf-sim or the discovery server ends the launch with exit status 1.
// - A process that exits with status 0 ends the launch: the others are stopped
//   and `turf` exits 0 (e.g. turf-sim --duration).
// - SIGINT/SIGTERM/SIGHUP stop every process with SIGTERM (a stop_last one,
//   the discovery server, once the others are gone), then SIGKILL after the
//   grace period; a second signal a second or more later sends SIGKILL at once
//   (one sooner is the same stop, as for the participants). Exit status 0 when all
//   stopped within the grace period, 1 otherwise.
#pragma once

#include <chrono>
#include <cstdio>
#include <vector>

#include "participants/launcher/launch_plan.h"
#include "participants/launcher/launch_profile.h"

namespace turf::launch {

struct SupervisorOptions {
  RestartPolicy restart;
  std::chrono::milliseconds grace{5000};
};

// Runs until stopped; returns the exit status for `turf`. Installs its own
// handling of SIGINT, SIGTERM and SIGCHLD for the duration.
int Supervise(const std::vector<ProcessCommand>& commands, const SupervisorOptions& options);

}  // namespace turf::launch
