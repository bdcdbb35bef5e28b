#include "core/legged/nao_types.h"

#include <fmt/format.h>
#include <tinyxml2.h>

#include <cmath>
#include <cstring>
#include <initializer_list>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

namespace turf {

namespace {

using tinyxml2::XMLDocument;
using tinyxml2::XMLElement;

// The facts' robot-type table: H, T, A, E; type 4's toes.
constexpr NaoTypeOffsets kTypes[kNaoRobotTypes] = {
    {0.055, -0.04, -0.055, 0.07, false}, {0.055, -0.05832, -0.07332, 0.10664, false},
    {0.055, -0.04, -0.055, 0.07, false}, {0.072954143, -0.067868424, -0.082868424, 0.125736848, false},
    {0.055, -0.04, -0.055, 0.07, true},
};

// Type 4's feet and toes (the facts' "Nao physical model"): the foot shortened at the front to make room for the
// toe, the same 0.2 kg split between them.
constexpr double kToeLength = 0.035517656;
constexpr double kToeFootLength = 0.124482344;
constexpr double kToeFootCentreY = 0.0122412;  // ahead of the ankle
constexpr double kToeFootMass = 0.1778;
constexpr double kToeMass = 0.0222;
constexpr double kToeRange[2] = {-1.0, 70.0};  // degrees

std::string Vec(double x, double y, double z) { return fmt::format("{:.9g} {:.9g} {:.9g}", x, y, z); }

XMLElement* Find(XMLElement* e, const char* tag, const std::string& name) {
  if (std::strcmp(e->Name(), tag) == 0 && e->Attribute("name") != nullptr && name == e->Attribute("name")) return e;
  for (XMLElement* c = e->FirstChildElement(); c != nullptr; c = c->NextSiblingElement())
    if (XMLElement* found = Find(c, tag, name)) return found;
  return nullptr;
}

// The model's elements the types change, found by name; `missing` names the first that is not there.
class Elements {
 public:
  explicit Elements(XMLElement* root) : root_(root) {}
  XMLElement* Get(const char* tag, const std::string& name) {
    XMLElement* e = Find(root_, tag, name);
    if (e == nullptr && missing_.empty()) missing_ = fmt::format("{} '{}'", tag, name);
    return e;
  }
  // The x and z of a body's pos, with y replaced.
  void SetY(XMLElement* body, double y) {
    double p[3] = {0, 0, 0};
    std::istringstream in(body->Attribute("pos") != nullptr ? body->Attribute("pos") : "");
    if (!(in >> p[0] >> p[1] >> p[2]) && missing_.empty())
      missing_ = fmt::format("pos of '{}'", body->Attribute("name"));
    body->SetAttribute("pos", Vec(p[0], y, p[2]).c_str());
  }
  const std::string& missing() const { return missing_; }

