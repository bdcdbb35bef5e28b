#include "participants/common/protobuf_log.h"

#include <fmt/format.h>
#include <google/protobuf/stubs/logging.h>
#include <spdlog/spdlog.h>

#include <string>

#include "participants/common/process.h"

namespace turf {

namespace {

RejectLog& Log() {
  static RejectLog log("datagram (libprotobuf)");
  return log;
}

void Handle(google::protobuf::LogLevel level, const char* filename, int line, const std::string& message) {
  const std::string file = filename != nullptr ? filename : "?";
  const std::string kind = fmt::format("protobuf.{}:{}", file.substr(file.find_last_of('/') + 1), line);
  if (level >= google::protobuf::LOGLEVEL_FATAL) spdlog::critical("libprotobuf: {}", message);
  Log().Reject(kind, message);
}

}  // namespace

void RouteProtobufLogs() { google::protobuf::SetLogHandler(&Handle); }

uint64_t ProtobufLogLines() { return Log().Total(); }

}  // namespace turf
