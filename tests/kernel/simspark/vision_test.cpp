#include "kernel/simspark/vision.h"

#include <gtest/gtest.h>

#include <cmath>

namespace turf::simspark {
namespace {

constexpr double kDeg = M_PI / 180.0;

VisionParams Ideal() {
  VisionParams params;
  params.noise = false;
  return params;
}

// A head at `position` looking along the field direction `yaw_deg` (0 = +x).
VisionScene HeadAt(Eigen::Vector3d position, double yaw_deg) {
  VisionScene scene;
  scene.head_position = position;
  // head y (forward) is field +y at identity, so yaw - 90 turns it to yaw_deg.
  scene.head_orientation = Eigen::AngleAxisd((yaw_deg - 90.0) * kDeg, Eigen::Vector3d::UnitZ());
  return scene;
}

Field3dGeometry NoField() { return Field3dGeometry{}; }  // dimensions only: no flags, posts or lines

Field3dGeometry OneLine(Eigen::Vector3d a, Eigen::Vector3d b) {
  Field3dGeometry field;
  field.lines.push_back({a, b});
  return field;
}

const SeeObject* Find(const SeeItems& items, const std::string& label) {
  for (const auto& o : items.objects)
    if (o.label == label) return &o;
  return nullptr;
}

TEST(VisionPolar, AxesAndSigns) {
  const Polar ahead = ToPolar({0, 5, 0});
  EXPECT_DOUBLE_EQ(ahead.distance, 5.0);
  EXPECT_NEAR(ahead.horizontal, 0.0, 1e-12);
  EXPECT_NEAR(ahead.vertical, 0.0, 1e-12);
  EXPECT_NEAR(ToPolar({-1, 1, 0}).horizontal, 45.0, 1e-12);  // left is positive
  EXPECT_NEAR(ToPolar({1, 1, 0}).horizontal, -45.0, 1e-12);
  EXPECT_NEAR(ToPolar({0, -1, 0}).horizontal, 180.0, 1e-12);  // behind: +180, never -180
  EXPECT_NEAR(ToPolar({1, -1e-12, 0}).horizontal, -90.0, 1e-9);
  EXPECT_NEAR(ToPolar({0, 1, 1}).vertical, 45.0, 1e-12);  // up is positive
  EXPECT_NEAR(ToPolar({3, 4, -5}).vertical, -45.0, 1e-12);
}

TEST(Vision, BallStraightAheadAtFiveMetres) {
  VisionScene scene = HeadAt({0, 0, 0}, 90);
  scene.ball = Eigen::Vector3d(0, 5, 0);
  const SeeItems items = ComputeSee(scene, NoField(), Ideal(), nullptr);
  const SeeObject* ball = Find(items, "B");
  ASSERT_NE(ball, nullptr);
  EXPECT_NEAR(ball->pol.distance, 5.0, 1e-12);
  EXPECT_NEAR(ball->pol.horizontal, 0.0, 1e-12);
  EXPECT_NEAR(ball->pol.vertical, 0.0, 1e-12);
}

TEST(Vision, HeadFacingPlusXSeesBallToTheLeftWithPositiveH) {
  VisionScene scene = HeadAt({1, 2, 0.5}, 0);
  scene.ball = Eigen::Vector3d(6, 3, 0.5);  // 5 ahead, 1 to the left (+y)
  const SeeObject* ball = Find(ComputeSee(scene, NoField(), Ideal(), nullptr), "B");
  ASSERT_NE(ball, nullptr);
  EXPECT_NEAR(ball->pol.distance, std::sqrt(26.0), 1e-12);
  EXPECT_NEAR(ball->pol.horizontal, std::atan2(1, 5) / kDeg, 1e-9);
  EXPECT_GT(ball->pol.horizontal, 0.0);
  EXPECT_NEAR(ball->pol.vertical, 0.0, 1e-9);
}

TEST(Vision, FacingAwayNothingIsSeen) {
  VisionScene scene = HeadAt({0, 0, 0.5}, 180);  // looks at the left goal
  scene.ball = Eigen::Vector3d(5, 0, 0.042);
  const SeeItems items = ComputeSee(scene, StandardField3d(), Ideal(), nullptr);
  EXPECT_EQ(Find(items, "B"), nullptr);
  EXPECT_EQ(Find(items, "F1R"), nullptr);
  EXPECT_EQ(Find(items, "G1R"), nullptr);
  EXPECT_NE(Find(items, "G1L"), nullptr);
  EXPECT_NE(Find(items, "G2L"), nullptr);
}

TEST(Vision, FlagAtItsKnownPlace) {
  // At the centre spot, head 0.5 m up, looking at the right goal: F1R is
  // 15 ahead and 10 to the left, 0.5 below.
  const VisionScene scene = HeadAt({0, 0, 0.5}, 0);
  const SeeItems items = ComputeSee(scene, StandardField3d(), Ideal(), nullptr);
  const SeeObject* flag = Find(items, "F1R");
  ASSERT_NE(flag, nullptr);
  EXPECT_NEAR(flag->pol.distance, std::sqrt(15 * 15 + 10 * 10 + 0.25), 1e-9);
  EXPECT_NEAR(flag->pol.horizontal, std::atan2(10, 15) / kDeg, 1e-9);
  EXPECT_NEAR(flag->pol.vertical, -std::atan2(0.5, std::hypot(15, 10)) / kDeg, 1e-9);
  const SeeObject* post = Find(items, "G2R");  // top of the post, 0.3 m above the head
  ASSERT_NE(post, nullptr);
  EXPECT_NEAR(post->pol.horizontal, -std::atan2(1.05, 15) / kDeg, 1e-9);
  EXPECT_NEAR(post->pol.vertical, std::atan2(0.3, std::hypot(15, 1.05)) / kDeg, 1e-9);
  EXPECT_EQ(Find(items, "F1L"), nullptr);  // behind
}

TEST(Vision, ConeEdgesAndMinimumDistance) {
  const VisionScene base = HeadAt({0, 0, 0}, 90);
  const auto seen = [&](Eigen::Vector3d ball) {
    VisionScene scene = base;
    scene.ball = ball;
    return Find(ComputeSee(scene, NoField(), Ideal(), nullptr), "B") != nullptr;
  };
  const auto dir = [](double h_deg, double v_deg) -> Eigen::Vector3d {
    const double h = (h_deg + 90) * kDeg;
    const double v = v_deg * kDeg;
    return Eigen::Vector3d(std::cos(v) * std::cos(h), std::cos(v) * std::sin(h), std::sin(v)) * 3.0;
  };
  EXPECT_TRUE(seen(dir(59.9, 0)));
  EXPECT_FALSE(seen(dir(60.1, 0)));
  EXPECT_TRUE(seen(dir(-59.9, 0)));
  EXPECT_FALSE(seen(dir(-60.1, 0)));
  EXPECT_TRUE(seen(dir(0, 59.9)));
  EXPECT_FALSE(seen(dir(0, 60.1)));
  EXPECT_FALSE(seen(dir(0, -60.1)));
  EXPECT_TRUE(seen(dir(59.9, -59.9)));
  EXPECT_TRUE(seen({0, 0.11, 0}));
  EXPECT_FALSE(seen({0, 0.1, 0}));  // d must exceed 0.1
  EXPECT_FALSE(seen({0, 0.05, 0}));
}

TEST(Vision, PlayersListOnlyVisibleParts) {
  VisionScene scene = HeadAt({0, 0, 0.5}, 0);
  scene.players.push_back({"Me",
                           3,
                           {{"head", {0, 0, 0.5}},             // the viewer's own head: d = 0
                            {"rlowerarm", {0.2, -0.1, 0.4}},   // own arm, ahead
                            {"rfoot", {0.02, -0.05, 0.0}}}});  // own foot: straight down, v < -60
  scene.players.push_back({"Them", 7, {{"head", {4, 1, 0.5}}, {"lfoot", {4, 1, 0}}, {"rfoot", {-4, 0, 0}}}});
  scene.players.push_back({"Them", 8, {{"head", {-3, 0, 0.5}}}});  // behind: omitted
  const SeeItems items = ComputeSee(scene, NoField(), Ideal(), nullptr);
  ASSERT_EQ(items.players.size(), 2u);
  EXPECT_EQ(items.players[0].team, "Me");
  EXPECT_EQ(items.players[0].id, 3);
  ASSERT_EQ(items.players[0].parts.size(), 1u);
  EXPECT_EQ(items.players[0].parts[0].name, "rlowerarm");
  EXPECT_NEAR(items.players[0].parts[0].pol.distance, std::sqrt(0.06), 1e-12);
  EXPECT_EQ(items.players[1].id, 7);
  ASSERT_EQ(items.players[1].parts.size(), 2u);
  EXPECT_EQ(items.players[1].parts[0].name, "head");
  EXPECT_EQ(items.players[1].parts[1].name, "lfoot");
}

TEST(Vision, LineCrossingTheWholeViewIsClippedAtBothSideEdges) {
  // From (0,0,0.5) looking along +y: the line y = 5 runs from far right to far left.
  const VisionScene scene = HeadAt({0, 0, 0.5}, 90);
  const SeeItems items = ComputeSee(scene, OneLine({-10, 5, 0}, {10, 5, 0}), Ideal(), nullptr);
  ASSERT_EQ(items.lines.size(), 1u);
  const SeeLine& line = items.lines[0];
  EXPECT_NEAR(line.begin.horizontal, 60.0, 1e-9);  // x = -10 is on the left
  EXPECT_NEAR(line.end.horizontal, -60.0, 1e-9);
  const double x = 5 * std::tan(60 * kDeg);
  EXPECT_NEAR(line.begin.distance, std::sqrt(x * x + 25 + 0.25), 1e-9);
  EXPECT_NEAR(line.end.distance, line.begin.distance, 1e-9);
}

TEST(Vision, LineWithOneVisibleEndKeepsItAndClipsTheOther) {
  const VisionScene scene = HeadAt({0, 0, 0.5}, 90);
  const SeeItems items = ComputeSee(scene, OneLine({0, 5, 0}, {20, 5, 0}), Ideal(), nullptr);
  ASSERT_EQ(items.lines.size(), 1u);
  const Polar exact_begin = ToPolar({0, 5, -0.5});
  EXPECT_NEAR(items.lines[0].begin.distance, exact_begin.distance, 1e-12);
  EXPECT_NEAR(items.lines[0].begin.horizontal, exact_begin.horizontal, 1e-12);
  EXPECT_NEAR(items.lines[0].begin.vertical, exact_begin.vertical, 1e-12);
  EXPECT_NEAR(items.lines[0].end.horizontal, -60.0, 1e-9);
}

TEST(Vision, LineFromBehindIsClippedAtTheLowerEdge) {
  // A line on the ground passing under the camera: the near part is below v = -60.
  const VisionScene scene = HeadAt({0, 0, 0.5}, 90);
  const SeeItems items = ComputeSee(scene, OneLine({0, -5, 0}, {0, 5, 0}), Ideal(), nullptr);
  ASSERT_EQ(items.lines.size(), 1u);
  EXPECT_NEAR(items.lines[0].begin.vertical, -60.0, 1e-9);
  EXPECT_NEAR(items.lines[0].begin.distance, 0.5 / std::sin(60 * kDeg), 1e-9);
  EXPECT_NEAR(items.lines[0].end.distance, std::sqrt(25.25), 1e-12);
}

TEST(Vision, LinesOutsideTheConeAreDropped) {
  const VisionScene scene = HeadAt({0, 0, 0.5}, 90);
  EXPECT_TRUE(ComputeSee(scene, OneLine({-5, -3, 0}, {5, -3, 0}), Ideal(), nullptr).lines.empty());  // behind
  EXPECT_TRUE(ComputeSee(scene, OneLine({-6, 1, 0}, {-6, 3, 0}), Ideal(), nullptr).lines.empty());   // left of cone
  EXPECT_TRUE(ComputeSee(scene, OneLine({0, 0.05, 0.5}, {0, 0.09, 0.5}), Ideal(), nullptr).lines.empty());  // too near
}

TEST(Vision, EveryReportedPointLiesInTheConeFromAnyPose) {
  Rng pose_rng(7);
  const Field3dGeometry field = StandardField3d();
  int lines_seen = 0;
  for (int i = 0; i < 500; ++i) {
    VisionScene scene;
    scene.head_position = {-15 + 30 * pose_rng.Uniform(), -10 + 20 * pose_rng.Uniform(),
                           0.3 + 0.4 * pose_rng.Uniform()};
    const Eigen::Vector3d axis = Eigen::Vector3d(pose_rng.Normal(), pose_rng.Normal(), pose_rng.Normal()).normalized();
    scene.head_orientation = Eigen::AngleAxisd(M_PI * pose_rng.Uniform(), axis);
    const SeeItems items = ComputeSee(scene, field, Ideal(), nullptr);
    const auto check = [](const Polar& p) {
      EXPECT_GE(p.distance, 0.1 - 1e-9);
      EXPECT_LE(std::abs(p.horizontal), 60.0 + 1e-6);
      EXPECT_LE(std::abs(p.vertical), 60.0 + 1e-6);
    };
    for (const auto& o : items.objects) check(o.pol);
    for (const auto& l : items.lines) {
      check(l.begin);
      check(l.end);
    }
    lines_seen += static_cast<int>(items.lines.size());
  }
  EXPECT_GT(lines_seen, 100);
}

TEST(Vision, NoiseHasTheSheetsStatistics) {
  VisionScene scene = HeadAt({0, 0, 0}, 90);
  scene.ball = Eigen::Vector3d(0, 10, 0);
  const VisionParams params;  // noise on
  Rng rng(42);
  const int n = 20000;
  double sd = 0, sh = 0, sv = 0, sdd = 0, shh = 0, svv = 0;
  for (int i = 0; i < n; ++i) {
    const SeeObject* ball = Find(ComputeSee(scene, NoField(), params, &rng), "B");
    ASSERT_NE(ball, nullptr);
    const double d = ball->pol.distance - 10.0;
    sd += d, sdd += d * d;
    sh += ball->pol.horizontal, shh += ball->pol.horizontal * ball->pol.horizontal;
    sv += ball->pol.vertical, svv += ball->pol.vertical * ball->pol.vertical;
  }
  const auto stddev = [n](double s, double ss) { return std::sqrt(ss / n - (s / n) * (s / n)); };
  const double sigma_d = 0.0965 * 10.0 / 100.0;
  EXPECT_NEAR(sd / n, 0.0, 4 * sigma_d / std::sqrt(n));
  EXPECT_NEAR(sh / n, 0.0, 4 * 0.1480 / std::sqrt(n));
  EXPECT_NEAR(sv / n, 0.0, 4 * 0.1225 / std::sqrt(n));
  EXPECT_NEAR(stddev(sd, sdd), sigma_d, 0.03 * sigma_d);
  EXPECT_NEAR(stddev(sh, shh), 0.1480, 0.03 * 0.1480);  // h and v sigmas not swapped (they differ by 17%)
  EXPECT_NEAR(stddev(sv, svv), 0.1225, 0.03 * 0.1225);
}

TEST(Vision, NoiseIsAppliedAfterTheConeCheck) {
  // Exactly inside the edge: always listed, sometimes reported beyond 60.
  VisionScene scene = HeadAt({0, 0, 0}, 90);
  const double h = (59.99 + 90) * kDeg;
  scene.ball = Eigen::Vector3d(std::cos(h), std::sin(h), 0) * 4.0;
  Rng rng(3);
  int beyond = 0;
  for (int i = 0; i < 1000; ++i) {
    const SeeObject* ball = Find(ComputeSee(scene, NoField(), VisionParams{}, &rng), "B");
    ASSERT_NE(ball, nullptr);
    beyond += ball->pol.horizontal > 60.0;
  }
  EXPECT_GT(beyond, 300);
}

TEST(Vision, EqualSeedsGiveEqualSees) {
  VisionScene scene = HeadAt({-3, 1, 0.55}, 20);
  scene.ball = Eigen::Vector3d(2, 0, 0.042);
  scene.players.push_back({"A", 2, {{"head", {1, 1, 0.5}}, {"lfoot", {1, 1.1, 0.03}}}});
  const auto run = [&](uint64_t seed) {
    Rng rng(seed);
    VisionScene s = scene;
    s.calibration_offset = DrawCalibrationOffset(&rng);
    return ComputeSee(s, StandardField3d(), VisionParams{}, &rng);
  };
  const SeeItems a = run(11), b = run(11), c = run(12);
  ASSERT_EQ(a.objects.size(), b.objects.size());
  ASSERT_EQ(a.lines.size(), b.lines.size());
  ASSERT_FALSE(a.lines.empty());
  for (size_t i = 0; i < a.objects.size(); ++i) {
    EXPECT_EQ(a.objects[i].pol.distance, b.objects[i].pol.distance);
    EXPECT_EQ(a.objects[i].pol.horizontal, b.objects[i].pol.horizontal);
  }
  for (size_t i = 0; i < a.lines.size(); ++i) EXPECT_EQ(a.lines[i].end.vertical, b.lines[i].end.vertical);
  EXPECT_EQ(a.players[0].parts[1].pol.vertical, b.players[0].parts[1].pol.vertical);
  ASSERT_EQ(a.objects.size(), c.objects.size());
  EXPECT_NE(a.objects[0].pol.distance, c.objects[0].pol.distance);
}

TEST(Vision, CalibrationOffsetIsSmallAndAddedInTheHeadFrame) {
  Rng rng(5);
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1), hi = Eigen::Vector3d::Constant(-1);
  for (int i = 0; i < 2000; ++i) {
    const Eigen::Vector3d o = DrawCalibrationOffset(&rng);
    lo = lo.cwiseMin(o);
    hi = hi.cwiseMax(o);
  }
  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_GE(lo[axis], -0.005);
    EXPECT_LT(hi[axis], 0.005);
    EXPECT_LT(lo[axis], -0.0045);
    EXPECT_GT(hi[axis], 0.0045);
  }
  VisionScene scene = HeadAt({0, 0, 0}, 0);  // looking along +x
  scene.ball = Eigen::Vector3d(5, 0, 0);
  scene.calibration_offset = {0, 0.004, 0};  // head-frame forward
  const SeeObject* ball = Find(ComputeSee(scene, NoField(), Ideal(), nullptr), "B");
  ASSERT_NE(ball, nullptr);
  EXPECT_NEAR(ball->pol.distance, 5.004, 1e-12);
  EXPECT_NEAR(ball->pol.horizontal, 0.0, 1e-9);
}

}  // namespace
}  // namespace turf::simspark
