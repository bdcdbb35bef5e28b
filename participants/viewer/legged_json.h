// Legged scenes as the page's JSON: each robot's shapes once (the "legged"
// message, sent like the SSL field: on connect and when the scene info
// arrives) and, with every state, each robot's drawn body poses as flat
// numbers. Pure functions.
//
//   legged {name, field: {length, width, goal_width, goal_depth, goal_height,
//                         ball_radius} or null (no field: no ball either),
//           robots: [{name, id, model, bodies: [body names],
//                     geoms: [{b: index into bodies, shape: "box"|"sphere"|
//                              "capsule"|"cylinder"|"ellipsoid"|"other",
//                              size: [3] (MuJoCo's: half sizes, radius, half length),
//                              p: [x,y,z], q: [w,x,y,z]  (in the body's frame)}]}]}
//   with every state: links: {<robot name>: [x,y,z, qw,qx,qy,qz, ...]}: the
//     world pose (world <- body) of each of that robot's `bodies`, in order;
//     positions to 1 mm, quaternions to 1e-4. A robot with no pose yet, or
//     whose links lack one of its bodies, is left out.
#pragma once

#include <turf/idl/Joints.h>
#include <nlohmann/json.hpp>

#include <map>
#include <string>
#include <vector>

namespace turf::viewer {

// The bodies a robot's geoms hang on, each once, in the order of first use
// (the root body first for a MuJoCo model whose root has a geom).
std::vector<std::string> DrawnBodies(const idl::RobotDescription& robot);
const char* GeomShapeName(idl::GeomShape shape);

std::string LeggedSceneJson(const idl::LeggedSceneInfo& scene);
// The "links" object of a state: newest LinkState per robot name.
nlohmann::json LinksJson(const idl::LeggedSceneInfo& scene, const std::map<std::string, idl::LinkState>& links);

}  // namespace turf::viewer
