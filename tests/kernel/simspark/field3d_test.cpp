#include "kernel/simspark/field3d.h"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/support/find.h"

namespace turf::simspark {
namespace {

const FieldPoint* Find(const std::vector<FieldPoint>& points, const std::string& label) {
  return turf::test::FindBy(points, &FieldPoint::label, label);
}

TEST(Field3d, FlagsAndGoalPostsAtTheSheetsPlaces) {
  const Field3dGeometry field = StandardField3d();
  ASSERT_EQ(field.flags.size(), 4u);
  ASSERT_EQ(field.goal_posts.size(), 4u);
  const struct {
    const char* label;
    double x, y, z;
  } expected[] = {{"F1L", -15, 10, 0},     {"F2L", -15, -10, 0},     {"F1R", 15, 10, 0},     {"F2R", 15, -10, 0},
                  {"G1L", -15, 1.05, 0.8}, {"G2L", -15, -1.05, 0.8}, {"G1R", 15, 1.05, 0.8}, {"G2R", 15, -1.05, 0.8}};
  for (const auto& e : expected) {
    const FieldPoint* p = Find(e.label[0] == 'F' ? field.flags : field.goal_posts, e.label);
    ASSERT_NE(p, nullptr) << e.label;
    EXPECT_NEAR(p->position.x(), e.x, 1e-12) << e.label;
    EXPECT_NEAR(p->position.y(), e.y, 1e-12) << e.label;
    EXPECT_NEAR(p->position.z(), e.z, 1e-12) << e.label;
  }
}

TEST(Field3d, TwentyOneLinesOnTheGroundInsideTheField) {
  const Field3dGeometry field = StandardField3d();
  ASSERT_EQ(field.lines.size(), 21u);
  int chords = 0;
  for (const auto& line : field.lines) {
    for (const Eigen::Vector3d& p : {line.a, line.b}) {
      EXPECT_EQ(p.z(), 0.0);
      EXPECT_LE(std::abs(p.x()), 15.0 + 1e-12);
      EXPECT_LE(std::abs(p.y()), 10.0 + 1e-12);
    }
    EXPECT_GT((line.b - line.a).norm(), 0.5);
    if (std::abs(line.a.head<2>().norm() - 2.0) < 1e-9 && std::abs(line.b.head<2>().norm() - 2.0) < 1e-9) {
      ++chords;
      EXPECT_NEAR((line.b - line.a).norm(), 2 * 2.0 * std::sin(M_PI / 10), 1e-9);  // decagon side
    }
  }
  EXPECT_EQ(chords, 10);
}

TEST(Field3d, PenaltyAreaAndGoalLines) {
  const Field3dGeometry field = StandardField3d();
  const auto has = [&](Eigen::Vector3d a, Eigen::Vector3d b) {
    for (const auto& line : field.lines)
      if (((line.a - a).norm() < 1e-9 && (line.b - b).norm() < 1e-9) ||
          ((line.a - b).norm() < 1e-9 && (line.b - a).norm() < 1e-9))
        return true;
    return false;
  };
  EXPECT_TRUE(has({0, -10, 0}, {0, 10, 0}));        // halfway
  EXPECT_TRUE(has({15, -10, 0}, {15, 10, 0}));      // right goal line
  EXPECT_TRUE(has({-15, 10, 0}, {15, 10, 0}));      // touch line
  EXPECT_TRUE(has({-13.2, -3, 0}, {-13.2, 3, 0}));  // left penalty area front
  EXPECT_TRUE(has({13.2, 3, 0}, {15, 3, 0}));       // right penalty area side
  EXPECT_TRUE(has({13.2, -3, 0}, {15, -3, 0}));
  EXPECT_FALSE(has({-13.2, -3, 0}, {-13.2, 3.5, 0}));
}

TEST(Field3d, FeaturesFollowTheDimensions) {
  Field3dGeometry dims;
  dims.length = 20;
  dims.width = 14;
  dims.goal_width = 1.6;
  const Field3dGeometry field = Field3dFromDimensions(dims);
  EXPECT_TRUE(Find(field.flags, "F2R")->position.isApprox(Eigen::Vector3d(10, -7, 0)));
  EXPECT_TRUE(Find(field.goal_posts, "G1L")->position.isApprox(Eigen::Vector3d(-10, 0.8, 0.8)));
  EXPECT_EQ(field.lines.size(), 21u);
}

}  // namespace
}  // namespace turf::simspark
