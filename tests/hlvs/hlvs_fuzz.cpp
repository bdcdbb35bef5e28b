// libFuzzer: any bytes as an ActuatorRequests frame stream (framing, decoding, the session) and back out as a
// SensorMeasurements. Must never crash, leak or hit undefined behaviour.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "codecs/hlvs/session.h"
#include "codecs/hlvs/wire.h"
#include "codecs/simspark/framing.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace turf::hlvs;
  turf::simspark::FrameDecoder frames(kMaxRequestBytes);
  frames.Feed(reinterpret_cast<const char*>(data), size);
  SessionOptions options;
  options.robot = "k1";
  options.model = FindModel("K1");
  Session session(options);
  RobotReading reading;
  reading.position.assign(options.model->motors.size(), 0.1);
  reading.touch.resize(options.model->touch.size());
  uint32_t now = 8;
  DecodeActuatorRequests(std::string_view(reinterpret_cast<const char*>(data), size));
  while (auto payload = frames.Next()) {
    const DecodeResult r = DecodeActuatorRequests(*payload);
    if (r.error == turf::Error::kOk) session.Apply(r.requests, now);
    FrameSensorMeasurements(session.Measure(reading, now, 1));
    session.Commands(reading);
    now += kBasicStepMs;
  }
  return 0;
}
