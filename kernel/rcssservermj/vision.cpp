#include "kernel/rcssservermj/vision.h"

#include <algorithm>
#include <cmath>

namespace turf::rcssservermj {

namespace {

constexpr double kDeg = 180.0 / M_PI;

double Truncate2(double v) { return std::trunc(v * 100.0) / 100.0; }

}  // namespace

Polar ToPolar(const Eigen::Vector3d& world, const Eigen::Vector3d& camera, const Eigen::Quaterniond& orientation) {
  const Eigen::Vector3d p = orientation.conjugate() * (world - camera);
  Polar out;
  out.distance = p.norm();
  if (out.distance <= 0) return out;
  out.azimuth = std::atan2(p.y(), p.x()) * kDeg;
  out.elevation = std::asin(std::clamp(p.z() / out.distance, -1.0, 1.0)) * kDeg;
  return out;
}

bool InView(const Polar& p) {
  return p.distance > 0 && std::abs(Truncate2(p.azimuth)) <= kViewLimitDeg &&
         std::abs(Truncate2(p.elevation)) <= kViewLimitDeg;
}

SeeItems ComputeSee(const VisionInput& in) {
  SeeItems see;
  auto look = [&](const std::string& name, const Eigen::Vector3d& at, std::vector<SeenMarker>* out) {
    const Polar p = ToPolar(at, in.camera, in.orientation);
    if (InView(p)) out->push_back({name, p});
  };
  if (in.markers != nullptr)
    for (const FieldMarker& m : *in.markers) look(m.name, m.position, &see.markers);
  look("B", in.ball, &see.markers);
  if (in.players == nullptr) return see;
  for (const VisiblePlayer& player : *in.players) {
    SeenPlayer seen{player.team, player.number, {}};
    for (const FieldMarker& part : player.parts) look(part.name, part.position, &seen.parts);
    if (!seen.parts.empty()) see.players.push_back(std::move(seen));
  }
  return see;
}

}  // namespace turf::rcssservermj
