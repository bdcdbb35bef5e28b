// A kernel's stream statistics (kernel/stream_report.h) on the stats topic
// and in the status log.
#pragma once

#include <turf/idl/SensorStats.h>

#include "kernel/stream_report.h"

namespace turf {

idl::SensorStats StatsToIdl(const StreamReport& report);
// One info line with every stream that carried samples in the window.
void ReportStreams(const StreamReport& report);

}  // namespace turf
