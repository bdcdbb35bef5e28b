// libFuzzer: arbitrary bytes restored into an SSL and two legged kernels (one world; robots and ball in groups on
// two threads, core/legged/legged_islands.h). A
// restore must refuse what it cannot use without crashing, and a kernel that
// accepted a snapshot must step on (non-finite states are the world's to undo).
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "core/legged/legged_scene.h"
#include "kernel/legged_kernel.h"
#include "kernel/ssl_kernel.h"

namespace {

turf::LeggedScene BoxRobots(int n) {
  turf::LeggedScene s;
  turf::LeggedRobot r;
  r.model = "box.xml";
  r.model_xml =
      "<mujoco><compiler angle='radian'/><worldbody><body name='base' pos='0 0 0.5'><freejoint/><geom type='box' "
      "size='0.1 0.1 0.1'/>"
      "<body name='arm'><joint name='j1' type='hinge' axis='0 0 1'/><geom type='capsule' size='0.02' "
      "fromto='0 0 0 0.2 0 0'/></body></body></worldbody></mujoco>";
  for (int i = 0; i < n; ++i) {
    r.name = "box_" + std::to_string(i + 1);
    r.x = 3.0 * i;
    s.robots.push_back(r);
  }
  if (n > 1) {
    s.field.enabled = true;  // and its ball, in one of the groups
    s.physics.island_threads = 2;
  }
  return s;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static turf::SslKernel ssl{turf::Scene{}};
  static turf::LeggedKernel legged{BoxRobots(1)};
  static turf::LeggedKernel islands{BoxRobots(3)};
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  // Start each input from the first byte's choice of a kernel's own snapshot
  // with this input's tail spliced in, so deep sections get exercised too.
  static const std::string ssl_start = ssl.Save();
  static const std::string legged_start = legged.Save();
  static const std::string islands_start = islands.Save();
  if (size == 0) return 0;
  const int kind = data[0] % 3;
  const std::string& start = kind == 0 ? ssl_start : kind == 1 ? legged_start : islands_start;
  const size_t cut = size > 4 ? (static_cast<size_t>(data[1]) << 16 | data[2] << 8 | data[3]) % (start.size() + 1) : 0;
  const std::string spliced = start.substr(0, cut) + std::string(bytes.substr(std::min<size_t>(size, 4)));
  if (kind == 0 && ssl.Restore(spliced).empty()) ssl.Step();
  if (kind == 1 && legged.Restore(spliced).empty()) legged.Step();
  if (kind == 2 && islands.Restore(spliced).empty()) islands.Step();
  return 0;
}
