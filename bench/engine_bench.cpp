// The physics engine's speed with N Booster T1 robots, the world bench/rcssservermj_nn/reference_speed.mjs builds on
// the reference's engine (MuJoCo 3, RCSSServerMJ's robot file): the robot of configs/scenes/t1_stand.yaml copied N
// times in a row 2 m apart, every copy holding the scene's pose with its PD gains, in RCSSServerMJ's air. One step of
// turf's legged kernel (every stage; MuJoCo 2.2.2; one world, or physics.island_threads groups of robots stepped
// side by side), after 200 steps of settling. Prints table rows; run on demand
// (bench/run.sh engine).
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "kernel/legged_kernel.h"
#include "loader/legged_scene_yaml.h"

namespace {

using Clock = std::chrono::steady_clock;
constexpr double kSpacing = 2.0;  // m between the robots
constexpr int kWarmup = 200;

turf::LeggedScene Copies(const turf::LeggedScene& stand, int n) {
  turf::LeggedScene scene = stand;
  scene.physics.fluid_density = 1.2;  // RCSSServerMJ's air (its world's <option>)
  scene.physics.fluid_viscosity = 2.0e-5;
  scene.robots.clear();
  for (int i = 0; i < n; ++i) {
    turf::LeggedRobot r = stand.robots.front();
    r.name = "t1_" + std::to_string(i + 1);
    r.id = i + 1;
    r.x = (i - (n - 1) / 2.0) * kSpacing;
    scene.robots.push_back(std::move(r));
  }
  return scene;
}

void Row(const turf::LeggedScene& stand, int n, int steps, int threads) {
  turf::LeggedScene scene = Copies(stand, n);
  scene.physics.island_threads = threads;
  turf::LeggedKernel kernel(std::move(scene));
  for (int i = 0; i < kWarmup; ++i) kernel.Step();
  const turf::LeggedHealth before = kernel.world().health();
  const auto start = Clock::now();
  for (int i = 0; i < steps; ++i) kernel.Step();
  const double us = std::chrono::duration<double, std::micro>(Clock::now() - start).count() / steps;
  const double step_us = kernel.scene().physics.step * 1e6;
  const turf::LeggedHealth& after = kernel.world().health();
  const double iterations = static_cast<double>(after.solver_iterations - before.solver_iterations) / steps;
  const double rows = static_cast<double>(after.constraint_rows - before.constraint_rows) / steps;
  const std::string engine = threads == 1 ? "turf's legged kernel, MuJoCo 2.2.2 (native)"
                                          : "turf's legged kernel, islands on " + std::to_string(threads) + " threads";
  // Solver iterations: summed over the groups' worlds, each solving its own islands.
  std::printf("| %-43s | %6d | %8.1f | %8.1f | %5.1fx | %10.2f | %5.0f |\n", engine.c_str(), n, us, us / n,
              step_us / us, iterations, rows);
}

std::vector<int> Counts(const std::string& text) {
  std::vector<int> counts;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) counts.push_back(std::stoi(item));
  return counts;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"turf-bench-engine: physics steps with N T1 robots holding a standing pose"};
  std::string counts = "1,2,11,22";
  int steps = 1000;
  bool header = false;
  app.add_option("--counts", counts, "comma-separated robot counts");
  app.add_option("--steps", steps, "measured steps per row")->check(CLI::Range(1, 1000000));
  app.add_flag("--header", header, "print the table's header first");
  std::string threads = "1";
  app.add_option("--island-threads", threads,
                 "comma-separated physics.island_threads values: a row for each count with each (1: one world)");
  CLI11_PARSE(app, argc, argv);
  turf::LeggedSceneLoadResult stand = turf::LoadLeggedSceneFile(TURF_SOURCE_DIR "/configs/scenes/t1_stand.yaml");
  if (!stand.scene) throw std::runtime_error("cannot load configs/scenes/t1_stand.yaml");
  if (header) {
    std::printf("| %-43s | robots |  us/step | us/robot |    RTF | solver its |  rows |\n", "engine");
    std::printf("| %s | ------ | -------- | -------- | ------ | ---------- | ----- |\n", std::string(43, '-').c_str());
  }
  for (int t : Counts(threads)) {
    for (int n : Counts(counts)) Row(*stand.scene, n, steps, t);
  }
  return 0;
}
