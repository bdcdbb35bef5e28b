#include "core/legged/legged_scene.h"

#include <fmt/format.h>

#include <cmath>
#include <set>

#include "core/legged/legged_world.h"
#include "core/legged/placement_limits.h"

namespace turf {

namespace {

bool Positive(double v) { return std::isfinite(v) && v > 0.0; }
bool NonNegative(double v) { return std::isfinite(v) && v >= 0.0; }
bool Within(double v, double lo, double hi) { return std::isfinite(v) && v >= lo && v <= hi; }

// Upper bounds of a scene's numbers: past them MuJoCo's first steps are NaN (a ball of 1e300 kg, friction 1e300, air
// of 1e12 kg/m^3, a robot at 1e20 m), whatever the scene meant.
constexpr double kMaxFieldSize = 1000.0;    // m: every size of the field
constexpr double kMaxBallRadius = 1.0;      // m
constexpr double kMaxBallMass = 100.0;      // kg
constexpr double kMaxFriction = 100.0;      // MuJoCo's sliding friction coefficient
constexpr double kMaxFluidDensity = 1e4;    // kg/m^3 (water: 1000)
constexpr double kMaxFluidViscosity = 1e3;  // Pa s (water: 0.001)
constexpr double kMinLeggedStep = 1e-4;     // s: a smaller step is 0 ns of simulated time, or near it

}  // namespace

std::vector<std::string> ValidateLeggedScene(const LeggedScene& s) {
  std::vector<std::string> e;
  if (!Within(s.physics.step, kMinLeggedStep, 0.02)) e.push_back("physics.step must be in [0.0001, 0.02] s");
  if (!Within(s.physics.fluid_density, 0.0, kMaxFluidDensity) ||
      !Within(s.physics.fluid_viscosity, 0.0, kMaxFluidViscosity))
    e.push_back(fmt::format("physics: fluid_density must be in [0, {}] kg/m^3, fluid_viscosity in [0, {}] Pa s",
                            kMaxFluidDensity, kMaxFluidViscosity));
  if (s.physics.solver_iterations < 1 || s.physics.solver_iterations > 1000)
    e.push_back("physics.solver_iterations must be 1..1000");
  if (s.physics.island_threads < 1 || s.physics.island_threads > 8) e.push_back("physics.island_threads must be 1..8");
  if (s.physics.island_threads > 1 && (s.contacts.enabled || s.joint_stops.enabled))
    e.push_back(
        "physics.island_threads > 1 needs MuJoCo's own contacts and joint limits (no contacts, no joint_stops)");
  if (!(s.physics.motor_impulse_window >= 0.0 && s.physics.motor_impulse_window <= 1.0))
    e.push_back("physics.motor_impulse_window must be in [0, 1] s");
  if (!NonNegative(s.physics.body_linear_drag) || !NonNegative(s.physics.body_angular_drag))
    e.push_back("physics.body_drag must be finite and not negative");
  if (!Positive(s.rates.joint_state_hz) || s.rates.joint_state_hz * s.physics.step > 1.0)
    e.push_back("rates.joint_state_hz must be positive and at most 1/physics.step");
  if (!Positive(s.ground_friction) || s.ground_friction > kMaxFriction)
    e.push_back(fmt::format("ground_friction must be in (0, {}]", kMaxFriction));
  if (s.contacts.enabled) {
    const OdeContactLaw& c = s.contacts;
    if (!Positive(c.reference_step) || !NonNegative(c.surface_layer) || !Positive(c.world_erp) || c.world_erp > 1 ||
        !Positive(c.world_cfm))
      e.push_back("contacts: reference_step and world_cfm positive, surface_layer >= 0, world_erp in (0, 1]");
    for (const OdeSurface* surface : {&c.robot, &c.ground, &c.ball}) {
      // Negative = not set; a set ERP is in (0, 1], a set CFM positive.
      if (!std::isfinite(surface->erp) || !std::isfinite(surface->cfm) || !std::isfinite(surface->slip) ||
          surface->erp == 0 || surface->erp > 1 || surface->cfm == 0 || !std::isfinite(surface->bounce) ||
          surface->bounce > 1 || !std::isfinite(surface->bounce_vel))
        e.push_back(
            "contacts: a surface's erp must be in (0, 1], cfm positive, slip >= 0, bounce in [0, 1], "
            "bounce_vel >= 0 (or left out)");
    }
  }
  if (s.joint_stops.enabled) {
    const OdeJointStops& j = s.joint_stops;
    if (!Positive(j.step) || j.step > 1.0 || !Positive(j.erp) || j.erp > 1 || !NonNegative(j.bounce) || j.bounce > 1 ||
        !NonNegative(j.fudge) || j.fudge > 1)
      e.push_back("joint_stops: step in (0, 1] s, erp in (0, 1], bounce and fudge in [0, 1]");
  }
  if (s.field.enabled) {
    const Field3d& f = s.field;
    for (double v : {f.length, f.width, f.goal_width, f.goal_depth, f.goal_height, f.goal_wall, f.wall_distance}) {
      if (!Positive(v) || v > kMaxFieldSize)
        e.push_back(fmt::format("field: every size must be in (0, {}] m", kMaxFieldSize));
    }
    if (!Positive(f.ball_radius) || f.ball_radius > kMaxBallRadius || !Positive(f.ball_mass) ||
        f.ball_mass > kMaxBallMass)
      e.push_back(fmt::format("field: ball_radius must be in (0, {}] m, ball_mass in (0, {}] kg", kMaxBallRadius,
                              kMaxBallMass));
    if (!(Within(f.ball_x, -kMaxLeggedPlacement, kMaxLeggedPlacement) &&
          Within(f.ball_y, -kMaxLeggedPlacement, kMaxLeggedPlacement)))
      e.push_back(fmt::format("field: ball start must be within {} m of the origin", kMaxLeggedPlacement));
    for (double v :
         {f.ball_friction[0], f.ball_friction[1], f.ball_friction[2], f.ball_linear_drag, f.ball_angular_drag})
      if (!Within(v, 0.0, kMaxFriction))
        e.push_back(fmt::format("field: the ball's friction and drag must be in [0, {}]", kMaxFriction));
    if (f.ball_priority < 0) e.push_back("field: ball_priority must not be negative");
    if (f.ball_condim != 1 && f.ball_condim != 3 && f.ball_condim != 4 && f.ball_condim != 6)
      e.push_back("field: ball_condim must be 1, 3, 4 or 6");
    const bool time_constant = Positive(f.ball_solref[0]) && Positive(f.ball_solref[1]);
    const bool direct = f.ball_solref[0] < 0 && f.ball_solref[1] <= 0 && std::isfinite(f.ball_solref[0]) &&
                        std::isfinite(f.ball_solref[1]);
    if (!time_constant && !direct)
      e.push_back(
          "field: ball_solref must be a positive time constant and damping ratio, or negative stiffness "
          "and damping");
  }
  if (s.robots.empty()) e.push_back("robots: at least one robot");
  if (s.robots.size() > kMaxLeggedRobots)
    e.push_back(fmt::format("robots: at most {} (there are {})", kMaxLeggedRobots, s.robots.size()));
  std::set<std::string> names;
  for (const LeggedRobot& r : s.robots) {
    const std::string where = fmt::format("robots.{}", r.name);
    if (r.name.empty() || r.name.find_first_of("/ \t\"<>&") != std::string::npos)
      e.push_back(fmt::format("{}: name must be non-empty without '/', spaces or XML characters", where));
    if (!names.insert(r.name).second) e.push_back(fmt::format("{}: duplicate name", where));
    if (r.model_xml.empty()) e.push_back(fmt::format("{}: no model", where));
    if (!(Within(r.x, -kMaxLeggedPlacement, kMaxLeggedPlacement) &&
          Within(r.y, -kMaxLeggedPlacement, kMaxLeggedPlacement) && std::isfinite(r.yaw)))
      e.push_back(
          fmt::format("{}: pose must be finite, x and y within {} m of the origin", where, kMaxLeggedPlacement));
    if (r.z && !(std::isfinite(*r.z) && *r.z >= 0.0 && *r.z <= 10.0))
      e.push_back(fmt::format("{}: z must be in [0, 10] m", where));
    std::set<std::string> joints;
    for (const JointStart& j : r.start_joints) {
      if (!joints.insert(j.joint).second) e.push_back(fmt::format("{}.joints.{}: duplicate joint", where, j.joint));
      if (!std::isfinite(j.position)) e.push_back(fmt::format("{}.joints.{}: q must be finite", where, j.joint));
      if (!NonNegative(j.kp) || !NonNegative(j.kd) || j.kp > kMaxPdKp || j.kd > kMaxPdKd)
        e.push_back(fmt::format("{}.joints.{}: kp and kd must be finite and non-negative, kp at most {}, kd at most {}",
                                where, j.joint, kMaxPdKp, kMaxPdKd));
    }
    const MotorParams& m = r.motors;
    if (!Positive(m.max_torque) || !Positive(m.max_speed) || !NonNegative(m.velocity_kp) ||
        !NonNegative(m.velocity_kd) || !NonNegative(m.position_kp) || !NonNegative(m.position_kd) ||
        !NonNegative(m.max_reference_lead))
      e.push_back(fmt::format("{}: motor limits must be positive and gains non-negative", where));
    if (m.velocity_kp > kMaxPdKp || m.position_kp > kMaxPdKp || m.velocity_kd > kMaxPdKd || m.position_kd > kMaxPdKd)
      e.push_back(fmt::format("{}: motor kp gains must be at most {}, kd gains at most {}", where, kMaxPdKp, kMaxPdKd));
  }
  return e;
}

}  // namespace turf
