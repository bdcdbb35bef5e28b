// Values of turf's common IDL types (Common.idl: Vec2, Vec3, Quat) from plain
// numbers: the one place codecs, participants and tests build them.
#pragma once

#include <turf/idl/Common.h>

#include <array>

namespace turf::idl {

inline Vec2 V2(double x, double y) {
  Vec2 v;
  v.x(x);
  v.y(y);
  return v;
}

inline Vec3 V3(double x, double y, double z) {
  Vec3 v;
  v.x(x);
  v.y(y);
  v.z(z);
  return v;
}

inline Vec3 V3(const std::array<double, 3>& a) { return V3(a[0], a[1], a[2]); }

// w, x, y, z
inline Quat Q4(const std::array<double, 4>& a) {
  Quat q;
  q.w(a[0]);
  q.x(a[1]);
  q.y(a[2]);
  q.z(a[3]);
  return q;
}

inline std::array<double, 3> A3(const Vec3& v) { return {v.x(), v.y(), v.z()}; }

}  // namespace turf::idl
