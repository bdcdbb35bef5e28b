#include "participants/viewer/legged_json.h"

#include <algorithm>

#include "core/enum_names.h"
#include "participants/viewer/json_util.h"

namespace turf::viewer {

namespace {

using json_util::R;
using nlohmann::json;

// Where `name` is among `links`: `hint` first (the publisher keeps one order).
const idl::LinkPose* FindLink(const idl::LinkState& links, const std::string& name, size_t hint) {
  const std::vector<idl::LinkPose>& all = links.links();
  if (hint < all.size() && all[hint].name() == name) return &all[hint];
  const auto it = std::find_if(all.begin(), all.end(), [&](const idl::LinkPose& l) { return l.name() == name; });
  return it == all.end() ? nullptr : &*it;
}

}  // namespace

std::vector<std::string> DrawnBodies(const idl::RobotDescription& robot) {
  std::vector<std::string> bodies;
  for (const idl::RobotGeom& g : robot.geoms())
    if (std::find(bodies.begin(), bodies.end(), g.body()) == bodies.end()) bodies.push_back(g.body());
  return bodies;
}

const char* GeomShapeName(idl::GeomShape shape) {
  constexpr const char* kNames[] = {"box", "sphere", "capsule", "cylinder", "ellipsoid", "other"};
  return EnumName(shape, kNames, "other");
}

std::string LeggedSceneJson(const idl::LeggedSceneInfo& s) {
  json robots = json::array();
  for (const idl::RobotDescription& r : s.robots()) {
    const std::vector<std::string> bodies = DrawnBodies(r);
    json geoms = json::array();
    for (const idl::RobotGeom& g : r.geoms()) {
      const size_t b = std::find(bodies.begin(), bodies.end(), g.body()) - bodies.begin();
      const idl::Vec3& size = g.size();
      const idl::Vec3& p = g.position();
      const idl::Quat& q = g.orientation();
      geoms.push_back({{"b", b},
                       {"shape", GeomShapeName(g.shape())},
                       {"size", {R(size.x()), R(size.y()), R(size.z())}},
                       {"p", {R(p.x()), R(p.y()), R(p.z())}},
                       {"q", {R(q.w()), R(q.x()), R(q.y()), R(q.z())}}});
    }
    robots.push_back({{"name", r.robot()}, {"id", r.id()}, {"model", r.model()}, {"bodies", bodies}, {"geoms", geoms}});
  }
  json field = nullptr;
  if (s.has_field()) {
    field = {{"length", R(s.field_length())},     {"width", R(s.field_width())},
             {"goal_width", R(s.goal_width())},   {"goal_depth", R(s.goal_depth())},
             {"goal_height", R(s.goal_height())}, {"ball_radius", R(s.ball_radius())}};
  }
  return json_util::Dump(json{{"type", "legged"}, {"name", s.name()}, {"field", field}, {"robots", robots}});
}

json LinksJson(const idl::LeggedSceneInfo& scene, const std::map<std::string, idl::LinkState>& links) {
  json out = json::object();
  for (const idl::RobotDescription& r : scene.robots()) {
    const auto it = links.find(r.robot());
    if (it == links.end()) continue;
    const std::vector<std::string> bodies = DrawnBodies(r);
    json poses = json::array();
    for (size_t i = 0; i < bodies.size(); ++i) {
      const idl::LinkPose* l = FindLink(it->second, bodies[i], i);
      if (!l) break;
      const idl::Vec3& p = l->position();
      const idl::Quat& q = l->orientation();
      for (double v : {R(p.x(), 1e3), R(p.y(), 1e3), R(p.z(), 1e3), R(q.w()), R(q.x()), R(q.y()), R(q.z())})
        poses.push_back(v);
    }
    if (poses.size() == 7 * bodies.size()) out[r.robot()] = std::move(poses);
  }
  return out;
}

}  // namespace turf::viewer
