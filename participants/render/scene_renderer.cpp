#include "participants/render/scene_renderer.h"

#include <mujoco/mujoco.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <unordered_map>

#include "core/legged/legged_mjcf.h"
#include "core/mj_state.h"
#include "participants/render/field_look.h"
#include "participants/render/team_colours.h"

namespace turf {

namespace {

constexpr float kNear = 0.02f;  // m: the clip planes of every camera
constexpr float kFar = 250.0f;

// Builtin shapes (spheres, capsules, cylinders) with fewer facets than MuJoCo's default 28 x 16: software
// rasterisation pays per vertex, and a 320 x 240 image shows no difference.
constexpr int kSlices = 16;
constexpr int kStacks = 8;

float Dot(const float a[3], const std::array<double, 3>& b) {
  return a[0] * static_cast<float>(b[0]) + a[1] * static_cast<float>(b[1]) + a[2] * static_cast<float>(b[2]);
}

// Removes from the scene the geoms whose bounding sphere lies wholly outside the camera's view (behind it, beyond
// its far plane, or past one of its four sides): with 22 robots most of a scene is out of any one camera's view, and
// software rendering would transform every vertex of it. Planes and geoms without a model bound stay.
void CullOutsideFrustum(mjvScene* scn, const Pose& camera, double hfov, double vfov) {
  const auto forward = CameraForward(camera);
  const auto up = CameraUp(camera);
  const std::array<double, 3> right{forward[1] * up[2] - forward[2] * up[1], forward[2] * up[0] - forward[0] * up[2],
                                    forward[0] * up[1] - forward[1] * up[0]};
  const float sx = static_cast<float>(std::sin(0.5 * hfov)), cx = static_cast<float>(std::cos(0.5 * hfov));
  const float sy = static_cast<float>(std::sin(0.5 * vfov)), cy = static_cast<float>(std::cos(0.5 * vfov));
  int kept = 0;
  for (int i = 0; i < scn->ngeom; ++i) {
    const mjvGeom& g = scn->geoms[i];
    bool visible = g.type == mjGEOM_PLANE || g.modelrbound <= 0;
    if (!visible) {
      const float p[3] = {g.pos[0] - static_cast<float>(camera.position[0]),
                          g.pos[1] - static_cast<float>(camera.position[1]),
                          g.pos[2] - static_cast<float>(camera.position[2])};
      const float d = Dot(p, forward), x = Dot(p, right), y = Dot(p, up), r = g.modelrbound;
      visible = d > kNear - r && d < kFar + r && d * sx - x * cx > -r && d * sx + x * cx > -r && d * sy - y * cy > -r &&
                d * sy + y * cy > -r;
    }
    if (visible) scn->geoms[kept++] = g;
  }
  scn->ngeom = kept;
}

}  // namespace

struct SceneRenderer::Impl {
  MjModelPtr model;
  MjDataPtr data;
  mjvScene scene;
  mjvOption option;
  mjvCamera free_camera;
  mjrContext context;
  std::unordered_map<std::string, int> bodies;  // composed name -> body id
  std::vector<int> mounts;                      // per camera: its body
  int ball = -1;

