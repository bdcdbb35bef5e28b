// RCSSServerMJ's ideal vision (shared/protocols/rcssservermj.md, "See"): each
// point in polar coordinates of the camera-site frame (x forward, y left, z
// up), kept when |azimuth| and |elevation| are at most 60 deg after truncation
// to 2 decimals. No noise, no occlusion, no minimum distance.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "kernel/rcssservermj/field.h"

namespace turf::rcssservermj {

struct Polar {
  double distance = 0;   // m
  double azimuth = 0;    // deg, positive = left
  double elevation = 0;  // deg, positive = up
};

struct SeenMarker {
  std::string name;  // B, l_luf, ... or a robot part (head, lfoot, rfoot)
  Polar pol;
};

struct SeenPlayer {
  std::string team;
  int number = 0;
  std::vector<SeenMarker> parts;
};

struct SeeItems {
  std::vector<SeenMarker> markers;  // world markers and the ball, in this order
  std::vector<SeenPlayer> players;
};

inline constexpr double kViewLimitDeg = 60.0;

// The point `world` seen from a camera at `camera` (world <- camera rotation).
Polar ToPolar(const Eigen::Vector3d& world, const Eigen::Vector3d& camera, const Eigen::Quaterniond& orientation);
// Within the ±60° cut (after truncation to 2 decimals), and not at the camera itself.
bool InView(const Polar& p);

struct VisiblePlayer {
  std::string team;
  int number = 0;
  std::vector<FieldMarker> parts;  // head, lfoot, rfoot in world coordinates
};

struct VisionInput {
  Eigen::Vector3d camera = Eigen::Vector3d::Zero();
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  // world <- camera site
  Eigen::Vector3d ball = Eigen::Vector3d::Zero();
  const std::vector<FieldMarker>* markers = nullptr;
  const std::vector<VisiblePlayer>* players = nullptr;  // the agent itself included
};

// World markers (the field's order), then the ball `B`, then every player with
// at least one part in view.
SeeItems ComputeSee(const VisionInput& in);

}  // namespace turf::rcssservermj
