// FrontEndHandle's members, for the front-end's .cpp, where its Impl is complete (front_end_handle.h).
#pragma once

#include <memory>
#include <utility>

#include "participants/lockstep_front_end/front_end_handle.h"

namespace turf {

template <class Impl, class Options, class StatsT>
FrontEndHandle<Impl, Options, StatsT>::FrontEndHandle(Options options)
    : impl_(std::make_unique<Impl>(std::move(options), nullptr)) {}

template <class Impl, class Options, class StatsT>
FrontEndHandle<Impl, Options, StatsT>::FrontEndHandle(Options options, dds::Bus& bus)
    : impl_(std::make_unique<Impl>(std::move(options), &bus)) {}

template <class Impl, class Options, class StatsT>
FrontEndHandle<Impl, Options, StatsT>::~FrontEndHandle() = default;

template <class Impl, class Options, class StatsT>
bool FrontEndHandle<Impl, Options, StatsT>::Run(const std::function<bool()>& stop) {
  return impl_->Run(stop);
}

template <class Impl, class Options, class StatsT>
StatsT FrontEndHandle<Impl, Options, StatsT>::Stats() const {
  return impl_->stats().Get();
}

template <class Impl, class Options, class StatsT>
StatsT FrontEndHandle<Impl, Options, StatsT>::WaitForStats(const std::function<bool(const StatsT&)>& done,
                                                           std::chrono::milliseconds timeout) const {
  return impl_->stats().WaitFor(done, timeout);
}

template <class Impl, class Options, class StatsT>
uint16_t LeagueHandle<Impl, Options, StatsT>::agent_port() const {
  return this->impl_->agent_port();
}

template <class Impl, class Options, class StatsT>
uint16_t LeagueHandle<Impl, Options, StatsT>::monitor_port() const {
  return this->impl_->monitor_port();
}

}  // namespace turf
