// Camera rendering speed (issue 16): frames per second of MuJoCo's offscreen renderer through EGL (Mesa llvmpipe
// on a machine without a GPU), for 1, 4 and 10 cameras at 320x240 and 640x480, each frame rendered, read back
// and encoded as turf-render does it, in one thread (llvmpipe spreads rasterisation over its own threads:
// LP_NUM_THREADS, default one per core). No DDS: the frames are dropped after encoding.
// Scene: a legged scene file (default simspark_match.yaml: 22 Naos at the touch line, the 3D field with lines),
// its robots' cameras in scene order, each at the size under test.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

#include "codecs/image/image_codec.h"
#include "core/legged/legged_cameras.h"
#include "core/legged/legged_mjcf.h"
#include "core/mj_state.h"
#include "loader/legged_scene_yaml.h"
#include "participants/render/egl_context.h"
#include "participants/render/scene_renderer.h"

namespace {

using Clock = std::chrono::steady_clock;

struct Row {
  int cameras;
  int width;
  int height;
};

double Measure(const turf::LeggedScene& scene, std::vector<turf::CameraSpec> cameras, int rounds,
               turf::ImageEncoding encoding) {
  for (turf::CameraSpec& c : cameras) c.encoding = encoding;
  turf::SceneRenderer renderer(scene, cameras);
  renderer.UpdateFrames();
  std::vector<uint8_t> rgb;
  auto one_round = [&] {
    for (size_t i = 0; i < cameras.size(); ++i) {
      renderer.Render(i, &rgb);
      const turf::CameraSpec& c = cameras[i];
      if (encoding == turf::ImageEncoding::kYuv422) turf::image::RgbToYuyv(rgb, c.width, c.height);
      if (encoding == turf::ImageEncoding::kJpeg) turf::image::EncodeJpeg(rgb, c.width, c.height, c.jpeg_quality);
    }
  };
  one_round();  // warm-up: shaders, buffers
  const auto start = Clock::now();
  for (int r = 0; r < rounds; ++r) one_round();
  const double s = std::chrono::duration<double>(Clock::now() - start).count();
  return static_cast<double>(rounds) * static_cast<double>(cameras.size()) / s;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app("turf-bench-render: offscreen camera rendering speed (frames per second, all cameras together)");
  std::string scene_file = std::string(TURF_SOURCE_DIR) + "/configs/scenes/simspark_match.yaml";
  double seconds = 3.0;
  app.add_option("--scene", scene_file, "legged scene whose robots' cameras are rendered")->capture_default_str();
  app.add_option("--seconds", seconds, "about this long per row")->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  turf::LeggedSceneLoadResult loaded = turf::LoadLeggedSceneFile(scene_file);
  if (!loaded.scene) {
    std::fprintf(stderr, "%s\n", loaded.errors.front().c_str());
    return 2;
  }
  const turf::LeggedMjcf mjcf = turf::ComposeLeggedMjcf(*loaded.scene);
  turf::MjModelPtr model(turf::CompileLeggedMjcf(mjcf.xml));
  const turf::LeggedCameras all = turf::ResolveLeggedCameras(*loaded.scene, model.get());
  turf::EglContext egl;
  std::printf("renderer: %s; scene %s (%zu cameras)\n", egl.Renderer().c_str(), scene_file.c_str(), all.cameras.size());
  std::printf(
      "| cameras | size | rgb8 frames/s | yuv422 frames/s | jpeg frames/s |\n| --- | --- | --- | --- | --- |\n");
  for (const Row& row :
       {Row{1, 320, 240}, Row{4, 320, 240}, Row{10, 320, 240}, Row{1, 640, 480}, Row{4, 640, 480}, Row{10, 640, 480}}) {
    if (static_cast<size_t>(row.cameras) > all.cameras.size()) continue;
    std::vector<turf::CameraSpec> cams(all.cameras.begin(), all.cameras.begin() + row.cameras);
    for (turf::CameraSpec& c : cams) {
      c.width = row.width;
      c.height = row.height;
    }
    // Rounds for about `seconds` at a first guess of 100 frames/s at 320x240.
    const double guess = 100.0 * (320.0 * 240.0) / (row.width * row.height);
    const int rounds = std::max(3, static_cast<int>(seconds * guess / row.cameras));
    const double rgb = Measure(*loaded.scene, cams, rounds, turf::ImageEncoding::kRgb8);
    const double yuv = Measure(*loaded.scene, cams, rounds, turf::ImageEncoding::kYuv422);
    const double jpeg = Measure(*loaded.scene, cams, rounds, turf::ImageEncoding::kJpeg);
    std::printf("| %d | %dx%d | %.0f | %.0f | %.0f |\n", row.cameras, row.width, row.height, rgb, yuv, jpeg);
    std::fflush(stdout);
  }
  return 0;
}
