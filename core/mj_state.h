// MuJoCo's model and data, owned, and what both kinds of world do with them:
// keep the last good state to undo a step that blew up, and snapshot the data.
#pragma once

#include <memory>
#include <vector>

#include "core/state_io.h"

struct mjModel_;
struct mjData_;

namespace turf {

struct MjDeleter {
  void operator()(mjModel_* m) const;
  void operator()(mjData_* d) const;
};
using MjModelPtr = std::unique_ptr<mjModel_, MjDeleter>;
using MjDataPtr = std::unique_ptr<mjData_, MjDeleter>;

// Everything in mjData that a step reads or an output reports: the variable
// sizes, time, warnings and the whole main buffer (state, controls, warm
// start, contacts, sensors, derived quantities). Scratch memory is left out.
void SaveMjData(const mjModel_* m, const mjData_* d, StateWriter& out);
// Fails the reader (and leaves d untouched) if the snapshot is of another model.
void RestoreMjData(const mjModel_* m, mjData_* d, StateReader& in);

// A fingerprint of a compiled model's sizes, so a snapshot of one scene is
// never restored into another.
uint64_t ModelFingerprint(const mjModel_* m);

// The last frame whose time (frame x step) a snapshot may carry: 2^62 ns.
inline uint64_t MaxFrame(int64_t step_ns) {
  return step_ns > 0 ? (uint64_t{1} << 62) / static_cast<uint64_t>(step_ns) : 0;
}
// A world's frame counter read back from a snapshot: past MaxFrame fails the reader and gives 0.
inline uint64_t RestoreFrame(StateReader& in, int64_t step_ns) {
  const uint64_t frame = in.Get<uint64_t>();
  if (frame <= MaxFrame(step_ns)) return frame;
  in.Fail("frame out of range");
  return 0;
}

// A world's MuJoCo data and frame counter as one snapshot field (state_io.h): `Frame` is const when saving.
template <class Frame>
struct MjWorldState {
  const mjModel_* model;
  mjData_* data;
  Frame& frame;
  int64_t step_ns;
  void Save(StateWriter& out) const {
    SaveMjData(model, data, out);
    out.Put(frame);
  }
  void Restore(StateReader& in) {
    RestoreMjData(model, data, in);
    frame = RestoreFrame(in, step_ns);
  }
};
template <class Frame>
MjWorldState<Frame> MjWorld(const MjModelPtr& model, const MjDataPtr& data, Frame& frame, int64_t step_ns) {
  return {model.get(), data.get(), frame, step_ns};
}

// The positions of the last step that stayed finite.
class LastGoodState {
 public:
  void Accept(const mjModel_* m, const mjData_* d);
  // Back to the last good positions, at rest.
  void Undo(const mjModel_* m, mjData_* d) const;
  void Save(StateWriter& out) const;
  void Restore(StateReader& in);

 private:
  std::vector<double> qpos_;
  std::vector<double> qvel_;
};

// True if every position and velocity is finite (and no velocity beyond
// `max_speed`).
bool StateFinite(const mjModel_* m, const mjData_* d, double max_speed);

}  // namespace turf
