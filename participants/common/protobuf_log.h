// libprotobuf's own log lines (for instance "String field 'google.protobuf.Any.type_url' contains invalid UTF-8
// data when parsing a protocol buffer", one per bad datagram) go through turf's logger, counted and rate-limited
// per source line of libprotobuf (RejectLog), instead of one unthrottled ERROR line per datagram on stderr.
// Every participant that parses protobuf calls RouteProtobufLogs() once at start-up.
#pragma once

#include <cstdint>

namespace turf {

void RouteProtobufLogs();
// libprotobuf log lines seen since RouteProtobufLogs() (printed or not).
uint64_t ProtobufLogLines();

}  // namespace turf
