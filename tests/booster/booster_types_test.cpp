// The Booster SDK's low-level types as turf generates them from idl/booster/BoosterLowLevel.idl: the names they
// register on the wire, and their CDR bytes against the layouts of shared/protocols/booster-sdk-dds.md, written out
// by hand here, so that a wrong member order, type or padding shows up without the vendor's library.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "tests/support/cdr.h"
#include "turf/idl/BoosterLowLevel.h"
#include "turf/idl/BoosterLowLevelPubSubTypes.h"

namespace bi = booster_interface::msg::dds_;

namespace {

// Little-endian CDR, written field by field as the facts' tables give them.
struct Cdr {
  std::vector<uint8_t> bytes{0x00, 0x01, 0x00, 0x00};  // encapsulation: plain CDR, little endian
  void U8(uint8_t v) { bytes.push_back(v); }
  void Pad(size_t n) { bytes.insert(bytes.end(), n, 0); }
  void U32(uint32_t v) {
    for (int i = 0; i < 4; ++i) bytes.push_back(static_cast<uint8_t>(v >> (8 * i)));
  }
  void F32(float v) {
    uint32_t u;
    std::memcpy(&u, &v, 4);
    U32(u);
  }
};

template <class PubSub, class Sample>
std::vector<uint8_t> Serialise(const Sample& sample) {
  const std::string cdr = turf::test::Cdr<PubSub>(sample);
  return {cdr.begin(), cdr.end()};
}

TEST(BoosterTypes, RegisterTheSdksRos2StyleNames) {
  EXPECT_STREQ(bi::LowCmd_PubSubType().getName(), "booster_interface::msg::dds_::LowCmd_");
  EXPECT_STREQ(bi::LowState_PubSubType().getName(), "booster_interface::msg::dds_::LowState_");
  EXPECT_STREQ(bi::Odometer_PubSubType().getName(), "booster_interface::msg::dds_::Odometer_");
  EXPECT_STREQ(bi::FallDownState_PubSubType().getName(), "booster_interface::msg::dds_::FallDownState_");
}

// The SDK's low_level_publisher: head pitch (index 1) to 0.785 rad with kp 4, kd 1, weight 1; here with 2 joints.
TEST(BoosterTypes, LowCmdBytesFollowTheFactsLayout) {
  bi::LowCmd_ cmd;
  cmd.cmd_type(bi::SERIAL);
  cmd.motor_cmd().resize(2);
  bi::MotorCmd_& head = cmd.motor_cmd()[1];
  head.mode(0x0A);
  head.q(0.785f);
  head.dq(0.5f);
  head.tau(-1.25f);
  head.kp(4.0f);
  head.kd(1.0f);
  head.weight(1.0f);
  Cdr want;
  want.U32(1);  // cmd_type SERIAL
  want.U32(2);  // motor_cmd length
  for (int i = 0; i < 2; ++i) {
    const bool h = i == 1;
    want.U8(h ? 0x0A : 0);  // mode, then 3 bytes of padding: 28 bytes per MotorCmd
    want.Pad(3);
    for (float v : {h ? 0.785f : 0.f, h ? 0.5f : 0.f, h ? -1.25f : 0.f, h ? 4.f : 0.f, h ? 1.f : 0.f, h ? 1.f : 0.f})
      want.F32(v);  // q, dq, tau, kp, kd, weight
  }
  EXPECT_EQ(Serialise<bi::LowCmd_PubSubType>(cmd), want.bytes);
  EXPECT_EQ(want.bytes.size(), 4u + 4 + 4 + 2 * 28);
}

TEST(BoosterTypes, LowStateBytesFollowTheFactsLayout) {
  bi::LowState_ state;
  state.imu_state().rpy({0.1f, -0.2f, 0.3f});
  state.imu_state().gyro({1.f, 2.f, 3.f});
  state.imu_state().acc({0.f, 0.f, 9.81f});
  bi::MotorState_ m;
  m.mode(1);
  m.q(0.25f);
  m.dq(-0.5f);
  m.ddq(2.f);
  m.tau_est(3.5f);
  m.temperature(40);
  m.lost(7);
  m.reserve({8, 9});
  state.motor_state_parallel({m});
  state.motor_state_serial({m, m});
  Cdr want;
  for (float v : {0.1f, -0.2f, 0.3f, 1.f, 2.f, 3.f, 0.f, 0.f, 9.81f}) want.F32(v);  // ImuState: 36 bytes
  auto motor = [&want] {                                                            // MotorState: 36 bytes
    want.U8(1);
    want.Pad(3);
    for (float v : {0.25f, -0.5f, 2.f, 3.5f}) want.F32(v);  // q, dq, ddq, tau_est
    want.U8(40);                                            // temperature, then 3 bytes of padding
    want.Pad(3);
    want.U32(7);  // lost
    want.U32(8);  // reserve
    want.U32(9);
  };
  want.U32(1);  // motor_state_parallel
  motor();
  want.U32(2);  // motor_state_serial
  motor();
  motor();
  EXPECT_EQ(Serialise<bi::LowState_PubSubType>(state), want.bytes);
  EXPECT_EQ(want.bytes.size(), 4u + 36 + 4 + 36 + 4 + 2 * 36);
}

TEST(BoosterTypes, OdometerAndFallDownBytes) {
  bi::Odometer_ odo;
  odo.x(1.5f);
  odo.y(-2.f);
  odo.theta(0.5f);
  Cdr o;
  for (float v : {1.5f, -2.f, 0.5f}) o.F32(v);
  EXPECT_EQ(Serialise<bi::Odometer_PubSubType>(odo), o.bytes);
  bi::FallDownState_ fall;
  fall.fall_down_state(bi::HAS_FALLEN);
  fall.is_recovery_available(true);
  Cdr f;
  f.U32(2);
  f.U8(1);
  std::vector<uint8_t> got = Serialise<bi::FallDownState_PubSubType>(fall);
  ASSERT_GE(got.size(), f.bytes.size());
  EXPECT_EQ(std::vector<uint8_t>(got.begin(), got.begin() + f.bytes.size()), f.bytes);  // then alignment padding
}

}  // namespace
