// Random numbers for sensor and link models, reproducible everywhere: the
// generator (xoshiro256**) and the distributions are written out here, because
// std:: distributions differ between standard libraries. One generator per
// stream, seeded from the scene seed and the stream's name, so a stream's draws
// never depend on another stream or on timing.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <utility>
#include <vector>

#include "core/state_io.h"

namespace turf {

// Seed of the stream `name` under the scene seed (FNV-1a of the name, mixed).
uint64_t StreamSeed(uint64_t scene_seed, std::string_view name);

class Rng {
 public:
  explicit Rng(uint64_t seed = 0);
  uint64_t Next();
  // Uniform in [0, 1).
  double Uniform() { return static_cast<double>(Next() >> 11) * 0x1.0p-53; }
  bool Bernoulli(double p) { return Uniform() < p; }
  // Standard normal (Box-Muller; the second value of a pair is kept).
  double Normal();
  double Normal(double mean, double stddev) { return mean + stddev * Normal(); }
  // Exponential with the given mean.
  double Exponential(double mean) { return -mean * std::log1p(-Uniform()); }

  // The stream's position, for snapshots.
  void Save(StateWriter& out) const;
  void Restore(StateReader& in);

 private:
  uint64_t s_[4];
  bool has_spare_ = false;
  double spare_ = 0.0;
};

// Fisher-Yates from the back: element i - 1 swaps with one drawn as Next() % i (the same order everywhere).
template <class T>
void Shuffle(std::vector<T>* v, Rng& rng) {
  for (std::size_t i = v->size(); i > 1; --i) std::swap((*v)[i - 1], (*v)[rng.Next() % i]);
}

}  // namespace turf
