// turf-replay: a recording's outputs back onto a DDS domain; see replay.h.
#include <spdlog/spdlog.h>
#include <unistd.h>
#include <CLI/CLI.hpp>

#include <atomic>
#include <csignal>
#include <string>

#include "participants/common/participant_main.h"
#include "participants/common/process.h"
#include "participants/replay/replay.h"
#include "participants/replay/replay_command.h"
#include "participants/replay/resimulate.h"

namespace {

// SIGUSR1 toggles pause (`kill -USR1 <pid>`); a lock-free atomic is safe to use in a signal handler.
std::atomic<bool> g_paused{false};
static_assert(std::atomic<bool>::is_always_lock_free);
extern "C" void TogglePause(int /*signal*/) { g_paused.store(!g_paused.load()); }

}  // namespace

int main(int argc, char** argv) {
  turf::ParticipantMain participant(
      "turf-replay: plays the outputs of a turf-record MCAP file (world state, clock, cameras, ...) back onto a DDS "
      "domain, for the viewer and team software; or, with --resimulate, re-runs the match from its recorded inputs "
      "in this process and checks that every recorded output is reproduced byte for byte");
  turf::ReplayOptions options;
  std::string speed = "1";
  CLI::App& app = participant.app();
  app.add_option("file", options.file, "the MCAP file (turf-record's)")->required()->check(CLI::ExistingFile);
  app.add_option("--speed", speed, "a multiple of the recorded pace (e.g. 1, 4, 0.5), or max")
      ->check([](const std::string& s) -> std::string {
        if (s == "max") return "";
        try {
          const std::string problem = turf::ReplaySpeedProblem(std::stod(s));
          return problem.empty() ? "" : "--speed: " + problem + ", or max";
        } catch (...) {
          return "--speed: a number or max";
        }
      })
      ->capture_default_str();
  app.add_option("--start", options.start_s,
                 "begin this many seconds (of recorded time) after the first message; latched topics (the field) "
                 "are still published first")
      ->check(CLI::Range(0.0, 1e9))
      ->capture_default_str();
  app.add_option("--end", options.end_s,
                 "stop this many seconds (of recorded time) after the first message (0: at the end of the file)")
      ->check(CLI::Range(0.0, 1e9))
      ->capture_default_str();
  bool no_stdin = false;
  app.add_flag("--no-stdin", no_stdin,
               "ignore the standard input (by default it takes commands, one per line: pause, resume, seek SECONDS of "
               "simulation time, speed X or speed max)");
  app.add_flag("--wait-for-reader", options.wait_for_reader,
               "before the first message, wait (up to 30 s) until a reader of a replayed topic is matched");
  bool resimulate = false;
  turf::ResimulateOptions resim;
  app.add_flag("--resimulate", resimulate,
               "play nothing: re-simulate the recorded match (its scene, seed and the inputs turf-sim applied, step by "
               "step) in this process and compare every recorded output byte for byte; exit 0 if identical, 1 with "
               "the first difference if not");
  app.add_option("--skip", resim.skip, "with --resimulate: topics (without prefix) not compared")
      ->capture_default_str();
  participant.AddCommonFlags(options, {"DDS domain id to replay onto", "topic name prefix to replay under"});
  return participant.Run(argc, argv, [&] {
    if (resimulate) {
      resim.file = options.file;
      const turf::ResimulateResult r = turf::Resimulate(resim, turf::StopRequested);
      if (turf::StopRequested() && !r.identical) {  // cut short: what was not reached is no difference
        spdlog::info("stopped at sim time {:.3f} s, before the comparison was complete: no verdict",
                     static_cast<double>(r.sim_time_ns) * 1e-9);
        return turf::kExitClean;
      }
      spdlog::info("{}", r.verdict);
      return r.identical ? turf::kExitClean : turf::kExitFailure;
    }
    options.speed = speed == "max" ? 0.0 : std::stod(speed);
    options.stdin_commands = !no_stdin;
    std::signal(SIGUSR1, TogglePause);
    options.paused = [] { return g_paused.load(); };
    spdlog::info("pause and resume: kill -USR1 {} (or the control topic: pause, resume, speed, seek)", ::getpid());
    turf::Replay(options, turf::StopRequested);
    return turf::kExitClean;
  });
}
