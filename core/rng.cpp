#include "core/rng.h"

#include <algorithm>
#include <iterator>

namespace turf {

namespace {

uint64_t SplitMix64(uint64_t* state) {
  uint64_t z = (*state += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

uint64_t Rotl(uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }

}  // namespace

uint64_t StreamSeed(uint64_t scene_seed, std::string_view name) {
  uint64_t h = 0xcbf29ce484222325ULL;
  for (char c : name) {
    h ^= static_cast<unsigned char>(c);
    h *= 0x100000001b3ULL;
  }
  uint64_t state = scene_seed ^ h;
  return SplitMix64(&state);
}

Rng::Rng(uint64_t seed) {
  uint64_t state = seed;
  for (uint64_t& s : s_) s = SplitMix64(&state);
}

uint64_t Rng::Next() {
  const uint64_t result = Rotl(s_[1] * 5, 7) * 9;
  const uint64_t t = s_[1] << 17;
  s_[2] ^= s_[0];
  s_[3] ^= s_[1];
  s_[1] ^= s_[2];
  s_[0] ^= s_[3];
  s_[2] ^= t;
  s_[3] = Rotl(s_[3], 45);
  return result;
}

double Rng::Normal() {
  if (has_spare_) {
    has_spare_ = false;
    return spare_;
  }
  double u1 = Uniform();
  while (u1 <= 0.0) u1 = Uniform();
  const double u2 = Uniform();
  const double r = std::sqrt(-2.0 * std::log(u1));
  spare_ = r * std::sin(2.0 * M_PI * u2);
  has_spare_ = true;
  return r * std::cos(2.0 * M_PI * u2);
}

void Rng::Save(StateWriter& out) const {
  for (uint64_t word : s_) out.Put(word);
  out.Put(has_spare_);
  out.Put(spare_);
}

void Rng::Restore(StateReader& in) {
  uint64_t s[4];
  for (uint64_t& word : s) word = in.Get<uint64_t>();
  // An all-zero xoshiro state (never reached from a seed) gives zeros forever, and Normal() would wait for a
  // non-zero draw forever: a snapshot (untrusted bytes) with one fails.
  if ((s[0] | s[1] | s[2] | s[3]) == 0) in.Fail("random generator state all zero");
  const bool has_spare = in.Bool();
  const double spare = in.Get<double>();
  if (!in.ok()) return;
  std::copy(std::begin(s), std::end(s), std::begin(s_));
  has_spare_ = has_spare;
  spare_ = spare;
}

}  // namespace turf
