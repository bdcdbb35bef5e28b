// The datagrams an SSL team's software sends (built with turf's protos,
// codecs/proto), for the end-to-end, multi-host, fault and launch tests.
#pragma once

#include <optional>
#include <string>

namespace turf::test {

// grSim: a local-velocity command for one robot (with a flat kick, m/s).
std::string GrsimMove(bool yellow, int id, double forward, double left, double angular, double kick = 0);

// grSim: a replacement of one robot (dir in degrees), and of the ball (at rest)
// when `ball_x` is given.
std::string GrsimPlace(bool yellow, int id, double x, double y, double dir_deg, std::optional<double> ball_x = {},
                       double ball_y = 0);

}  // namespace turf::test
