// libFuzzer target for the viewer's page messages (ParsePageRequest: JSON from anyone who reaches the web port):
// any bytes are accepted with a finite request of a known operation or refused with a named error, never a crash,
// a sanitizer report or an exception. The first byte picks the scene the message is checked against: none, an SSL
// field (division B), a legged scene.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "participants/viewer/page_request.h"
#include "tests/viewer/viewer_samples.h"

namespace {

bool Finite(const turf::idl::Vec3& v) { return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z()); }
bool Finite(const turf::idl::Vec2& v) { return std::isfinite(v.x()) && std::isfinite(v.y()); }
bool Finite(const turf::idl::Quat& q) {
  return std::isfinite(q.w()) && std::isfinite(q.x()) && std::isfinite(q.y()) && std::isfinite(q.z());
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace turf;
  if (size == 0) return 0;
  static const idl::SslField field = test::DivBField();
  static const idl::LeggedSceneInfo legged = test::LeggedScene();
  viewer::PageScene scene;
  if (data[0] % 3 == 1) scene.ssl = &field;
  if (data[0] % 3 == 2) scene.legged = &legged;
  const std::string_view text(reinterpret_cast<const char*>(data) + 1, size - 1);
  const viewer::PageRequest r = viewer::ParsePageRequest(text, scene);
  if (r.error != Error::kOk) {
    if (r.detail.empty()) std::abort();
    return 0;
  }
  if (r.op.empty() || text.size() > viewer::kMaxPageMessage) std::abort();
  const idl::SimControl& c = r.control;
  if (!Finite(c.ball().position()) || !Finite(c.ball().velocity()) || !std::isfinite(c.speed())) std::abort();
  if (!Finite(c.robot().position()) || !std::isfinite(c.robot().orientation()) || !Finite(c.robot().velocity()))
    std::abort();
  if (!Finite(c.legged().position()) || !Finite(c.legged().orientation())) std::abort();
  return 0;
}
