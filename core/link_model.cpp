#include "core/link_model.h"

#include <algorithm>
#include <cmath>

namespace turf {

const char* CheckLinkParams(const LinkParams& p) {
  auto finite_nonneg = [](double v) { return std::isfinite(v) && v >= 0.0; };
  auto probability = [](double v) { return std::isfinite(v) && v >= 0.0 && v <= 1.0; };
  if (!finite_nonneg(p.latency) || p.latency > 10.0) return "latency must be in [0, 10] s";
  if (!finite_nonneg(p.jitter) || p.jitter > 10.0) return "jitter must be in [0, 10] s";
  if (!probability(p.loss)) return "loss must be a probability";
  const GilbertElliott& b = p.burst;
  if (!probability(b.p_good_to_bad) || !probability(b.p_bad_to_good) || !probability(b.loss_good) ||
      !probability(b.loss_bad))
    return "burst loss parameters must be probabilities";
  if (b.enabled && b.p_bad_to_good <= 0.0) return "burst.p_bad_to_good must be > 0 (bursts must end)";
  return "";
}

Link::Link(const LinkParams& params, uint64_t seed) : params_(params), rng_(seed) {}

void Link::Reset(uint64_t seed) {
  rng_ = Rng(seed);
  bad_ = false;
  last_arrival_ns_ = INT64_MIN;
  counters_ = {};
}

bool Link::Lost() {
  const GilbertElliott& b = params_.burst;
  if (!b.enabled) return params_.loss > 0.0 && rng_.Bernoulli(params_.loss);
  const bool lost = rng_.Bernoulli(bad_ ? b.loss_bad : b.loss_good);
  bad_ = bad_ ? !rng_.Bernoulli(b.p_bad_to_good) : rng_.Bernoulli(b.p_good_to_bad);
  return lost;
}

double Link::Delay() {
  double jitter = 0.0;
  if (params_.jitter > 0.0) {
    switch (params_.jitter_kind) {
      case JitterKind::kGaussian:
        jitter = rng_.Normal(0.0, params_.jitter);
        break;
      case JitterKind::kUniform:
        jitter = (2.0 * rng_.Uniform() - 1.0) * params_.jitter;
        break;
      case JitterKind::kExponential:
        jitter = rng_.Exponential(params_.jitter);
        break;
      case JitterKind::kCount:
        break;
    }
  }
  return std::max(0.0, params_.latency + jitter);
}

std::optional<int64_t> Link::Transmit(int64_t send_ns) {
  ++counters_.sent;
  // Draw both every time, so that loss and delay streams stay aligned.
  const bool lost = Lost();
  const double delay = Delay();
  if (lost) {
    ++counters_.lost;
    return std::nullopt;
  }
  const int64_t arrival = std::max<int64_t>(send_ns + std::llround(delay * 1e9), last_arrival_ns_);
  last_arrival_ns_ = arrival;
  return arrival;
}

std::optional<int64_t> Link::TransmitAcknowledged(int64_t send_ns, int64_t retry_ns, int max_tries) {
  for (int attempt = 0; attempt < max_tries; ++attempt) {
    const std::optional<int64_t> arrival = Transmit(send_ns + attempt * retry_ns);
    if (arrival) return arrival;
  }
  return std::nullopt;
}

}  // namespace turf
