// The IDL text of turf's DDS types (idl/*.idl, compiled in), as the schema of an MCAP channel: Foxglove and other
// tools decode CDR messages with it (schema encoding "omgidl"). A schema must be self-contained, so IdlSchema puts
// each included file in place of its #include line, once, before the file that uses it, and drops the other
// preprocessor lines (include guards), which IDL readers outside a C preprocessor do not take.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace turf::record {

struct IdlFile {
  const char* name;  // "Clock.idl"
  const char* text;
};

// Every idl/*.idl of this build (generated: idl_texts.cpp).
const std::vector<IdlFile>& IdlFiles();

// The IDL that defines struct `type` ("Clock", in module turf::idl) with everything it includes; empty if no file
// defines it.
std::string IdlSchema(std::string_view type);

}  // namespace turf::record