  ~Impl() {
    mjr_freeContext(&context);
    mjv_freeScene(&scene);
  }
};

namespace {

// Each team robot's top-level body's geoms in its team's colour (their materials set aside).
void WearTeamColours(mjModel* m, const LeggedScene& scene) {
  for (const LeggedRobot& r : scene.robots) {
    const auto rgba = TeamColour(r.name);
    if (!rgba) continue;
    const std::string prefix = LeggedElementName(r.name, "");
    for (int g = 0; g < m->ngeom; ++g) {
      const int b = m->geom_bodyid[g];
      const char* body = mj_id2name(m, mjOBJ_BODY, b);
      if (m->body_parentid[b] != 0 || body == nullptr || std::string(body).rfind(prefix, 0) != 0) continue;
      m->geom_matid[g] = -1;
      for (int k = 0; k < 4; ++k) m->geom_rgba[4 * g + k] = (*rgba)[k];
    }
  }
}

// Every light, and the headlight, `scale` times as bright.
void ScaleLights(mjModel* m, double scale) {
  const float s = static_cast<float>(scale);
  for (int i = 0; i < 3 * m->nlight; ++i) {
    m->light_diffuse[i] *= s;
    m->light_ambient[i] *= s;
    m->light_specular[i] *= s;
  }
  for (int k = 0; k < 3; ++k) {
    m->vis.headlight.diffuse[k] *= s;
    m->vis.headlight.ambient[k] *= s;
    m->vis.headlight.specular[k] *= s;
  }
}

}  // namespace

SceneRenderer::SceneRenderer(const LeggedScene& scene, std::vector<CameraSpec> cameras, const RenderLook& look)
    : cameras_(std::move(cameras)), impl_(std::make_unique<Impl>()) {
  mjv_defaultScene(&impl_->scene);
  mjr_defaultContext(&impl_->context);
  const LeggedMjcf mjcf = ComposeLeggedMjcf(scene);
  if (!mjcf.errors.empty()) throw std::invalid_argument(mjcf.errors.front());
  impl_->model.reset(CompileLeggedMjcf(AddFieldLook(mjcf.xml, scene.field)));
  mjModel* m = impl_->model.get();
  if (look.team_colours) WearTeamColours(m, scene);
  ScaleLights(m, look.brightness);
  impl_->data.reset(mj_makeData(m));
  mj_kinematics(m, impl_->data.get());  // the start pose, for bodies no state moves
  for (int b = 0; b < m->nbody; ++b) {
    const char* name = mj_id2name(m, mjOBJ_BODY, b);
    if (name != nullptr) impl_->bodies.emplace(name, b);
  }
  impl_->ball = mj_name2id(m, mjOBJ_BODY, kLeggedBall);
  int width = 1, height = 1;
  for (const CameraSpec& c : cameras_) {
    auto it = impl_->bodies.find(LeggedElementName(c.robot, c.body));
    if (it == impl_->bodies.end())
      throw std::invalid_argument("camera " + CameraId(c) + ": no body " + c.body + " on robot " + c.robot);
    impl_->mounts.push_back(it->second);
    width = std::max(width, c.width);
    height = std::max(height, c.height);
  }
  // The offscreen buffer holds the largest camera; no multisampling and no shadows (software rendering's cost).
  m->vis.global.offwidth = width;
  m->vis.global.offheight = height;
  m->vis.quality.offsamples = 0;
  m->vis.quality.numslices = kSlices;
  m->vis.quality.numstacks = kStacks;
  mjv_defaultOption(&impl_->option);
  for (int g = 0; g < mjNGROUP; ++g) impl_->option.sitegroup[g] = 0;  // sites are markers, not things a camera sees
  impl_->option.flags[mjVIS_TENDON] = 0;
  mjv_defaultCamera(&impl_->free_camera);
  mjv_makeScene(m, &impl_->scene, 2000);
  impl_->scene.flags[mjRND_SHADOW] = 0;
  impl_->scene.flags[mjRND_REFLECTION] = 0;
  mjr_makeContext(m, &impl_->context, mjFONTSCALE_50);
  mjr_setBuffer(mjFB_OFFSCREEN, &impl_->context);
  if (impl_->context.currentBuffer != mjFB_OFFSCREEN)
    throw std::runtime_error("MuJoCo's renderer has no offscreen buffer in this OpenGL context");
}

SceneRenderer::~SceneRenderer() = default;

bool SceneRenderer::SetBodyPose(const std::string& robot, const std::string& body, const Pose& pose) {
  auto it = impl_->bodies.find(LeggedElementName(robot, body));
  if (it == impl_->bodies.end()) return false;
  mjData* d = impl_->data.get();
  const int b = it->second;
  mjtNum q[4] = {pose.orientation[0], pose.orientation[1], pose.orientation[2], pose.orientation[3]};
  if (mju_normalize4(q) < mjMINVAL) return false;
  for (int i = 0; i < 3; ++i) d->xpos[3 * b + i] = pose.position[i];
  mju_copy4(d->xquat + 4 * b, q);
  mju_quat2Mat(d->xmat + 9 * b, q);
  return true;
}

bool SceneRenderer::SetBallPosition(const std::array<double, 3>& position) {
  if (impl_->ball < 0) return false;
  for (int i = 0; i < 3; ++i) impl_->data->xpos[3 * impl_->ball + i] = position[i];
  return true;
}

void SceneRenderer::UpdateFrames() {
  const mjModel* m = impl_->model.get();
  mjData* d = impl_->data.get();
  for (int b = 1; b < m->nbody; ++b)  // inertial frames: geoms that share them are placed from them
    mj_local2Global(d, d->xipos + 3 * b, d->ximat + 9 * b, m->body_ipos + 3 * b, m->body_iquat + 4 * b, b, 0);
  for (int g = 0; g < m->ngeom; ++g) {
    const int b = m->geom_bodyid[g];
    mj_local2Global(d, d->geom_xpos + 3 * g, d->geom_xmat + 9 * g, m->geom_pos + 3 * g, m->geom_quat + 4 * g, b,
                    m->geom_sameframe[g]);
  }
  for (int l = 0; l < m->nlight; ++l) {
    const int b = m->light_bodyid[l];
    mju_mulMatVec(d->light_xdir + 3 * l, d->xmat + 9 * b, m->light_dir + 3 * l, 3, 3);
    mju_mulMatVec(d->light_xpos + 3 * l, d->xmat + 9 * b, m->light_pos + 3 * l, 3, 3);
    mju_addTo3(d->light_xpos + 3 * l, d->xpos + 3 * b);
  }
}

Pose SceneRenderer::CameraPose(size_t camera) const {
  const mjData* d = impl_->data.get();
  const int b = impl_->mounts.at(camera);
  Pose body;
  for (int i = 0; i < 3; ++i) body.position[i] = d->xpos[3 * b + i];
  for (int i = 0; i < 4; ++i) body.orientation[i] = d->xquat[4 * b + i];
  return CameraWorldPose(body, cameras_.at(camera));
}

void SceneRenderer::Render(size_t camera, std::vector<uint8_t>* rgb) {
  const CameraSpec& spec = cameras_.at(camera);
  const Pose pose = CameraPose(camera);
  const auto forward = CameraForward(pose);
  const auto up = CameraUp(pose);
  mjvScene& scn = impl_->scene;
  mjv_updateScene(impl_->model.get(), impl_->data.get(), &impl_->option, nullptr, &impl_->free_camera, mjCAT_ALL, &scn);
  CullOutsideFrustum(&scn, pose, spec.hfov, VerticalFov(spec.width, spec.height, spec.hfov));
  const float half_height = kNear * static_cast<float>(std::tan(0.5 * VerticalFov(spec.width, spec.height, spec.hfov)));
  for (mjvGLCamera& gl : scn.camera) {
    for (int i = 0; i < 3; ++i) {
      gl.pos[i] = static_cast<float>(pose.position[i]);
      gl.forward[i] = static_cast<float>(forward[i]);
      gl.up[i] = static_cast<float>(up[i]);
    }
    gl.frustum_center = 0;
    gl.frustum_bottom = -half_height;
    gl.frustum_top = half_height;
    gl.frustum_near = kNear;
    gl.frustum_far = kFar;
  }
  const mjrRect viewport{0, 0, spec.width, spec.height};
  mjr_render(viewport, &scn, &impl_->context);
  const size_t row = static_cast<size_t>(spec.width) * 3;
  rgb->resize(row * static_cast<size_t>(spec.height));
  mjr_readPixels(rgb->data(), nullptr, viewport, &impl_->context);
  // OpenGL's rows are bottom-up.
  std::vector<uint8_t> swap(row);
  for (int top = 0, bottom = spec.height - 1; top < bottom; ++top, --bottom) {
    uint8_t* a = rgb->data() + static_cast<size_t>(top) * row;
    uint8_t* b = rgb->data() + static_cast<size_t>(bottom) * row;
    std::memcpy(swap.data(), a, row);
    std::memcpy(a, b, row);
    std::memcpy(b, swap.data(), row);
  }
}

}  // namespace turf
