// Snapshot tests of a 3D league's session (SimSpark, RCSSServerMJ: SaveLeague / RestoreLeague), shared by both
// leagues' tests and fuzz targets: a scripted match run cycle by cycle, the damaged-snapshot check, and the fuzz
// targets' spliced restore. Header-only and gtest-free (the fuzz targets build without it).
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <initializer_list>
#include <string>
#include <string_view>
#include <utility>

#include "core/state_io.h"

namespace turf::test {

// A scripted match: `Match` derives from LeagueScript<Match> and has Inputs(i) (cycle i's inputs, the same on every
// run), Cycle() (runs a cycle, returns what it produced as text), session() (the league's session) and world() (the
// fake world it steps, copyable: the kernel's snapshot in a real run). The checks return "" or what went wrong.
template <class Match>
class LeagueScript {
 public:
  std::string Step(int i) {
    self().Inputs(i);
    return self().Cycle();
  }
  // Cycles [from, to), their outputs concatenated.
  std::string Run(int from, int to) {
    std::string log;
    for (int i = from; i < to; ++i) log += Step(i);
    return log;
  }
  // The league saved after cycles [0, cycles).
  std::string SaveAfter(int cycles) {
    Run(0, cycles);
    return self().session().SaveLeague();
  }

  // Saved after `at` cycles and restored (with the world as it was), the match sends cycles [at, to) again byte for
  // byte; without the league's state it does not. The script must exercise every one of `parts`.
  std::string RestoredMatchSendsTheSameBytes(int at, int to, std::initializer_list<const char*> parts) {
    const std::string snapshot = SaveAfter(at);
    const auto world = self().world();
    const std::string first = Run(at, to);
    for (const char* part : parts)
      if (first.find(part) == std::string::npos) return std::string("the script does not exercise ") + part;
    self().world() = world;
    if (Run(at, to) == first) return "the match went on the same without the league's state";
    self().world() = world;
    if (std::string why = self().session().RestoreLeague(snapshot); !why.empty()) return "refused: " + why;
    if (self().session().cycle() != static_cast<uint64_t>(at))
      return "restored at cycle " + std::to_string(self().session().cycle());
    return Run(at, to) == first ? "" : "the restored match sent other bytes";
  }

  // Saved between cycle `at`'s inputs (and `pending()`'s) and its step: the match goes on to `to` the same.
  template <class Pending>
  std::string SavedWithInputsPendingGoesOnTheSame(int at, int to, const Pending& pending) {
    Run(0, at);
    self().Inputs(at);
    pending();
    const std::string snapshot = self().session().SaveLeague();
    const auto world = self().world();
    const std::string first = self().Cycle() + Run(at + 1, to);
    self().world() = world;
    if (std::string why = self().session().RestoreLeague(snapshot); !why.empty()) return "refused: " + why;
    return self().Cycle() + Run(at + 1, to) == first ? "" : "the restored match sent other bytes";
  }

  // A snapshot restored over the state it was saved from saves as the same bytes.
  std::string SnapshotOfTheSameStateIsTheSameBytes(int at) {
    const std::string snapshot = SaveAfter(at);
    if (std::string why = self().session().RestoreLeague(snapshot); !why.empty()) return "refused: " + why;
    return self().session().SaveLeague() == snapshot ? "" : "saved as other bytes";
  }

 private:
  Match& self() { return static_cast<Match&>(*this); }
};

// The name given to agent `id` in `names`, else its number: outputs compare by player, not by connection.
inline std::string NameOf(int id, std::initializer_list<std::pair<int, const char*>> names) {
  for (const auto& [agent, name] : names)
    if (agent == id) return name;
  return std::to_string(id);
}

// Every `stride`-th truncation of `snapshot` and every byte of it flipped with `mask`. Returns "" if each was
// refused with the league's state left at `now` (restore(bytes) -> why, save() -> bytes), or, for a flip only,
// taken (a double's bits) and then `now` restored; else what went wrong.
template <class Save, class Restore>
std::string DamagedSnapshotsChangeNothing(const std::string& snapshot, const std::string& now, const Save& save,
                                          const Restore& restore, size_t stride = 1, char mask = '\xA5') {
  for (size_t cut = 0; cut < snapshot.size(); cut += stride) {
    if (restore(snapshot.substr(0, cut)).empty()) return "taken when cut at " + std::to_string(cut);
    if (save() != now) return "changed when cut at " + std::to_string(cut);
  }
  for (size_t at = 0; at < snapshot.size(); ++at) {
    std::string flipped = snapshot;
    flipped[at] = static_cast<char>(flipped[at] ^ mask);
    if (!restore(flipped).empty()) {
      if (save() != now) return "changed when flipped at " + std::to_string(at);
    } else if (!restore(now).empty()) {
      return "cannot go back after a flip at " + std::to_string(at);
    }
  }
  return "";
}

// One 20 ms cycle of a fuzz target's league session over the world `world(t)` builds for the cycle's end time.
template <class Session, class World>
void FuzzCycle(Session& session, const World& world) {
  session.TakeRequests();
  session.Advance(world(0.02 * static_cast<double>(session.cycle() + 1)));
  session.TakeOutputs();
}

// A libFuzzer step: `match.start` (the session's own snapshot) with the input's tail spliced in at the position
// its first two bytes choose, so deep sections get exercised too. A refused restore must change nothing; an
// accepted one must leave a session that runs a cycle (FuzzCycle over `world`) and takes `match.start` back.
// Aborts otherwise.
template <class Match, class World>
void FuzzSplicedRestore(Match& match, const World& world, const uint8_t* data, size_t size) {
  const auto require = [](bool ok) {
    if (!ok) std::abort();
  };
  if (size < 3) return;
  const std::string& start = match.start;
  const size_t cut = (static_cast<size_t>(data[0]) << 8 | data[1]) % (start.size() + 1);
  const std::string spliced = start.substr(0, cut) + std::string(reinterpret_cast<const char*>(data) + 2, size - 2);
  const std::string before = match.session.SaveLeague();
  if (match.session.RestoreLeague(spliced).empty()) {
    FuzzCycle(match.session, world);
    require(match.session.RestoreLeague(match.start).empty());
  } else {
    require(match.session.SaveLeague() == before);
  }
}

// A league fuzzer's entry: the input restored into the league's rules alone (`rules(in)`: a game or a referee,
// updated once if it took the bytes), then spliced into `Match`'s whole league snapshot (FuzzSplicedRestore).
// Match: a session and its snapshot `start`, set up once.
template <class Match, class World, class Rules>
int FuzzLeague(const uint8_t* data, size_t size, const World& world, Rules rules) {
  static Match match;
  StateReader in(std::string_view(reinterpret_cast<const char*>(data), size));
  rules(in);
  FuzzSplicedRestore(match, world, data, size);
  return 0;
}

}  // namespace turf::test
