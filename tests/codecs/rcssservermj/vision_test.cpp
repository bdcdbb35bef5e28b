// The fields' markers and the ideal vision (shared/protocols/rcssservermj.md, "See (ideal vision)", "Fields").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "kernel/rcssservermj/field.h"
#include "kernel/rcssservermj/vision.h"
#include "tests/support/find.h"

namespace turf::rcssservermj {
namespace {

TEST(MjField, FifaMarkersAtTheFactsPositions) {
  const std::vector<FieldMarker> m = FieldMarkers(*FindField("fifa"));
  EXPECT_EQ(m.size(), 30u);  // 4 corners, 2 halfway, 2 circle, 2 marks, 4 posts, 8 goalie area, 8 penalty area
  auto at = [&](const char* name) { return turf::test::FindBy(m, &FieldMarker::name, name)->position; };
  EXPECT_EQ(at("l_luf"), Eigen::Vector3d(-52.5, 34, 0));
  EXPECT_EQ(at("l_rlf"), Eigen::Vector3d(52.5, -34, 0));
  EXPECT_EQ(at("t_clf"), Eigen::Vector3d(0, -34, 0));
  EXPECT_EQ(at("x_cuc"), Eigen::Vector3d(0, 9.15, 0));
  EXPECT_EQ(at("p_lpm"), Eigen::Vector3d(-41.5, 0, 0));
  EXPECT_EQ(at("g_rup"), Eigen::Vector3d(52.5, 3.66, 2.44));
  EXPECT_EQ(at("l_luga"), Eigen::Vector3d(-47, 18.32, 0));  // the full area width, as coded upstream
  EXPECT_EQ(at("t_rlga"), Eigen::Vector3d(52.5, -18.32, 0));
  EXPECT_EQ(at("l_rupa"), Eigen::Vector3d(36, 40.32, 0));
  EXPECT_EQ(at("t_llpa"), Eigen::Vector3d(-52.5, -40.32, 0));
}

TEST(MjField, PenaltyMarkersOnlyWhereTheFieldHasAPenaltyArea) {
  EXPECT_EQ(FieldMarkers(*FindField("hl_adult_2019")).size(), 22u);
  EXPECT_EQ(FindField("hl_adult"), FindField("hl_adult_2020"));
  EXPECT_EQ(FindField("sim3d_7vs7")->length, 55);
  EXPECT_EQ(FindField("nope"), nullptr);
}

TEST(MjVision, PolarInTheCameraFrame) {
  // Camera at 1 m height facing +y (yaw 90 deg): a point 3 m ahead and 3 m to its left on the ground.
  const Eigen::Quaterniond yaw90(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()));
  const Polar p = ToPolar(Eigen::Vector3d(-3, 3, 0), Eigen::Vector3d(0, 0, 1), yaw90);
  EXPECT_NEAR(p.distance, std::sqrt(19.0), 1e-9);
  EXPECT_NEAR(p.azimuth, 45.0, 1e-9);  // left is positive
  EXPECT_NEAR(p.elevation, -std::asin(1 / std::sqrt(19.0)) * 180 / M_PI, 1e-9);
}

TEST(MjVision, SixtyDegreeCutAfterTruncation) {
  EXPECT_TRUE(InView({1, 60.009, 0}));  // truncates to 60.0
  EXPECT_FALSE(InView({1, 60.01, 0}));
  EXPECT_FALSE(InView({1, 0, -61}));
  EXPECT_FALSE(InView({0, 0, 0}));
}

TEST(MjVision, SeesMarkersBallAndPlayersInFront) {
  const std::vector<FieldMarker> markers = FieldMarkers(*FindField("fifa"));
  const std::vector<VisiblePlayer> players = {
      {"a", 1, {{"head", {10, 0, 1}}, {"lfoot", {-10, 0, 0}}}},  // foot behind the camera
      {"b", 7, {{"head", {-20, 0, 1}}}},                         // wholly behind
  };
  VisionInput in;
  in.camera = Eigen::Vector3d(0, 0, 1);
  in.ball = Eigen::Vector3d(5, 0, 0.11);
  in.markers = &markers;
  in.players = &players;
  const SeeItems see = ComputeSee(in);
  std::vector<std::string> names;
  for (const SeenMarker& m : see.markers) names.push_back(m.name);
  // Facing +x from the centre: the right goal's side; the halfway ends are at ±90 deg.
  EXPECT_NE(std::find(names.begin(), names.end(), "g_rup"), names.end());
  EXPECT_EQ(std::find(names.begin(), names.end(), "g_lup"), names.end());
  EXPECT_EQ(std::find(names.begin(), names.end(), "t_cuf"), names.end());
  EXPECT_EQ(names.back(), "B");
  ASSERT_EQ(see.players.size(), 1u);
  EXPECT_EQ(see.players[0].team, "a");
  ASSERT_EQ(see.players[0].parts.size(), 1u);
  EXPECT_EQ(see.players[0].parts[0].name, "head");
}

}  // namespace
}  // namespace turf::rcssservermj
