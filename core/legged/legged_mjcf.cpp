#include "core/legged/legged_mjcf.h"

#include <fmt/format.h>
#include <tinyxml2.h>

#include <mujoco/mujoco.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <sstream>
#include <stdexcept>

namespace turf {

namespace {

using tinyxml2::XMLDocument;
using tinyxml2::XMLElement;
using tinyxml2::XMLNode;

// Attributes that name an element or refer to one: all get the prefix.
constexpr const char* kNameAttributes[] = {
    "name", "class",    "childclass", "joint",  "joint1",   "joint2",        "body",       "body1",     "body2",
    "site", "geom",     "geom1",      "geom2",  "objname",  "refname",       "tendon",     "tendon1",   "tendon2",
    "mesh", "material", "texture",    "hfield", "actuator", "jointinparent", "slidersite", "cranksite", "target"};

constexpr const char* kCopiedSections[] = {"contact", "equality", "tendon", "sensor"};

void PrefixNames(XMLElement* e, const std::string& prefix) {
  for (const char* attr : kNameAttributes) {
    const char* v = e->Attribute(attr);
    if (v != nullptr) e->SetAttribute(attr, LeggedElementName(prefix, v).c_str());
  }
  for (XMLElement* c = e->FirstChildElement(); c != nullptr; c = c->NextSiblingElement()) PrefixNames(c, prefix);
}

// Elements a robot file may not hold: files read from elsewhere (<include>), and generators and assets whose sizes
// MuJoCo 2.2.2 takes as they come (a 60000 x 60000 texture crashed it; a 400 x 400 composite took minutes to
// compile, deaf to signals). The first found in `e`'s subtree, or null.
const char* Refused(const XMLElement* e) {
  static constexpr const char* kRefused[] = {"include", "composite", "flexcomp", "skin", "texture", "hfield"};
  for (const char* name : kRefused)
    if (std::strcmp(e->Name(), name) == 0) return name;
  for (const XMLElement* c = e->FirstChildElement(); c != nullptr; c = c->NextSiblingElement())
    if (const char* found = Refused(c)) return found;
  return nullptr;
}

bool ReadVector(const char* text, double* out, int n) {
  std::istringstream in(text);
  for (int i = 0; i < n; ++i) {
    if (!(in >> out[i]) || !std::isfinite(out[i])) return false;
  }
  return true;
}

// Moves a robot's top-level body to its placement: rotated by yaw about z,
// shifted to (x, y) on the ground, and raised to the placement's z if given.
bool PlaceBody(XMLElement* body, const LeggedRobot& r, std::vector<std::string>* errors) {
  for (const char* attr : {"euler", "axisangle", "xyaxes", "zaxis"}) {
    if (body->Attribute(attr) != nullptr) {
      errors->push_back(fmt::format("robot {}: a top-level body may orient with quat only, not {}", r.name, attr));
      return false;
    }
  }
  double p[3] = {0, 0, 0};
  double q[4] = {1, 0, 0, 0};
  if (const char* pos = body->Attribute("pos"); pos != nullptr && !ReadVector(pos, p, 3)) {
    errors->push_back(fmt::format("robot {}: bad pos of a top-level body", r.name));
    return false;
  }
  if (const char* quat = body->Attribute("quat"); quat != nullptr && !ReadVector(quat, q, 4)) {
    errors->push_back(fmt::format("robot {}: bad quat of a top-level body", r.name));
    return false;
  }
  const double c = std::cos(r.yaw);
  const double s = std::sin(r.yaw);
  const double px = r.x + c * p[0] - s * p[1];
  const double py = r.y + s * p[0] + c * p[1];
  // Yaw quaternion (cos(yaw/2), 0, 0, sin(yaw/2)) times q.
  const double w = std::cos(r.yaw / 2);
  const double z = std::sin(r.yaw / 2);
  const double qw = w * q[0] - z * q[3];
  const double qx = w * q[1] - z * q[2];
  const double qy = w * q[2] + z * q[1];
  const double qz = w * q[3] + z * q[0];
  const double pz = r.z ? *r.z : p[2];
  body->SetAttribute("pos", fmt::format("{:.9g} {:.9g} {:.9g}", px, py, pz).c_str());
  body->SetAttribute("quat", fmt::format("{:.9g} {:.9g} {:.9g} {:.9g}", qw, qx, qy, qz).c_str());
  return true;
}

std::string FieldXml(const Field3d& f, double friction) {
  std::string x;
  auto box = [&x, friction](const std::string& name, double px, double py, double pz, double hx, double hy, double hz) {
    x += fmt::format(R"(    <geom name="{}" type="box" pos="{:.6g} {:.6g} {:.6g}" size="{:.6g} {:.6g} {:.6g}" )"
                     R"(friction="{:.4g} 0.005 0.0001" rgba="0.9 0.9 0.9 1"/>)"
                     "\n",
                     name, px, py, pz, hx, hy, hz, friction);
  };
  const double hx = f.length / 2;
  const double gh = f.goal_height / 2;
  for (int side : {-1, 1}) {
    const char* n = side < 0 ? "left" : "right";
    const double x_mid = side * (hx + f.goal_depth / 2);
    for (int post : {-1, 1}) {
      box(fmt::format("goal_{}_side_{}", n, post < 0 ? "neg" : "pos"), x_mid,
          post * (f.goal_width / 2 + f.goal_wall / 2), gh, f.goal_depth / 2, f.goal_wall / 2, gh);
    }
    box(fmt::format("goal_{}_back", n), side * (hx + f.goal_depth - f.goal_wall / 2 + f.goal_wall), 0, gh,
        f.goal_wall / 2, f.goal_width / 2, gh);
    box(fmt::format("goal_{}_roof", n), x_mid, 0, f.goal_height + f.goal_wall / 2, f.goal_depth / 2,
        f.goal_width / 2 + f.goal_wall, f.goal_wall / 2);
  }
  const double d = f.wall_distance;
  if (f.walls) {
    box("wall_neg_x", -d, 0, 0, 0.5, d, 0.5);
    box("wall_pos_x", d, 0, 0, 0.5, d, 0.5);
    box("wall_neg_y", 0, -d, 0, d, 0.5, 0.5);
    box("wall_pos_y", 0, d, 0, d, 0.5, 0.5);
  }
  if (!f.ball) return x;
  const double inertia = 0.4 * f.ball_mass * f.ball_radius * f.ball_radius;
  x += fmt::format(R"(    <body name="{}" pos="{:.6g} {:.6g} {:.6g}">)"
                   "\n"
                   R"(      <freejoint name="ball"/>)"
                   "\n"
                   R"(      <inertial pos="0 0 0" mass="{:.6g}" diaginertia="{:.6g} {:.6g} {:.6g}"/>)"
                   "\n"
                   R"(      <geom name="ball" type="sphere" size="{:.6g}" friction="{:.6g} {:.6g} {:.6g}" )"
                   R"(condim="{}" solref="{:.6g} {:.6g}" priority="{}" rgba="1 0.5 0 1"/>)"
                   "\n    </body>\n",
                   kLeggedBall, f.ball_x, f.ball_y, f.ball_radius, f.ball_mass, inertia, inertia, inertia,
                   f.ball_radius, f.ball_friction[0], f.ball_friction[1], f.ball_friction[2], f.ball_condim,
                   f.ball_solref[0], f.ball_solref[1], f.ball_priority);
  return x;
}

std::string SceneXml(const LeggedScene& s) {
  const int n = static_cast<int>(s.robots.size());
  const int nconmax = 60 * n + 20;
  std::string x;
  x += fmt::format("<mujoco model=\"turf_{}\">\n", s.name);
  x += "  <compiler autolimits=\"true\" angle=\"radian\"/>\n";
  // rcssserver3d's contact law rewrites the rows of an elliptic cone (ode_contacts.h).
  x += fmt::format(
      "  <option timestep=\"{}\" iterations=\"{}\" gravity=\"0 0 -9.81\" integrator=\"Euler\" density=\"{:.6g}\" "
      "viscosity=\"{:.6g}\"{}/>\n",
      s.physics.step, s.physics.solver_iterations, s.physics.fluid_density, s.physics.fluid_viscosity,
      s.contacts.enabled ? " cone=\"elliptic\"" : "");
  x += fmt::format("  <size nconmax=\"{}\" njmax=\"{}\"/>\n", nconmax, 6 * nconmax);
  x += "  <default/>\n  <asset/>\n  <worldbody>\n";
  const double half = s.field.enabled ? s.field.wall_distance : 50.0;
  x += fmt::format(R"(    <geom name="{}" type="plane" size="{:.6g} {:.6g} 0.1" friction="{:.4g} 0.005 0.0001" )"
                   R"(rgba="0.1 0.5 0.1 1"/>)"
                   "\n",
                   kLeggedFloor, half, half, s.ground_friction);
  if (s.field.enabled) x += FieldXml(s.field, s.ground_friction);
  x += "  </worldbody>\n";
  for (const char* section : kCopiedSections) x += fmt::format("  <{}/>\n", section);
  x += "</mujoco>\n";
  return x;
}

void AddRobot(const LeggedRobot& r, XMLElement* out_root, std::vector<std::string>* errors) {
  XMLDocument doc;
  if (doc.Parse(r.model_xml.c_str(), r.model_xml.size()) != tinyxml2::XML_SUCCESS) {
    errors->push_back(fmt::format("robot {} ({}): not XML: {}", r.name, r.model, doc.ErrorStr()));
    return;
  }
  const XMLElement* root = doc.RootElement();
  if (root == nullptr || std::strcmp(root->Name(), "mujoco") != 0) {
    errors->push_back(fmt::format("robot {} ({}): the root element must be <mujoco>", r.name, r.model));
    return;
  }
  const XMLElement* compiler = root->FirstChildElement("compiler");
  const char* angle = compiler != nullptr ? compiler->Attribute("angle") : nullptr;
  if (angle == nullptr || std::strcmp(angle, "radian") != 0) {
    errors->push_back(fmt::format("robot {} ({}): needs <compiler angle=\"radian\"/>", r.name, r.model));
    return;
  }
  if (const char* refused = Refused(root)) {
    errors->push_back(fmt::format("robot {} ({}): <{}> is not supported in a robot file", r.name, r.model, refused));
    return;
  }
  XMLDocument* out = out_root->GetDocument();
  for (const XMLElement* section = root->FirstChildElement(); section != nullptr;
       section = section->NextSiblingElement()) {
    const std::string kind = section->Name();
    if (kind == "default") {
      XMLElement* cls = section->DeepClone(out)->ToElement();
      PrefixNames(cls, r.name);
      cls->SetAttribute("class", r.name.c_str());  // the robot's own class
      out_root->FirstChildElement("default")->InsertEndChild(cls);
    } else if (kind == "asset") {
      for (const XMLElement* a = section->FirstChildElement(); a != nullptr; a = a->NextSiblingElement()) {
        if (a->Attribute("file") != nullptr) {
          errors->push_back(fmt::format("robot {} ({}): assets from files are not supported", r.name, r.model));
          return;
        }
        XMLElement* c = a->DeepClone(out)->ToElement();
        PrefixNames(c, r.name);
        out_root->FirstChildElement("asset")->InsertEndChild(c);
      }
    } else if (kind == "worldbody") {
      for (const XMLElement* b = section->FirstChildElement(); b != nullptr; b = b->NextSiblingElement()) {
        if (std::strcmp(b->Name(), "body") != 0) {
          errors->push_back(
              fmt::format("robot {} ({}): only bodies may sit in <worldbody>, found <{}>", r.name, r.model, b->Name()));
          return;
        }
        XMLElement* c = b->DeepClone(out)->ToElement();
        PrefixNames(c, r.name);
        if (c->Attribute("childclass") == nullptr && root->FirstChildElement("default") != nullptr)
          c->SetAttribute("childclass", r.name.c_str());
        if (!PlaceBody(c, r, errors)) return;
        out_root->FirstChildElement("worldbody")->InsertEndChild(c);
      }
    } else {
      for (const char* copied : kCopiedSections) {
        if (kind != copied) continue;
        for (const XMLElement* e = section->FirstChildElement(); e != nullptr; e = e->NextSiblingElement()) {
          XMLElement* c = e->DeepClone(out)->ToElement();
          PrefixNames(c, r.name);
          out_root->FirstChildElement(copied)->InsertEndChild(c);
        }
      }
    }
  }
}

}  // namespace

std::string LeggedElementName(const std::string& robot, const std::string& element) { return robot + "/" + element; }

LeggedMjcf ComposeLeggedMjcf(const LeggedScene& scene) {
  LeggedMjcf result;
  XMLDocument out;
  const std::string base = SceneXml(scene);
  if (out.Parse(base.c_str(), base.size()) != tinyxml2::XML_SUCCESS) {
    result.errors.push_back(fmt::format("internal: scene MJCF does not parse: {}", out.ErrorStr()));
    return result;
  }
  for (const LeggedRobot& r : scene.robots) AddRobot(r, out.RootElement(), &result.errors);
  if (!result.errors.empty()) return result;
  tinyxml2::XMLPrinter printer;
  out.Print(&printer);
  result.xml = printer.CStr();
  return result;
}

mjModel* CompileLeggedMjcf(const std::string& xml) {
  auto vfs = std::make_unique<mjVFS>();  // ~2 MB: never on the stack
  mj_defaultVFS(vfs.get());
  constexpr const char* kFile = "legged_scene.xml";
  if (mj_makeEmptyFileVFS(vfs.get(), kFile, static_cast<int>(xml.size())) != 0)
    throw std::invalid_argument("MuJoCo VFS is full");
  std::copy(xml.begin(), xml.end(), static_cast<char*>(vfs->filedata[vfs->nfile - 1]));
  constexpr int kErrorSize = 1000;
  char error[kErrorSize] = {0};
  mjModel* m = mj_loadXML(kFile, vfs.get(), error, kErrorSize);
  mj_deleteVFS(vfs.get());
  if (m == nullptr) throw std::invalid_argument(fmt::format("MuJoCo cannot compile the legged scene: {}", error));
  return m;
}

}  // namespace turf