 private:
  XMLElement* root_;
  std::string missing_;
};

void MoveLimbs(const NaoTypeOffsets& t, Elements* el) {
  for (const char* side : {"r", "l"}) {
    const double s = side[0] == 'r' ? 1.0 : -1.0;  // model frame: x = the robot's right
    const std::string p = side;
    if (XMLElement* hip = el->Get("body", p + "hip1"))
      hip->SetAttribute("pos", Vec(s * t.hip_x, -0.01, -0.115).c_str());
    if (XMLElement* thigh = el->Get("body", p + "thigh")) thigh->SetAttribute("pos", Vec(0, 0.01, t.thigh_z).c_str());
    // lj1..lj3 turn about the hip's centre: the thigh's hinge sits T above the thigh.
    if (XMLElement* lj3 = el->Get("joint", p + "lj3")) lj3->SetAttribute("pos", Vec(0, -0.01, -t.thigh_z).c_str());
    if (XMLElement* ankle = el->Get("body", p + "ankle")) ankle->SetAttribute("pos", Vec(0, -0.01, t.ankle_z).c_str());
    if (XMLElement* elbow = el->Get("body", p + "elbow")) el->SetY(elbow, t.elbow_y);
  }
}

// The bodies of the model that collide (a geom with contype or conaffinity set).
std::vector<std::string> CollidingBodies(XMLElement* e) {
  std::vector<std::string> out;
  if (std::strcmp(e->Name(), "body") == 0) {
    for (XMLElement* g = e->FirstChildElement("geom"); g != nullptr; g = g->NextSiblingElement("geom")) {
      if (g->IntAttribute("contype", 1) != 0 || g->IntAttribute("conaffinity", 1) != 0) {
        out.push_back(e->Attribute("name") != nullptr ? e->Attribute("name") : "");
        break;
      }
    }
  }
  for (XMLElement* c = e->FirstChildElement(); c != nullptr; c = c->NextSiblingElement()) {
    std::vector<std::string> more = CollidingBodies(c);
    out.insert(out.end(), more.begin(), more.end());
  }
  return out;
}

// A new element under `parent` with the attributes given, in order.
XMLElement* Add(XMLDocument* doc, XMLElement* parent, const char* tag,
                std::initializer_list<std::pair<const char*, std::string>> attributes = {}) {
  XMLElement* e = doc->NewElement(tag);
  for (const auto& [name, value] : attributes) e->SetAttribute(name, value.c_str());
  parent->InsertEndChild(e);
  return e;
}

std::string Num(double v) { return fmt::format("{:.9g}", v); }

// The foot of side `p` shortened at the front; false if the model lacks it.
bool ShortenFoot(const std::string& p, Elements* el) {
  XMLElement* foot = el->Get("body", p + "foot");
  XMLElement* geom = el->Get("geom", p + "foot");
  XMLElement* site = el->Get("site", p + "f");
  if (foot == nullptr || geom == nullptr || site == nullptr) return false;
  foot->SetAttribute("pos", Vec(0, kToeFootCentreY, -0.04).c_str());
  geom->SetAttribute("size", Vec(0.04, kToeFootLength / 2, 0.01).c_str());
  geom->SetAttribute("mass", Num(kToeFootMass).c_str());
  site->SetAttribute("size", Vec(0.042, kToeFootLength / 2 + 0.002, 0.014).c_str());
  return true;
}

// The toe of side `p` at the foot's front edge, on the sole: its hinge at the toe's rear edge, its touch sensor.
void AddToe(XMLDocument* doc, const std::string& p, XMLElement* foot, XMLElement* sensor) {
  const double half = kToeLength / 2;
  XMLElement* toe = Add(doc, foot, "body", {{"name", p + "toe"}, {"pos", Vec(0, kToeFootLength / 2 + half, -0.005)}});
  Add(doc, toe, "joint",
      {{"name", p + "lj7"},
       {"axis", "1 0 0"},
       {"pos", Vec(0, -half, -0.005)},
       {"range", Num(kToeRange[0] * M_PI / 180) + " " + Num(kToeRange[1] * M_PI / 180)}});
  Add(doc, toe, "geom",
      {{"name", p + "toe"},
       {"type", "box"},
       {"size", Vec(0.04, half, 0.005)},
       {"mass", Num(kToeMass)},
       {"contype", "1"},
       {"conaffinity", "1"}});
  Add(doc, toe, "site", {{"name", p + "f1"}, {"type", "box"}, {"size", Vec(0.042, half + 0.002, 0.009)}});
  Add(doc, sensor, "touch", {{"name", p + "f1"}, {"site", p + "f1"}});
}

XMLElement* Section(XMLDocument* doc, const char* tag) {
  XMLElement* e = doc->RootElement()->FirstChildElement(tag);
  return e != nullptr ? e : Add(doc, doc->RootElement(), tag);
}

// Splits each foot into a shorter foot and a toe on a hinge. A robot's own parts never collide (SimSpark): each toe
// with every other colliding body of the robot, and the other toe.
void AddToes(XMLDocument* doc, Elements* el) {
  const std::vector<std::string> others = CollidingBodies(doc->RootElement());  // before the toes
  XMLElement* contact = Section(doc, "contact");
  XMLElement* sensor = Section(doc, "sensor");
  for (const std::string p : {"r", "l"}) {
    if (!ShortenFoot(p, el)) return;
    AddToe(doc, p, el->Get("body", p + "foot"), sensor);
    for (const std::string& body : others) Add(doc, contact, "exclude", {{"body1", p + "toe"}, {"body2", body}});
  }
  Add(doc, contact, "exclude", {{"body1", "ltoe"}, {"body2", "rtoe"}});
}

}  // namespace

const NaoTypeOffsets& NaoType(int type) {
  if (type < 0 || type >= kNaoRobotTypes) throw std::out_of_range(fmt::format("Nao robot type {} (0..4)", type));
  return kTypes[type];
}

NaoTypeModel NaoTypeMjcf(const std::string& type0_xml, int type) {
  if (type < 0 || type >= kNaoRobotTypes) return {"", fmt::format("robot type {} is not 0..4", type)};
  XMLDocument doc;
  if (doc.Parse(type0_xml.c_str(), type0_xml.size()) != tinyxml2::XML_SUCCESS || doc.RootElement() == nullptr)
    return {"", fmt::format("not XML: {}", doc.ErrorStr())};
  const NaoTypeOffsets& t = kTypes[type];
  Elements el(doc.RootElement());
  if (XMLElement* torso = el.Get("body", "torso")) {
    double p[3] = {0, 0, 0};
    std::istringstream in(torso->Attribute("pos") != nullptr ? torso->Attribute("pos") : "0 0 0");
    in >> p[0] >> p[1] >> p[2];
    torso->SetAttribute("pos", Vec(p[0], p[1], t.SoleBelowTorso()).c_str());
  }
  MoveLimbs(t, &el);
  if (t.toes) AddToes(&doc, &el);
  if (!el.missing().empty())
    return {"", fmt::format("robot type {} needs the Nao model's {} (configs/robots/nao.xml)", type, el.missing())};
  tinyxml2::XMLPrinter printer;
  doc.Print(&printer);
  return {printer.CStr(), ""};
}

}  // namespace turf
