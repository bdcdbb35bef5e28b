#include "participants/sim/legged_publisher.h"

#include "participants/sim/legged_convert.h"
#include "participants/sim/stats_report.h"

namespace turf {

LeggedPublisher::LeggedPublisher(dds::Bus& bus)
    : joint_writer_(bus.MakeWriter(dds::Topic::kRobotJointState)),
      imu_writer_(bus.MakeWriter(dds::Topic::kRobotImu)),
      force_writer_(bus.MakeWriter(dds::Topic::kRobotForce)),
      links_writer_(bus.MakeWriter(dds::Topic::kRobotLinks)),
      state_writer_(bus.MakeWriter(dds::Topic::kRobotsState)),
      world_writer_(bus.MakeWriter(dds::Topic::kWorldState)),
      scene_writer_(bus.MakeWriter(dds::Topic::kLeggedScene)),
      stats_writer_(bus.MakeWriter(dds::Topic::kStats)) {}

void LeggedPublisher::AfterStep(const LeggedKernel& kernel) {
  PublishReleased(kernel);
  if (kernel.stats()) {
    stats_writer_->Write(StatsToIdl(*kernel.stats()));
    last_stats_ = *kernel.stats();
  }
}

// The sensor streams' samples that arrived (their modelled links).
void LeggedPublisher::PublishReleased(const LeggedKernel& kernel) {
  for (const LeggedSample& s : kernel.released()) {
    switch (s.stream) {
      case LeggedStream::kJoints:
        FillJoints(s.robot_state, s.time_ns, s.frame, &joint_sample_);
        joint_writer_->Write(joint_sample_);
        break;
      case LeggedStream::kImu:
        FillImu(s.robot_state, s.time_ns, &imu_sample_);
        imu_writer_->Write(imu_sample_);
        break;
      default:
        FillForce(s.robot_state, s.time_ns, &force_sample_);
        force_writer_->Write(force_sample_);
        break;
    }
  }
}

// The whole frame (sensor noise of this frame, no link delay), body poses and the ball: what bridges and viewers
// read.
void LeggedPublisher::PublishState(const LeggedKernel& kernel) {
  kernel.Measure(&state_);
  FillState(state_, &frame_sample_);
  // The whole frame first: a lockstep driver (the SimSpark bridge) waits for it.
  state_writer_->Write(frame_sample_);
  for (const idl::LinkState& links : frame_sample_.links()) links_writer_->Write(links);
  if (state_.has_ball) {
    idl::WorldState world;
    world.sim_time_ns(state_.time_ns);
    world.frame(state_.frame);
    world.ball().position(V3(state_.ball_position));
    world.ball().velocity(V3(state_.ball_velocity));
    world_writer_->Write(world);
  }
}

void LeggedPublisher::PublishSceneInfo(const LeggedKernel& kernel) {
  const LeggedScene& s = kernel.scene();
  idl::LeggedSceneInfo info;
  info.name(s.name);
  info.has_field(s.field.enabled);
  info.field_length(s.field.length);
  info.field_width(s.field.width);
  info.goal_width(s.field.goal_width);
  info.goal_depth(s.field.goal_depth);
  info.goal_height(s.field.goal_height);
  info.ball_radius(s.field.ball_radius);
  for (int i = 0; i < kernel.world().RobotCount(); ++i) {
    idl::RobotDescription robot;
    robot.robot(s.robots[i].name);
    robot.id(s.robots[i].id);
    robot.model(s.robots[i].model);
    robot.robot_type(s.robots[i].robot_type);
    for (const LeggedGeom& g : kernel.world().RobotGeoms(i)) {
      idl::RobotGeom geom;
      geom.body(g.body);
      geom.shape(ToIdl(g.shape));
      geom.size(V3(g.size));
      geom.position(V3(g.position));
      geom.orientation(Q4(g.orientation));
      robot.geoms().push_back(geom);
    }
    info.robots().push_back(robot);
  }
  scene_writer_->Write(info);
}

}  // namespace turf
