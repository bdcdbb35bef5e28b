// A modelled link: what happens to a sample between its source and the
// network, in simulation time. Fixed latency plus jitter, and loss that is
// either independent (Bernoulli) or bursty (a Gilbert-Elliott chain). A link
// keeps order: a sample never arrives before the one sent before it.
#pragma once

#include <cstdint>
#include <optional>

#include "core/rng.h"

namespace turf {

enum class JitterKind : uint8_t { kGaussian, kUniform, kExponential, kCount };

// Two-state loss: in "good" samples are lost with loss_good, in "bad" with
// loss_bad; after each sample the state flips with the given probabilities.
// Mean burst (bad-state) length is 1 / p_bad_to_good samples.
struct GilbertElliott {
  bool enabled = false;
  double p_good_to_bad = 0.0;
  double p_bad_to_good = 1.0;
  double loss_good = 0.0;
  double loss_bad = 1.0;
};

struct LinkParams {
  double latency = 0.0;  // s, fixed part of the delay
  double jitter = 0.0;   // s: stddev (Gaussian), half width (uniform), mean (exponential)
  JitterKind jitter_kind = JitterKind::kGaussian;
  double loss = 0.0;  // independent loss probability (when burst loss is off)
  GilbertElliott burst;
};

// Why link parameters are unusable; empty when they are fine.
const char* CheckLinkParams(const LinkParams& params);

template <class Io>
void Fields(Io& io, IoRef<Io, LinkParams> p) {
  io(p.latency, p.jitter, InRange(p.jitter_kind, JitterKind::kCount), p.loss, p.burst.enabled, p.burst.p_good_to_bad,
     p.burst.p_bad_to_good, p.burst.loss_good, p.burst.loss_bad);
  io.Check(CheckLinkParams(p)[0] == '\0', "invalid link parameters");
}

struct LinkCounters {
  uint64_t sent = 0;
  uint64_t lost = 0;
};

class Link {
 public:
  Link(const LinkParams& params, uint64_t seed);
  // Changes the model; the random stream and the order guarantee go on.
  void SetParams(const LinkParams& params) { params_ = params; }
  const LinkParams& params() const { return params_; }
  // The fate of a sample sent at `send_ns`: nullopt if lost, else its arrival.
  std::optional<int64_t> Transmit(int64_t send_ns);
  // An acknowledged sample (a robot radio's kick request): while lost it is
  // sent again every `retry_ns`, at most `max_tries` times in all; each try is
  // a sample of the link. nullopt only if every try was lost.
  std::optional<int64_t> TransmitAcknowledged(int64_t send_ns, int64_t retry_ns, int max_tries);
  const LinkCounters& counters() const { return counters_; }
  // Restarts the stream from `seed` (a world reset).
  void Reset(uint64_t seed);
  // Parameters, random stream, burst state and order guarantee, for snapshots.
  void Save(StateWriter& out) const { Fields(out, *this); }
  void Restore(StateReader& in) { Fields(in, *this); }

 private:
  template <class Io, class Self>
  static void Fields(Io& io, Self& self) {
    io(self.params_, self.rng_, self.bad_, self.last_arrival_ns_, self.counters_.sent, self.counters_.lost);
  }
  bool Lost();
  double Delay();

  LinkParams params_;
  Rng rng_;
  bool bad_ = false;
  int64_t last_arrival_ns_ = INT64_MIN;
  LinkCounters counters_;
};

}  // namespace turf
