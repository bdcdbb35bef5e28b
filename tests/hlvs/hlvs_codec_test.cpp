// The HLVS wire codec: golden bytes of the facts' sample request (57 bytes) and of a SensorMeasurements written by
// hand from the field numbers, the greeting, framing, and every refusal by name.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "codecs/hlvs/wire.h"
#include "codecs/proto/hlvs.pb.h"
#include "tests/hlvs/hlvs_requests.h"
#include "tests/support/text.h"

namespace turf::hlvs {
namespace {

using test::Bytes;

// The facts' sample: motor_positions Neck 1.6, Head 0.8; sensor_time_steps NeckS 8, Camera 16 (57 bytes).
std::string SampleRequest() {
  return Bytes({0x0a, 0x0f, 0x0a, 0x04, 'N', 'e', 'c', 'k', 0x11, 0x9a, 0x99, 0x99, 0x99, 0x99, 0x99, 0xf9, 0x3f,  //
                0x0a, 0x0f, 0x0a, 0x04, 'H', 'e', 'a', 'd', 0x11, 0x9a, 0x99, 0x99, 0x99, 0x99, 0x99, 0xe9, 0x3f,  //
                0x32, 0x09, 0x0a, 0x05, 'N', 'e', 'c', 'k', 'S',  0x10, 0x08,                                      //
                0x32, 0x0a, 0x0a, 0x06, 'C', 'a', 'm', 'e', 'r',  'a',  0x10, 0x10});
}

TEST(HlvsWire, GreetingIsEightBytesWithNul) {
  ASSERT_EQ(kWelcome.size(), 8u);
  ASSERT_EQ(kRefused.size(), 8u);
  EXPECT_EQ(std::string(kWelcome), std::string("Welcome\0", 8));
  EXPECT_EQ(kRefused[7], '\0');
}

TEST(HlvsWire, DecodesTheFactsSampleRequest) {
  const std::string bytes = SampleRequest();
  ASSERT_EQ(bytes.size(), 57u);
  const DecodeResult r = DecodeActuatorRequests(bytes);
  ASSERT_EQ(r.error, Error::kOk) << r.detail;
  ASSERT_EQ(r.requests.positions.size(), 2u);
  EXPECT_EQ(r.requests.positions[0].name, "Neck");
  EXPECT_EQ(r.requests.positions[0].value, 1.6);
  EXPECT_EQ(r.requests.positions[1].name, "Head");
  EXPECT_EQ(r.requests.positions[1].value, 0.8);
  ASSERT_EQ(r.requests.sensor_time_steps.size(), 2u);
  EXPECT_EQ(r.requests.sensor_time_steps[1].name, "Camera");
  EXPECT_EQ(r.requests.sensor_time_steps[1].time_step_ms, 16u);
}

TEST(HlvsWire, OurProtoWritesTheSampleByteForByte) {
  pb::ActuatorRequests r = test::Position("Neck", 1.6);
  r.MergeFrom(test::Position("Head", 0.8));
  r.MergeFrom(test::TimeSteps({{"NeckS", 8}, {"Camera", 16}}));
  EXPECT_EQ(r.SerializeAsString(), SampleRequest());
}

TEST(HlvsWire, EncodesSensorMeasurementsGoldenBytes) {
  SensorMeasurements m;
  m.time_ms = 8;
  m.real_time_ms = 1000;
  m.messages.push_back({MessageType::kWarning, "w"});
  m.gyros.push_back({"Gyro", {1.0, 0, 0}});
  m.position_sensors.push_back({"NeckS", 0.5});
  m.bumpers.push_back({"b", true});
  const std::string expected =
      Bytes({0x08, 0x08,                                                  // time 8
             0x10, 0xe8, 0x07,                                            // real_time 1000
             0x1a, 0x05, 0x08, 0x01, 0x12, 0x01, 'w',                     // messages: WARNING "w"
             0x2a, 0x05, 0x0a, 0x01, 'b',  0x10, 0x01,                    // bumpers: "b" true
             0x52, 0x11, 0x0a, 0x04, 'G',  'y',  'r',  'o',  0x12, 0x09,  // gyros: "Gyro", value {
             0x09, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xf0, 0x3f,        //   X 1.0 }
             0x5a, 0x10, 0x0a, 0x05, 'N',  'e',  'c',  'k',  'S',         // position_sensors "NeckS"
             0x11, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xe0, 0x3f});      //   0.5
  EXPECT_EQ(EncodeSensorMeasurements(m), expected);
  const EncodeResult framed = FrameSensorMeasurements(m);
  ASSERT_EQ(framed.error, Error::kOk);
  EXPECT_EQ(framed.framed, Bytes({0, 0, 0, static_cast<int>(expected.size())}) + expected);
}

TEST(HlvsWire, CameraImageRoundTrips) {
  SensorMeasurements m;
  m.time_ms = 16;
  m.cameras.push_back({"Camera", 2, 1, -1, "BGRBGR"});
  pb::SensorMeasurements back;
  ASSERT_TRUE(back.ParseFromString(EncodeSensorMeasurements(m)));
  ASSERT_EQ(back.cameras_size(), 1);
  EXPECT_EQ(back.cameras(0).width(), 2u);
  EXPECT_EQ(back.cameras(0).quality(), -1);
  EXPECT_EQ(back.cameras(0).image(), "BGRBGR");
}

TEST(HlvsWire, NeverFramesAnEmptyOrOversizedMessage) {
  EXPECT_EQ(FrameSensorMeasurements({}).error, Error::kEmpty);
  SensorMeasurements big;
  big.time_ms = 8;
  big.cameras.push_back({"Camera", 1920, 1081, -1, std::string(1920 * 1081 * 3, 'x')});
  const EncodeResult r = FrameSensorMeasurements(big);
  EXPECT_EQ(r.error, Error::kTooLarge);
  EXPECT_TRUE(r.framed.empty());
}

std::string RequestWith(double position, const std::string& name = "Neck") {
  return test::Position(name, position).SerializeAsString();
}

TEST(HlvsWire, RefusesByName) {
  EXPECT_EQ(DecodeActuatorRequests(std::string(kMaxRequestBytes + 1, '\0')).error, Error::kTooLarge);
  EXPECT_EQ(DecodeActuatorRequests("\xff\xff\xff").error, Error::kMalformed);
  EXPECT_EQ(DecodeActuatorRequests(SampleRequest().substr(0, 20)).error, Error::kMalformed);  // truncated
  EXPECT_EQ(DecodeActuatorRequests(RequestWith(std::nan(""))).error, Error::kNotFinite);
  EXPECT_EQ(DecodeActuatorRequests(RequestWith(5e3)).error, Error::kOutOfRange);
  EXPECT_EQ(DecodeActuatorRequests(RequestWith(0, std::string(kMaxNameBytes + 1, 'a'))).error, Error::kTooLarge);
  pb::ActuatorRequests many;
  for (size_t i = 0; i <= kMaxRequestEntries; ++i) many.add_motor_positions()->set_name("Neck");
  EXPECT_EQ(DecodeActuatorRequests(many.SerializeAsString()).error, Error::kTooMany);
  pb::ActuatorRequests torque;
  auto* t = torque.add_motor_torques();
  t->set_name("Neck");
  t->set_torque(std::numeric_limits<double>::infinity());
  EXPECT_EQ(DecodeActuatorRequests(torque.SerializeAsString()).error, Error::kNotFinite);
  pb::ActuatorRequests pid;
  auto* g = pid.add_motor_pids();
  g->set_name("Neck");
  g->mutable_pid()->set_x(-1);
  EXPECT_EQ(DecodeActuatorRequests(pid.SerializeAsString()).error, Error::kOutOfRange);
}

TEST(HlvsWire, InfinitePositionIsVelocityControl) {
  const DecodeResult r = DecodeActuatorRequests(RequestWith(std::numeric_limits<double>::infinity()));
  ASSERT_EQ(r.error, Error::kOk);
  EXPECT_TRUE(std::isinf(r.requests.positions.at(0).value));
}

TEST(HlvsWire, EmptyRequestIsValid) {
  const DecodeResult r = DecodeActuatorRequests("");
  EXPECT_EQ(r.error, Error::kOk);
  EXPECT_TRUE(r.requests.positions.empty());
}

}  // namespace
}  // namespace turf::hlvs
