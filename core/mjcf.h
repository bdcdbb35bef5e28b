// Scene -> MJCF. The MuJoCo model of every scene variant is generated here from
// the typed scene; nothing is hand-kept per variant.
#pragma once

#include <string>

#include "core/scene.h"

namespace turf {

// Names of the generated bodies, so the world can find them again.
inline constexpr const char* kBallBody = "ball";
inline constexpr const char* kFloorGeom = "floor";
inline constexpr double kGravity = 9.81;
std::string RobotBodyName(Team team, int id);

// MuJoCo's `solref` damping ratio that keeps `restitution` of the normal speed
// in a bounce (a damped spring: e = exp(-zeta pi / sqrt(1 - zeta^2))).
double DampingRatioForRestitution(double restitution);

// A ball contact as MuJoCo's solref (timeconst, dampratio): a damped spring that keeps `restitution` of the normal
// speed, over several physics steps of `step` s.
struct BallSpring {
  double timeconst;
  double dampratio;
};
BallSpring BallContactSpring(double restitution, double step);

// Where a robot that is off the field waits: outside the walls, apart from
// every other parked robot, so it touches nothing.
Pose2 ParkingPose(const Scene& scene, Team team, int id);

std::string BuildMjcf(const Scene& scene);

}  // namespace turf
