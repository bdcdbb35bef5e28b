// turf._turf.SslSim: the SSL kernel for Python (ssl_sim.h).
#include <pybind11/stl.h>

#include "python/src/bind_kernel.h"
#include "python/src/bind_publish.h"
#include "python/src/bind_util.h"
#include "python/src/sim_error.h"
#include "python/src/ssl_sim.h"

namespace turf::py {

namespace {

using pyb::arg;

pyb::dict Observation(const SslSim& sim, pyb::handle self) {
  pyb::dict obs;
  obs["time"] = sim.kernel().time_ns() * 1e-9;
  obs["frame"] = sim.kernel().frame();
  obs["ball"] = View(sim.ball(), kBallColumns, self);
  obs["robots"] = View(sim.robots(), sim.robot_count(), kRobotColumns, self);
  obs["ball_detections"] = Copy(sim.ball_detections(), kBallDetectionColumns);
  obs["robot_detections"] = Copy(sim.robot_detections(), kRobotDetectionColumns);
  obs["camera_frames"] = Copy(sim.frames(), kFrameColumns);
  return obs;
}

// None; {"blue": rows, "yellow": rows} (either may be left out); or both teams as one 2 x robots x columns array.
std::vector<pyb::array_t<double>> TeamArrays(const SslSim& sim, const pyb::object& commands,
                                             std::vector<SslSim::TeamCommands>* out) {
  std::vector<pyb::array_t<double>> keep;
  const pyb::ssize_t rows = sim.robots_per_team();
  if (commands.is_none()) return keep;
  if (pyb::isinstance<pyb::dict>(commands)) {
    for (const auto& [key, value] : commands.cast<pyb::dict>()) {
      const Team team = TeamOf(pyb::reinterpret_borrow<pyb::object>(key));
      keep.push_back(Shaped(value, {rows, kCommandColumns}, std::string(TeamName(team)) + " commands"));
      out->push_back({team, keep.back().data()});
    }
    return keep;
  }
  keep.push_back(Shaped(commands, {kTeamCount, rows, kCommandColumns}, "commands"));
  out->push_back({Team::kBlue, keep.back().data()});
  out->push_back({Team::kYellow, keep.back().data() + rows * kCommandColumns});
  return keep;
}

RobotCommand MakeCommand(const pyb::object& team, int id, const std::string& frame, double vx, double vy, double omega,
                         const std::vector<double>& wheels, double kick_speed, bool chip, double chip_angle,
                         double dribbler) {
  RobotCommand c;
  c.team = TeamOf(team);
  c.id = id;
  if (frame == "local") {
    c.move = MoveKind::kLocalVelocity;
  } else if (frame == "global") {
    c.move = MoveKind::kGlobalVelocity;
  } else if (frame == "wheels") {
    c.move = MoveKind::kWheelVelocity;
    if (wheels.size() != 4) Check(Error::kMalformed, "wheels: 4 rim speeds");
    std::copy(wheels.begin(), wheels.end(), c.wheel_velocity.begin());
  } else if (frame == "none") {
    c.move = MoveKind::kNone;
  } else {
    Check(Error::kUnknownEnum, "frame '" + frame + "' (local, global, wheels or none)");
  }
  c.velocity = {vx, vy, omega};
  c.kick = kick_speed > 0.0 ? (chip ? KickKind::kChip : KickKind::kFlat) : KickKind::kNone;
  c.kick_speed = kick_speed;
  c.chip_angle = chip_angle;
  c.dribbler_speed = dribbler;
  return c;
}

pyb::dict FieldDict(const Scene& s) {
  pyb::dict d;
  d["length"] = s.field.length;
  d["width"] = s.field.width;
  d["goal_width"] = s.field.goal_width;
  d["boundary_width"] = s.field.boundary_width;
  d["boundary_width_goal_line"] = s.field.boundary_width_goal_line;
  d["ball_radius"] = s.ball.radius;
  d["robot_radius"] = s.robot.radius;
  d["max_speed"] = s.robot.drive.max_speed;
  d["max_angular_speed"] = s.robot.drive.max_angular_speed;
  d["max_flat_kick_speed"] = s.robot.kicker.max_flat_speed;
  return d;
}

}  // namespace

void BindSsl(pyb::module_& m) {
  pyb::class_<SslSim> cls(m, "SslSim", "An SSL world stepped in this process (see turf.Sim).");
  BindConstructor(cls, arg("scene") = "ssl_div_a");
  BindCheckCommands<SslSim, SslSim::TeamCommands>(cls, TeamArrays);
  BindKernelCommon(cls);
  cls.def(
         "step",
         [](pyb::object self, const pyb::object& commands, const pyb::object& steps) {
           SslSim& sim = self.cast<SslSim&>();
           const int64_t n = StepCountOf(steps);
           SslSim::StepScope stepping(sim);
           std::vector<SslSim::TeamCommands> teams;
           const std::vector<pyb::array_t<double>> keep = TeamArrays(sim, commands, &teams);
           {
             pyb::gil_scoped_release release;
             sim.Step(teams, n);
           }
           return Observation(sim, self);
         },
         arg("commands") = pyb::none(), arg("n") = 1)
      .def("observation",
           [](pyb::object self) {
             const SslSim& sim = self.cast<SslSim&>();
             sim.CheckIdle();
             return Observation(sim, self);
           })
      .def(
          "command",
          [](SslSim& sim, const pyb::object& team, int id, double vx, double vy, double omega, const std::string& frame,
             const std::vector<double>& wheels, double kick_speed, bool chip, double chip_angle, double dribbler) {
            sim.CheckIdle();
            sim.Command(MakeCommand(team, id, frame, vx, vy, omega, wheels, kick_speed, chip, chip_angle, dribbler));
          },
          arg("team"), arg("id"), arg("vx") = 0.0, arg("vy") = 0.0, arg("omega") = 0.0, arg("frame") = "local",
          arg("wheels") = std::vector<double>{}, arg("kick_speed") = 0.0, arg("chip") = false, arg("chip_angle") = 0.0,
          arg("dribbler") = 0.0)
      .def(
          "teleport_ball",
          [](pyb::object self, double x, double y, std::optional<double> z, double vx, double vy, double vz,
             bool roll) {
            SslSim& sim = self.cast<SslSim&>();
            sim.CheckIdle();
            BallTeleport t;
            t.position = {x, y, z.value_or(sim.kernel().scene().ball.radius)};
            t.velocity = {vx, vy, vz};
            t.roll = roll;
            sim.TeleportBall(t);
            return Observation(sim, self);
          },
          arg("x"), arg("y"), arg("z") = pyb::none(), arg("vx") = 0.0, arg("vy") = 0.0, arg("vz") = 0.0,
          arg("roll") = false)
      .def(
          "teleport_robot",
          [](pyb::object self, const pyb::object& team, int id, double x, double y, double orientation, double vx,
             double vy, double omega, bool on_field) {
            SslSim& sim = self.cast<SslSim&>();
            sim.CheckIdle();
            RobotTeleport t;
            t.team = TeamOf(team);
            t.id = id;
            t.on_field = on_field;
            t.x = x;
            t.y = y;
            t.orientation = orientation;
            t.velocity = {vx, vy, omega};
            sim.TeleportRobot(t);
            return Observation(sim, self);
          },
          arg("team"), arg("id"), arg("x") = 0.0, arg("y") = 0.0, arg("orientation") = 0.0, arg("vx") = 0.0,
          arg("vy") = 0.0, arg("omega") = 0.0, arg("on_field") = true)
      .def(
          "reset",
          [](pyb::object self, std::optional<uint64_t> seed) {
            SslSim& sim = self.cast<SslSim&>();
            sim.CheckIdle();
            sim.Reset(seed);
            return Observation(sim, self);
          },
          arg("seed") = pyb::none())
      .def(
          "restore",
          [](pyb::object self, const pyb::bytes& snapshot) {
            SslSim& sim = self.cast<SslSim&>();
            sim.CheckIdle();
            sim.Restore(snapshot);
            return Observation(sim, self);
          },
          arg("snapshot"))
      .def_property_readonly("kind", [](const SslSim&) { return "ssl"; })
      .def_property_readonly("robots_per_team", &SslSim::robots_per_team)
      .def_property_readonly("robot_count", &SslSim::robot_count)
      .def_property_readonly("robot_ids",
                             [](const SslSim& s) {
                               s.CheckIdle();
                               pyb::array_t<int32_t> a({s.robot_count(), 2}, s.robot_ids().data());
                               return a;
                             })
      .def_property_readonly("field", [](const SslSim& s) {
        s.CheckIdle();
        return FieldDict(s.kernel().scene());
      });
  BindPublish(cls);
  m.attr("SSL_COMMAND_COLUMNS") = pyb::make_tuple("vx", "vy", "omega", "kick_speed", "chip", "dribbler");
  m.attr("SSL_BALL_COLUMNS") = pyb::make_tuple("x", "y", "z", "vx", "vy", "vz");
  m.attr("SSL_ROBOT_COLUMNS") =
      pyb::make_tuple("x", "y", "yaw", "vx", "vy", "omega", "on_field", "ball_contact", "kick_count");
  m.attr("SSL_BALL_DETECTION_COLUMNS") =
      pyb::make_tuple("camera", "frame", "capture_time", "x", "y", "z", "confidence");
  m.attr("SSL_ROBOT_DETECTION_COLUMNS") =
      pyb::make_tuple("camera", "frame", "capture_time", "team", "id", "x", "y", "orientation", "confidence");
  m.attr("SSL_CAMERA_FRAME_COLUMNS") = pyb::make_tuple("camera", "frame", "capture_time", "sent_time");
}

}  // namespace turf::py
