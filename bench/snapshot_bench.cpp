// What a kernel snapshot costs (kernel/): its size, Save() and Restore()
// time, next to one physics step of the same kernel measured in the same run,
// for the SSL match, the 22-Nao SimSpark scene at realistic realism and the 22-T1 RCSSServerMJ scene.
// Prints a table; run on demand (bench/run.sh snapshot).
#include <chrono>
#include <cstdio>
#include <functional>
#include <stdexcept>
#include <string>

#include "kernel/legged_kernel.h"
#include "kernel/ssl_kernel.h"
#include "loader/legged_scene_yaml.h"
#include "loader/realism_yaml.h"
#include "loader/scene_yaml.h"

namespace {

using Clock = std::chrono::steady_clock;

// Mean wall time of `f` over `n` calls, in microseconds.
double MeanUs(int n, const std::function<void()>& f) {
  const auto start = Clock::now();
  for (int i = 0; i < n; ++i) f();
  return std::chrono::duration<double, std::micro>(Clock::now() - start).count() / n;
}

turf::SensorRealism Realistic() {
  turf::RealismLoadResult r = turf::LoadRealism("realistic");
  if (!r.realism) throw std::runtime_error("no realistic preset");
  return *r.realism;
}

template <class Kernel>
void Row(const char* name, Kernel& k, int warmup) {
  for (int i = 0; i < warmup; ++i) k.Step();  // contacts, frames and commands in flight
  const std::string snapshot = k.Save();
  std::string error;
  const double step = MeanUs(500, [&] { k.Step(); });
  const double save = MeanUs(200, [&] { (void)k.Save(); });
  const double restore = MeanUs(200, [&] { error = k.Restore(snapshot); });
  if (!error.empty()) throw std::runtime_error(error);
  std::printf("| %-28s | %9.1f | %9.1f | %11.1f | %10.1f |\n", name, snapshot.size() / 1024.0, step, save, restore);
}

}  // namespace

int main() {
  std::printf("| %-28s | %9s | %9s | %11s | %10s |\n", "scene (realistic)", "size KiB", "step us", "Save() us",
              "Restore us");
  std::printf("|------------------------------|-----------|-----------|-------------|------------|\n");
  turf::SceneLoadResult ssl = turf::LoadSceneFile(TURF_SOURCE_DIR "/configs/scenes/ssl_div_a.yaml");
  turf::LeggedSceneLoadResult legged = turf::LoadLeggedSceneFile(TURF_SOURCE_DIR "/configs/scenes/simspark_match.yaml");
  turf::LeggedSceneLoadResult t1 = turf::LoadLeggedSceneFile(TURF_SOURCE_DIR "/configs/scenes/rcssservermj_fifa.yaml");
  if (!ssl.scene || !legged.scene || !t1.scene) throw std::runtime_error("cannot load the scenes");
  ssl.scene->realism = Realistic();
  legged.scene->realism = Realistic();
  turf::SslKernel ssl_kernel(std::move(*ssl.scene));
  turf::LeggedKernel legged_kernel(std::move(*legged.scene));
  Row("SSL division A, 2x11", ssl_kernel, 500);
  Row("SimSpark match, 22 Naos", legged_kernel, 300);
  turf::LeggedKernel t1_kernel(std::move(*t1.scene));
  Row("RCSSServerMJ match, 22 T1", t1_kernel, 300);
  std::printf("step: one physics step with every stage; Save/Restore: a whole snapshot, in memory\n");
  return 0;
}
