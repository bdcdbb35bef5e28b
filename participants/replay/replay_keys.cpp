#include "participants/replay/replay_keys.h"

#include <fmt/format.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

namespace turf {
namespace {

std::vector<std::string_view> Words(std::string_view line) {
  std::vector<std::string_view> words;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    size_t j = i;
    while (j < line.size() && line[j] != ' ' && line[j] != '\t' && line[j] != '\r') ++j;
    if (j > i) words.push_back(line.substr(i, j - i));
    i = j;
  }
  return words;
}

// A finite number that is the whole word, or nothing.
bool Number(std::string_view word, double* value) {
  const std::string text(word);
  char* end = nullptr;
  errno = 0;
  *value = std::strtod(text.c_str(), &end);
  return errno == 0 && end == text.c_str() + text.size() && !text.empty() && std::isfinite(*value);
}

ReplayRefusal Refuse(idl::ControlError code, std::string reason) {
  return {code, std::move(reason) + " (commands: " + kReplayKeysHelp + ")"};
}

std::variant<ReplayCommand, ReplayRefusal> Op(ReplayCommand::Kind kind, double speed, int64_t seek_ns) {
  ReplayCommand command{kind, speed, seek_ns, {}};
  command.request.op(kind == ReplayCommand::Kind::kPause    ? idl::OP_PAUSE
                     : kind == ReplayCommand::Kind::kResume ? idl::OP_RESUME
                     : kind == ReplayCommand::Kind::kSpeed  ? idl::OP_SET_TIME_MODE
                                                            : idl::OP_SEEK);
  command.request.seek_time_ns(seek_ns);
  return command;
}

std::variant<ReplayCommand, ReplayRefusal> WithNumber(std::string_view verb, std::string_view arg) {
  double value = 0;
  if (verb == "speed" && arg == "max") return Op(ReplayCommand::Kind::kSpeed, 0, 0);
  if (!Number(arg, &value)) return Refuse(idl::CONTROL_BAD_ARGUMENTS, fmt::format("'{}' is no finite number", arg));
  if (verb == "speed") {
    if (std::string problem = ReplaySpeedProblem(value); !problem.empty())
      return Refuse(idl::CONTROL_OUT_OF_RANGE, std::move(problem));
    return Op(ReplayCommand::Kind::kSpeed, value, 0);
  }
  if (value < 0 || value > kMaxSeekSeconds)
    return Refuse(idl::CONTROL_OUT_OF_RANGE, fmt::format("seek {} s is outside [0, {}]", value, kMaxSeekSeconds));
  return Op(ReplayCommand::Kind::kSeek, 1, std::llround(value * 1e9));
}

}  // namespace

std::variant<ReplayCommand, ReplayRefusal> ParseReplayLine(std::string_view line) {
  if (line.size() > kMaxReplayLine)
    return Refuse(idl::CONTROL_TOO_LARGE, fmt::format("a line of {} bytes (at most {})", line.size(), kMaxReplayLine));
  const std::vector<std::string_view> words = Words(line);
  if (words.empty()) return Refuse(idl::CONTROL_EMPTY, "an empty line");
  const std::string_view verb = words[0];
  if (words.size() == 1 && (verb == "pause" || verb == "p")) return Op(ReplayCommand::Kind::kPause, 1, 0);
  if (words.size() == 1 && (verb == "resume" || verb == "play" || verb == "r"))
    return Op(ReplayCommand::Kind::kResume, 1, 0);
  if (words.size() == 2 && (verb == "seek" || verb == "s")) return WithNumber("seek", words[1]);
  if (words.size() == 2 && verb == "speed") return WithNumber("speed", words[1]);
  return Refuse(idl::CONTROL_PARSE, fmt::format("unknown command '{}'", line.substr(0, 64)));
}

}  // namespace turf
