#include "tests/support/team_packets.h"

#include <cstdint>

#include "codecs/proto/grsim.pb.h"

namespace turf::test {

std::string GrsimMove(bool yellow, int id, double forward, double left, double angular, double kick) {
  wire::grsim::grSim_Packet p;
  auto* c = p.mutable_commands();
  c->set_timestamp(0);
  c->set_isteamyellow(yellow);
  auto* r = c->add_robot_commands();
  r->set_id(static_cast<uint32_t>(id));
  r->set_kickspeedx(static_cast<float>(kick));
  r->set_kickspeedz(0);
  r->set_veltangent(static_cast<float>(forward));
  r->set_velnormal(static_cast<float>(left));
  r->set_velangular(static_cast<float>(angular));
  r->set_spinner(false);
  r->set_wheelsspeed(false);
  return p.SerializeAsString();
}

std::string GrsimPlace(bool yellow, int id, double x, double y, double dir_deg, std::optional<double> ball_x,
                       double ball_y) {
  wire::grsim::grSim_Packet p;
  auto* rep = p.mutable_replacement();
  auto* r = rep->add_robots();
  r->set_x(x);
  r->set_y(y);
  r->set_dir(dir_deg);
  r->set_id(static_cast<uint32_t>(id));
  r->set_yellowteam(yellow);
  r->set_turnon(true);
  if (ball_x) {
    rep->mutable_ball()->set_x(*ball_x);
    rep->mutable_ball()->set_y(ball_y);
    rep->mutable_ball()->set_vx(0);
    rep->mutable_ball()->set_vy(0);
  }
  return p.SerializeAsString();
}

}  // namespace turf::test
