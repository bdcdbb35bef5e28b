// A Nao scene for the legged tests: configs/robots/nao.xml placed on flat
// ground, no file parsing beyond reading the robot file.
#pragma once

#include <fstream>
#include <sstream>
#include <string>

#include "core/legged/legged_scene.h"

namespace turf::testing {

inline std::string ReadNaoXml() {
  std::ifstream in(std::string(TURF_SOURCE_DIR) + "/configs/robots/nao.xml");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

inline LeggedRobot Nao(const std::string& name, double x, double y, double yaw) {
  LeggedRobot r;
  r.name = name;
  r.model = "nao.xml";
  r.model_xml = ReadNaoXml();
  r.x = x;
  r.y = y;
  r.yaw = yaw;
  return r;
}

inline LeggedScene NaoScene(int robots = 1, bool field = false) {
  LeggedScene s;
  s.name = "nao-test";
  s.physics.sensors_after_step = true;  // rcssserver3d's perceptors: the state after the step, as simspark_match.yaml
  s.field.enabled = field;
  for (int i = 0; i < robots; ++i) s.robots.push_back(Nao("nao_" + std::to_string(i + 1), -2.0 + i, 0.0, 0.0));
  return s;
}

}  // namespace turf::testing
