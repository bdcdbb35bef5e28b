// The Nao's restricted vision perceptor (`See`): what a camera at the head
// centre reports about the ball, flags, goal posts, players' parts and field
// lines (shared/protocols/simspark.md, "See"). Pure: the caller passes the
// world as a VisionScene and a generator for the dynamic noise; the cadence
// (every third perceptor cycle) and the wire format are elsewhere.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <vector>

#include "core/rng.h"
#include "kernel/simspark/field3d.h"
#include "kernel/simspark/types.h"

namespace turf::simspark {

struct VisionParams {
  double half_cone_h_deg = 60.0;           // |h| <= this
  double half_cone_v_deg = 60.0;           // |v| <= this
  double min_distance = 0.1;               // m; objects at or closer are not listed; lines clipped this far in front
  double sigma_distance_percent = 0.0965;  // d += N(0, sigma) * d / 100
  double sigma_h_deg = 0.1480;
  double sigma_v_deg = 0.1225;
  bool noise = true;  // dynamic noise; the calibration offset is the scene's
};

struct VisionPart {
  std::string name;          // head, rlowerarm, llowerarm, rfoot, lfoot
  Eigen::Vector3d position;  // world frame, body centre
};

struct VisionPlayer {
  std::string team;  // team name as reported
  int unum = 0;
  std::vector<VisionPart> parts;
};

struct VisionScene {
  Eigen::Vector3d head_position = Eigen::Vector3d::Zero();
  // world <- head frame; head frame: x right, y forward, z up.
  Eigen::Quaterniond head_orientation = Eigen::Quaterniond::Identity();
  // Added to every head-frame position; drawn once per agent (DrawCalibrationOffset) or zero for ideal vision.
  Eigen::Vector3d calibration_offset = Eigen::Vector3d::Zero();
  std::optional<Eigen::Vector3d> ball;  // centre, world frame
  std::vector<VisionPlayer> players;    // including the viewer itself
};

// Head-frame position -> (d, h, v): d = |p|; h = atan2(y, x) - 90 normalised to
// (-180, 180], positive to the left; v = atan2(z, |p.xy|), positive up. Degrees.
Polar ToPolar(const Eigen::Vector3d& in_head);

// Constant per-agent calibration error: each axis U(-0.005, 0.005) m.
Eigen::Vector3d DrawCalibrationOffset(Rng* rng);

// One See. Objects are listed in the order ball, flags, goal posts; players in
// scene order with their visible parts only (omitted when none); lines in field
// order, clipped to the view cone. Noise (when params.noise and rng) is drawn in
// that same order, d then h then v per point, so equal seeds give equal results.
SeeItems ComputeSee(const VisionScene& scene, const Field3dGeometry& field, const VisionParams& params, Rng* rng);

}  // namespace turf::simspark
