// libFuzzer: rt/joint_ctrl as it arrives from any DDS participant. Bytes are deserialized as a LowCmd_ (plain CDR,
// as Fast DDS hands them to the generated type) and decoded for both robots: never a crash, and a message either
// refused with a reason or decoded into one finite PD command per joint of the robot.
#include <fastcdr/Cdr.h>
#include <fastcdr/FastBuffer.h>
#include <fastcdr/exceptions/Exception.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "codecs/booster/low_cmd.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::vector<char> bytes(data, data + size);
  eprosima::fastcdr::FastBuffer buffer(bytes.data(), bytes.size());
  eprosima::fastcdr::Cdr cdr(buffer, eprosima::fastcdr::Cdr::DEFAULT_ENDIAN, eprosima::fastcdr::Cdr::DDS_CDR);
  booster_interface::msg::dds_::LowCmd_ cmd;
  try {
    cdr.read_encapsulation();
    cmd.deserialize(cdr);
  } catch (const eprosima::fastcdr::exception::Exception&) {
    return 0;  // not a LowCmd_: Fast DDS drops it before any decoder
  }
  for (const turf::booster::BoosterModel model : {turf::booster::BoosterModel::kT1, turf::booster::BoosterModel::kK1}) {
    const turf::booster::LowCmdDecode d = turf::booster::DecodeLowCmd(cmd, model);
    if (d.error != turf::Error::kOk) {
      if (d.detail.empty() || !d.commands.empty()) std::abort();
      continue;
    }
    if (d.commands.size() != turf::booster::SdkJoints(model).size()) std::abort();
    for (const turf::JointCommand& c : d.commands) {
      for (const double v : {c.value, c.dq, c.tau, c.kp, c.kd})
        if (!std::isfinite(v)) std::abort();
    }
  }
  return 0;
}
