// A sample's simulation time as turf-record writes it into each MCAP message's publish_time: sim_time_ns, or a
// camera frame's capture_time_ns; 0 for types without one. turf replay --resimulate matches samples by it.
#pragma once

#include <cstdint>
#include <type_traits>
#include <utility>

namespace turf::record {

template <class T, class = void>
struct HasSimTime : std::false_type {};
template <class T>
struct HasSimTime<T, std::void_t<decltype(std::declval<const T&>().sim_time_ns())>> : std::true_type {};
template <class T, class = void>
struct HasCaptureTime : std::false_type {};
template <class T>
struct HasCaptureTime<T, std::void_t<decltype(std::declval<const T&>().capture_time_ns())>> : std::true_type {};

template <class T>
uint64_t SimTimeOf(const T& sample) {
  int64_t t = 0;
  if constexpr (HasSimTime<T>::value) {
    t = sample.sim_time_ns();
  } else if constexpr (HasCaptureTime<T>::value) {
    t = sample.capture_time_ns();
  }
  return t > 0 ? static_cast<uint64_t>(t) : 0;
}

}  // namespace turf::record
