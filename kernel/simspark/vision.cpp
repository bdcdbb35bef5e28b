#include "kernel/simspark/vision.h"

#include <algorithm>
#include <cmath>

namespace turf::simspark {

namespace {

constexpr double kRadToDeg = 180.0 / M_PI;
constexpr double kDegToRad = M_PI / 180.0;

// Degrees into (-180, 180].
double NormalizeDeg(double deg) {
  double r = std::remainder(deg, 360.0);  // [-180, 180]
  if (r <= -180.0) r += 360.0;
  return r;
}

// The perceptor's cone check, done on the exact position (before noise).
bool InCone(const Polar& pol, const VisionParams& params) {
  return pol.distance > params.min_distance && std::abs(pol.horizontal) <= params.half_cone_h_deg &&
         std::abs(pol.vertical) <= params.half_cone_v_deg;
}

void AddNoise(Polar* pol, const VisionParams& params, Rng* rng) {
  if (!params.noise || rng == nullptr) return;
  pol->distance += rng->Normal(0.0, params.sigma_distance_percent) * pol->distance / 100.0;
  pol->horizontal += rng->Normal(0.0, params.sigma_h_deg);
  pol->vertical += rng->Normal(0.0, params.sigma_v_deg);
}

// Clips p(t) = a + t (b - a), t in [0, 1], to the view frustum in head
// coordinates: |x| <= y tan(H), |z| <= y tan(V), y >= near. Returns false if
// nothing remains. The frustum lies inside the cone (|h| <= H, |v| <= V), and a
// point on a side plane has |h| = H exactly.
bool ClipToFrustum(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const VisionParams& params, double* t0,
                   double* t1) {
  const double th = std::tan(params.half_cone_h_deg * kDegToRad);
  const double tv = std::tan(params.half_cone_v_deg * kDegToRad);
  const Eigen::Vector3d d = b - a;
  // Each constraint is f(p) = n . p - c >= 0.
  const struct {
    Eigen::Vector3d n;
    double c;
  } planes[] = {
      {{-1.0, th, 0.0}, 0.0},                  // x <= y tan(H)  (right edge, h = -H)
      {{1.0, th, 0.0}, 0.0},                   // x >= -y tan(H) (left edge, h = +H)
      {{0.0, tv, -1.0}, 0.0},                  // z <= y tan(V)
      {{0.0, tv, 1.0}, 0.0},                   // z >= -y tan(V)
      {{0.0, 1.0, 0.0}, params.min_distance},  // near plane
  };
  *t0 = 0.0;
  *t1 = 1.0;
  for (const auto& plane : planes) {
    const double f0 = plane.n.dot(a) - plane.c;
    const double df = plane.n.dot(d);
    if (df == 0.0) {
      if (f0 < 0.0) return false;
      continue;
    }
    const double t = -f0 / df;
    if (df > 0.0) {
      *t0 = std::max(*t0, t);
    } else {
      *t1 = std::min(*t1, t);
    }
    if (*t0 > *t1) return false;
  }
  return true;
}

}  // namespace

Polar ToPolar(const Eigen::Vector3d& in_head) {
  Polar pol;
  pol.distance = in_head.norm();
  pol.horizontal = NormalizeDeg(std::atan2(in_head.y(), in_head.x()) * kRadToDeg - 90.0);
  pol.vertical = std::atan2(in_head.z(), std::hypot(in_head.x(), in_head.y())) * kRadToDeg;
  return pol;
}

Eigen::Vector3d DrawCalibrationOffset(Rng* rng) {
  Eigen::Vector3d offset;
  for (int i = 0; i < 3; ++i) offset[i] = -0.005 + 0.01 * rng->Uniform();
  return offset;
}

SeeItems ComputeSee(const VisionScene& scene, const Field3dGeometry& field, const VisionParams& params, Rng* rng) {
  const Eigen::Matrix3d head_from_world = scene.head_orientation.normalized().toRotationMatrix().transpose();
  const auto in_head = [&](const Eigen::Vector3d& world) -> Eigen::Vector3d {
    return head_from_world * (world - scene.head_position) + scene.calibration_offset;
  };
  // The polar position of a world point if it is in the cone, noise added.
  const auto see_point = [&](const Eigen::Vector3d& world) -> std::optional<Polar> {
    Polar pol = ToPolar(in_head(world));
    if (!InCone(pol, params)) return std::nullopt;
    AddNoise(&pol, params, rng);
    return pol;
  };

  SeeItems items;
  if (scene.ball) {
    if (auto pol = see_point(*scene.ball)) items.objects.push_back({"B", *pol});
  }
  for (const auto* points : {&field.flags, &field.goal_posts}) {
    for (const FieldPoint& point : *points) {
      if (auto pol = see_point(point.position)) items.objects.push_back({point.label, *pol});
    }
  }

  for (const VisionPlayer& player : scene.players) {
    SeePlayer seen{player.team, player.unum, {}};
    for (const VisionPart& part : player.parts) {
      if (auto pol = see_point(part.position)) seen.parts.push_back({part.name, *pol});
    }
    if (!seen.parts.empty()) items.players.push_back(std::move(seen));
  }

  for (const FieldSegment& line : field.lines) {
    const Eigen::Vector3d a = in_head(line.a);
    const Eigen::Vector3d b = in_head(line.b);
    Polar begin = ToPolar(a);
    Polar end = ToPolar(b);
    const bool see_begin = InCone(begin, params);
    const bool see_end = InCone(end, params);
    if (!(see_begin && see_end)) {
      // As the reference server: a visible end point stays, an invisible one
      // moves to where the segment enters the frustum.
      double t0 = 0.0;
      double t1 = 1.0;
      if (!ClipToFrustum(a, b, params, &t0, &t1)) continue;
      if (!see_begin) begin = ToPolar(a + t0 * (b - a));
      if (!see_end) end = ToPolar(a + t1 * (b - a));
    }
    AddNoise(&begin, params, rng);
    AddNoise(&end, params, rng);
    items.lines.push_back({begin, end});
  }
  return items;
}

}  // namespace turf::simspark
