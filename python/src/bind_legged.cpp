// turf._turf.LeggedSim: the legged kernel for Python (legged_sim.h).
#include <pybind11/stl.h>

#include "python/src/bind_kernel.h"
#include "python/src/bind_publish.h"
#include "python/src/bind_util.h"
#include "python/src/legged_sim.h"
#include "python/src/sim_error.h"

namespace turf::py {

namespace {

using pyb::arg;

pyb::array_t<double> Array(const std::vector<double>& v) { return Copy(v.data(), static_cast<pyb::ssize_t>(v.size())); }
template <size_t N>
pyb::array_t<double> Array(const std::array<double, N>& v) {
  return Copy(v.data(), static_cast<pyb::ssize_t>(N));
}

// One robot's readings: joints, IMU, base pose and velocity, every force sensor's values with its contact flag, and
// its last touch of the ball.
pyb::dict RobotDict(const LeggedRobotState& r) {
  pyb::dict d;
  d["name"] = r.name;
  d["joint_position"] = Array(r.joint_positions);
  d["joint_velocity"] = Array(r.joint_velocities);
  d["joint_effort"] = Array(r.joint_efforts);
  d["orientation"] = Array(r.orientation);
  d["gyro"] = Array(r.gyro);
  d["accelerometer"] = Array(r.accelerometer);
  d["base_position"] = Array(r.base_position);
  d["base_orientation"] = Array(r.base_orientation);
  d["base_velocity"] = Array(r.base_velocity);
  std::vector<double> force, contact;
  for (const ForceReading& f : r.forces) {
    force.insert(force.end(), f.values.begin(), f.values.end());
    contact.push_back(f.contact ? 1.0 : 0.0);
  }
  d["force"] = Array(force);
  d["contact"] = Array(contact);
  // When a body of the robot last touched the ball (the end of that physics step, s; -1: never), one element.
  d["ball_touch_time"] = Array(std::array<double, 1>{r.ball_touch_ns < 0 ? -1.0 : r.ball_touch_ns * 1e-9});
  return d;
}

pyb::dict Observation(const LeggedSim& sim) {
  pyb::dict obs;
  obs["time"] = sim.kernel().time_ns() * 1e-9;
  obs["frame"] = sim.kernel().frame();
  pyb::list robots, truth;
  for (const LeggedRobotState& r : sim.measured().robots) robots.append(RobotDict(r));
  for (const LeggedRobotState& r : sim.truth().robots) truth.append(RobotDict(r));
  obs["robots"] = robots;
  obs["truth"] = truth;
  const LeggedWorldState& t = sim.truth();
  if (t.has_ball) {
    std::vector<double> ball(t.ball_position.begin(), t.ball_position.end());
    ball.insert(ball.end(), t.ball_velocity.begin(), t.ball_velocity.end());
    obs["ball"] = Array(ball);
  }
  return obs;
}

int RobotOf(const LeggedSim& sim, const pyb::handle& robot) {
  if (pyb::isinstance<pyb::str>(robot)) return sim.RobotIndex(robot.cast<std::string>());
  if (pyb::isinstance<pyb::int_>(robot)) return IntOr(robot, -1);
  Check(Error::kUnknownRobot, "robot " + pyb::repr(robot).cast<std::string>() + " (a name or an index)");
  return -1;
}

// None, or a dict of robot (name or index) -> joints x 5 rows; `out` points into the arrays returned.
std::vector<pyb::array_t<double>> RobotArrays(const LeggedSim& sim, const pyb::object& commands,
                                              std::vector<LeggedSim::RobotCommands>* out) {
  std::vector<pyb::array_t<double>> keep;
  if (commands.is_none()) return keep;
  if (!pyb::isinstance<pyb::dict>(commands))
    Check(Error::kMalformed, "commands: a dict of robot (name or index) -> joints x 5 array");
  for (const auto& [key, value] : commands.cast<pyb::dict>()) {
    const int robot = RobotOf(sim, key);
    const auto joints = static_cast<pyb::ssize_t>(sim.joint_names(robot).size());
    keep.push_back(Shaped(value, {joints, kJointColumns}, "commands of robot " + std::to_string(robot)));
    out->push_back({robot, keep.back().data()});
  }
  return keep;
}

JointMode ModeOf(const std::string& mode) {
  const char* names[] = {"velocity", "position", "torque", "pd"};
  for (int i = 0; i < kJointModeCount; ++i)
    if (mode == names[i]) return static_cast<JointMode>(i);
  Check(Error::kUnknownEnum, "joint mode '" + mode + "' (velocity, position, torque or pd)");
  return JointMode::kVelocity;
}

}  // namespace

void BindLegged(pyb::module_& m) {
  pyb::class_<LeggedSim> cls(m, "LeggedSim", "A legged world stepped in this process (see turf.Sim).");
  BindConstructor(cls, arg("scene"));
  BindCheckCommands<LeggedSim, LeggedSim::RobotCommands>(cls, RobotArrays);
  BindKernelCommon(cls);
  cls.def(
         "step",
         [](LeggedSim& sim, const pyb::object& commands, const pyb::object& steps) {
           const int64_t n = StepCountOf(steps);
           LeggedSim::StepScope stepping(sim);
           std::vector<LeggedSim::RobotCommands> robots;
           const std::vector<pyb::array_t<double>> keep = RobotArrays(sim, commands, &robots);
           {
             pyb::gil_scoped_release release;
             sim.Step(robots, n);
           }
           return Observation(sim);
         },
         arg("commands") = pyb::none(), arg("n") = 1)
      .def("observation",
           [](const LeggedSim& sim) {
             sim.CheckIdle();
             return Observation(sim);
           })
      .def(
          "joint_command",
          [](LeggedSim& sim, const pyb::object& robot, const std::string& joint, const std::string& mode, double value,
             double kp, double kd, double dq, double tau) {
            sim.CheckIdle();
            sim.SetJointCommand(RobotOf(sim, robot), {joint, ModeOf(mode), value, kp, kd, dq, tau});
          },
          arg("robot"), arg("joint"), arg("mode") = "pd", arg("value") = 0.0, arg("kp") = -1.0, arg("kd") = -1.0,
          arg("dq") = 0.0, arg("tau") = 0.0)
      .def(
          "teleport_robot",
          [](LeggedSim& sim, const pyb::object& robot, std::array<double, 3> position,
             std::array<double, 4> orientation, bool reset_joints) {
            sim.CheckIdle();
            RobotPlacement p;
            p.position = position;
            p.orientation = orientation;
            p.reset_joints = reset_joints;
            sim.PlaceRobot(RobotOf(sim, robot), p);
            return Observation(sim);
          },
          arg("robot"), arg("position"), arg("orientation") = std::array<double, 4>{1, 0, 0, 0},
          arg("reset_joints") = false)
      .def(
          "teleport_ball",
          [](LeggedSim& sim, std::array<double, 3> position, std::array<double, 3> velocity) {
            sim.CheckIdle();
            sim.PlaceBall(position, velocity);
            return Observation(sim);
          },
          arg("position"), arg("velocity") = std::array<double, 3>{0, 0, 0})
      .def(
          "reset",
          [](LeggedSim& sim, std::optional<uint64_t> seed) {
            sim.CheckIdle();
            sim.Reset(seed);
            return Observation(sim);
          },
          arg("seed") = pyb::none())
      .def(
          "restore",
          [](LeggedSim& sim, const pyb::bytes& snapshot) {
            sim.CheckIdle();
            sim.Restore(snapshot);
            return Observation(sim);
          },
          arg("snapshot"))
      .def("joint_names", &LeggedSim::joint_names, arg("robot"))
      .def("joint_limits",
           [](const LeggedSim& sim, int robot) {
             sim.CheckIdle();
             std::vector<double> rows;
             for (size_t j = 0; j < sim.joint_names(robot).size(); ++j) {
               const LeggedJointInfo info = sim.kernel().world().JointInfo(robot, static_cast<int>(j));
               rows.insert(rows.end(),
                           {info.limited ? info.lo : -INFINITY, info.limited ? info.hi : INFINITY, info.effort_limit});
             }
             return Copy(rows, 3);
           })
      .def(
          "start_joints",
          [](const LeggedSim& sim, int robot) {
            sim.CheckIdle();
            // q, kp, kd per joint as the scene starts it (NaN for a joint the scene does not name).
            const std::vector<std::string>& names = sim.joint_names(robot);
            std::vector<double> rows(names.size() * 3, NAN);
            for (const JointStart& j : sim.kernel().scene().robots[robot].start_joints) {
              for (size_t i = 0; i < names.size(); ++i) {
                if (names[i] != j.joint) continue;
                rows[i * 3] = j.position;
                rows[i * 3 + 1] = j.kp;
                rows[i * 3 + 2] = j.kd;
              }
            }
            return Copy(rows, 3);
          },
          arg("robot"))
      .def_property_readonly("kind", [](const LeggedSim&) { return "legged"; })
      .def_property_readonly("robot_count", &LeggedSim::robot_count)
      .def_property_readonly("robot_names", [](const LeggedSim& s) {
        s.CheckIdle();
        std::vector<std::string> names;
        for (const LeggedRobot& r : s.kernel().scene().robots) names.push_back(r.name);
        return names;
      });
  BindPublish(cls);
  m.attr("LEGGED_JOINT_COLUMNS") = pyb::make_tuple("q", "dq", "kp", "kd", "tau");
}

}  // namespace turf::py
