// What turf.SslSim and turf.LeggedSim share around their kernel (SslKernel, LeggedKernel): snapshots, a reset
// with an optional new seed, realism changes by preset and values, and the world's DDS publication. Header-only.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "python/src/controls.h"
#include "python/src/publication.h"
#include "python/src/sim_error.h"

namespace turf::py {

template <class Kernel, class WorldPublication>
class KernelHost {
 public:
  // step() runs without the GIL, so Sims in different threads step in parallel. Meanwhile every other call on the
  // same Sim is refused (not_allowed): another thread's reset or teleport would change the world under the step.
  // The flag is read and written with the GIL held only.
  class StepScope {
   public:
    explicit StepScope(KernelHost& host) : host_(host) {
      host_.CheckIdle();
      host_.stepping_ = true;
    }
    ~StepScope() { host_.stepping_ = false; }
    StepScope(const StepScope&) = delete;
    StepScope& operator=(const StepScope&) = delete;

   private:
    KernelHost& host_;
  };
  void CheckIdle() const {
    if (stepping_)
      throw SimError(Error::kNotAllowed,
                     "this Sim is stepping in another thread (not_allowed): use a Sim from one thread at a time");
  }

  const Kernel& kernel() const { return *kernel_; }
  std::string Save() const { return kernel_->Save(); }

  // The world's topics on a DDS domain from now on (publication.h), replacing an earlier publication; Unpublish
  // ends it. publication() is null while not publishing. Options turf-sim would refuse leave the publication as
  // it was.
  void Publish(const PublishOptions& options) {
    CheckPublishOptions(options);
    publication_.reset();
    publication_ = std::make_unique<WorldPublication>(options, *kernel_);
  }
  void Unpublish() { publication_.reset(); }
  const WorldPublication* publication() const { return publication_.get(); }

 protected:
  explicit KernelHost(std::unique_ptr<Kernel> kernel) : kernel_(std::move(kernel)) {}

  // The realism `preset` with `values` changed (controls.h); throws SimError (invalid_realism) if the kernel
  // refuses it.
  void ChangeRealism(const std::string& preset, const std::vector<std::pair<std::string, double>>& values) {
    const SensorRealism realism = ChangedRealism(kernel_->realism(), preset, values);
    if (std::string e = kernel_->SetRealism(realism); !e.empty()) Check(Error::kInvalidRealism, e);
  }

  // Back to the scene's start; a new seed rebuilds the kernel (the realism is kept).
  void ResetKernel(std::optional<uint64_t> seed) {
    if (seed && *seed != kernel_->scene().seed) {
      auto scene = kernel_->scene();
      scene.seed = *seed;
      scene.realism = kernel_->realism();
      kernel_ = std::make_unique<Kernel>(std::move(scene));
    } else {
      kernel_->Reset();
    }
  }

  // Throws SimError (malformed) for a snapshot the kernel refuses.
  void RestoreKernel(const std::string& snapshot) {
    if (std::string e = kernel_->Restore(snapshot); !e.empty()) Check(Error::kMalformed, "snapshot (" + e + ")");
  }

  std::unique_ptr<Kernel> kernel_;
  std::unique_ptr<WorldPublication> publication_;

 private:
  bool stepping_ = false;
};

}  // namespace turf::py
