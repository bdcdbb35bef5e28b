// libFuzzer: arbitrary bytes restored into an SSL and a legged kernel. A
// restore must refuse what it cannot use without crashing, and a kernel that
// accepted a snapshot must step on (non-finite states are the world's to undo).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "core/legged/legged_scene.h"
#include "kernel/legged_kernel.h"
#include "kernel/ssl_kernel.h"

namespace {

turf::LeggedScene OneBoxRobot() {
  turf::LeggedScene s;
  turf::LeggedRobot r;
  r.name = "box_1";
  r.model = "box.xml";
  r.model_xml =
      "<mujoco><compiler angle='radian'/><worldbody><body name='base' pos='0 0 0.5'><freejoint/><geom type='box' "
      "size='0.1 0.1 0.1'/>"
      "<body name='arm'><joint name='j1' type='hinge' axis='0 0 1'/><geom type='capsule' size='0.02' "
      "fromto='0 0 0 0.2 0 0'/></body></body></worldbody></mujoco>";
  s.robots.push_back(r);
  return s;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static turf::SslKernel ssl{turf::Scene{}};
  static turf::LeggedKernel legged{OneBoxRobot()};
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  // Start each input from the first byte's choice of a kernel's own snapshot
  // with this input's tail spliced in, so deep sections get exercised too.
  static const std::string ssl_start = ssl.Save();
  static const std::string legged_start = legged.Save();
  if (size == 0) return 0;
  const bool use_ssl = data[0] & 1;
  const std::string& start = use_ssl ? ssl_start : legged_start;
  const size_t cut = size > 4 ? (static_cast<size_t>(data[1]) << 16 | data[2] << 8 | data[3]) % (start.size() + 1) : 0;
  const std::string spliced = start.substr(0, cut) + std::string(bytes.substr(std::min<size_t>(size, 4)));
  if (use_ssl) {
    if (ssl.Restore(spliced).empty()) ssl.Step();
  } else {
    if (legged.Restore(spliced).empty()) legged.Step();
  }
  return 0;
}
