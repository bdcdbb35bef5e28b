// Eigen values, arrays and optionals in state snapshots (core/state_io.h). Each Get* fails the reader on a value
// that is not finite: a snapshot never restores a NaN into a state that never holds one.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <cstddef>
#include <optional>

#include "core/state_io.h"

namespace turf {

inline double GetFinite(StateReader& in) {
  const double v = in.Get<double>();
  if (!std::isfinite(v)) in.Fail("value not finite");
  return v;
}

inline void PutVector(const Eigen::Vector3d& v, StateWriter& out) {
  for (int k = 0; k < 3; ++k) out.Put(v[k]);
}

inline Eigen::Vector3d GetVector(StateReader& in) {
  Eigen::Vector3d v;
  for (int k = 0; k < 3; ++k) v[k] = GetFinite(in);
  return v;
}

template <size_t N>
void PutArray(const std::array<double, N>& v, StateWriter& out) {
  for (double x : v) out.Put(x);
}

template <size_t N>
std::array<double, N> GetArray(StateReader& in) {
  std::array<double, N> v{};
  for (double& x : v) x = GetFinite(in);
  return v;
}

// x, y, z, w (Eigen's coefficient order).
inline void PutQuaternion(const Eigen::Quaterniond& q, StateWriter& out) {
  for (int k = 0; k < 4; ++k) out.Put(q.coeffs()[k]);
}

inline Eigen::Quaterniond GetQuaternion(StateReader& in) {
  Eigen::Quaterniond q;
  for (int k = 0; k < 4; ++k) q.coeffs()[k] = GetFinite(in);
  return q;
}

// A presence flag, then the value through `put`.
template <class T, class PutT>
void PutOptional(const std::optional<T>& v, StateWriter& out, PutT put) {
  out.Put(v.has_value());
  if (v) put(*v);
}

// The presence flag, then the value from `get` if present.
template <class T, class GetT>
std::optional<T> GetOptional(StateReader& in, GetT get) {
  if (!in.Bool()) return std::nullopt;
  return get();
}

// A league's robot move (a struct with robot, position, orientation and reset_joints: the 3D leagues' sessions).
template <class Move>
void PutMove(const Move& m, StateWriter& out) {
  out.Str(m.robot);
  PutVector(m.position, out);
  PutQuaternion(m.orientation, out);
  out.Put(m.reset_joints);
}

template <class Move>
Move GetMove(StateReader& in, size_t max_name) {
  Move m;
  m.robot = in.Str(max_name);
  m.position = GetVector(in);
  m.orientation = GetQuaternion(in);
  m.reset_joints = in.Bool();
  return m;
}

}  // namespace turf
