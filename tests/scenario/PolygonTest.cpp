// Plane-polygon geometry on its own (scenario/geometry/Polygon.h), against results worked out by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/Error.h"
#include "scenario/geometry/Polygon.h"

namespace wiggle {
namespace {

const Outline kUnitSquare = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};  // counter-clockwise
// An L: [0, 2] x [0, 1] below, [0, 1] x [1, 2] above (areas 2 and 1).
const Outline kL = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};

TEST(Polygon, AreaIsSignedByOrientation) {
  EXPECT_DOUBLE_EQ(signedArea(kUnitSquare), 1.0);
  EXPECT_DOUBLE_EQ(signedArea(Outline(kUnitSquare.rbegin(), kUnitSquare.rend())), -1.0);
  EXPECT_DOUBLE_EQ(signedArea(kL), 3.0);
  EXPECT_DOUBLE_EQ(signedArea({{0, 0}, {4, 0}, {0, 3}}), 6.0);
}

TEST(Polygon, CentroidIsTheAreaWeightedMeanOfItsParts) {
  const OutlinePoint c = areaCentroid(kL);  // (2 (1, 0.5) + 1 (0.5, 1.5)) / 3
  EXPECT_NEAR(c[0], 2.5 / 3.0, 1e-15);
  EXPECT_NEAR(c[1], 2.5 / 3.0, 1e-15);
  const OutlinePoint t = areaCentroid({{0, 0}, {3, 0}, {0, 6}});  // the vertices' mean for a triangle
  EXPECT_NEAR(t[0], 1.0, 1e-15);
  EXPECT_NEAR(t[1], 2.0, 1e-15);
  const OutlinePoint moved = areaCentroid(translated(kL, 10.0, -4.0));
  EXPECT_NEAR(moved[0], 10.0 + 2.5 / 3.0, 1e-13);
  EXPECT_NEAR(moved[1], -4.0 + 2.5 / 3.0, 1e-13);
}

TEST(Polygon, BoundingBox) {
  const OutlineBox box = boundingBox(translated(kL, -1.0, 0.5));
  EXPECT_EQ(box.xMin, -1.0);
  EXPECT_EQ(box.xMax, 1.0);
  EXPECT_EQ(box.yMin, 0.5);
  EXPECT_EQ(box.yMax, 2.5);
  EXPECT_EQ(box.width(), 2.0);
  EXPECT_EQ(box.height(), 2.0);
}

TEST(Polygon, FindsCrossingsTouchesAndFolds) {
  EXPECT_FALSE(findSelfIntersection(kUnitSquare));
  EXPECT_FALSE(findSelfIntersection(kL));
  // A bow tie: edge 0 ((0,0)-(1,1)) crosses edge 2 ((1,0)-(0,1)).
  const auto bowTie = findSelfIntersection({{0, 0}, {1, 1}, {1, 0}, {0, 1}});
  ASSERT_TRUE(bowTie);
  EXPECT_EQ((*bowTie)[0], 0u);
  EXPECT_EQ((*bowTie)[1], 2u);
  // A vertex touching a non-neighbouring edge.
  EXPECT_TRUE(findSelfIntersection({{0, 0}, {2, 0}, {2, 2}, {1, 0}, {0, 2}}));
  // Neighbouring edges folding back onto each other (out along y = 0 and back again).
  EXPECT_TRUE(findSelfIntersection({{0, 0}, {2, 0}, {1, 0}, {1, 1}}));
}

TEST(Polygon, NamesWhatIsWrong) {
  EXPECT_FALSE(polygonProblem(kL));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto problem = [](const Outline& p) { return polygonProblem(p).value_or(""); };
  EXPECT_NE(problem({{0, 0}, {1, 0}}).find("3"), std::string::npos);
  EXPECT_NE(problem({{0, 0}, {1, nan}, {0, 1}}).find("finite"), std::string::npos);
  EXPECT_NE(problem({{0, 0}, {1, 0}, {1, 0}, {0, 1}}).find("repeat"), std::string::npos);
  EXPECT_NE(problem({{0, 0}, {1, 0}, {2, 0}}).find("area"), std::string::npos);
  EXPECT_NE(problem({{0, 0}, {1, 1}, {1, 0}, {0, 1}}).find("intersect"), std::string::npos);
  try {
    requireValidPolygon({{0, 0}, {1, 0}}, "intruder.vertices");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()).rfind("intruder.vertices: ", 0), 0u) << e.what();
  }
}

TEST(Polygon, OrientationTranslationRotation) {
  const Outline cw(kUnitSquare.rbegin(), kUnitSquare.rend());
  EXPECT_GT(signedArea(counterClockwise(cw)), 0.0);
  EXPECT_EQ(counterClockwise(kUnitSquare), kUnitSquare);  // already counter-clockwise: unchanged
  const Outline turned = rotated({{1, 0}, {0, 1}, {-1, 0}}, 90.0);  // (x, y) -> (-y, x)
  EXPECT_NEAR(turned[0][0], 0.0, 1e-15);
  EXPECT_NEAR(turned[0][1], 1.0, 1e-15);
  EXPECT_NEAR(turned[1][0], -1.0, 1e-15);
  EXPECT_NEAR(turned[1][1], 0.0, 1e-15);
  EXPECT_NEAR(signedArea(rotated(kL, 33.0)), 3.0, 1e-13);
}

TEST(Polygon, ContainmentDistanceAndDepth) {
  EXPECT_TRUE(containsPoint(kL, {0.5, 1.5}));
  EXPECT_FALSE(containsPoint(kL, {1.5, 1.5}));  // the L's missing corner
  EXPECT_FALSE(containsPoint(kL, {3.0, 0.5}));
  EXPECT_DOUBLE_EQ(distanceToBoundary(kUnitSquare, {0.5, 0.5}), 0.5);
  EXPECT_DOUBLE_EQ(distanceToBoundary(kUnitSquare, {0.5, 3.0}), 2.0);   // nearest: the top edge
  EXPECT_DOUBLE_EQ(distanceToBoundary(kUnitSquare, {4.0, 5.0}), 5.0);   // nearest: corner (1, 1)
  EXPECT_DOUBLE_EQ(depthInside(kUnitSquare, {0.25, 0.5}), 0.25);
  EXPECT_DOUBLE_EQ(depthInside(kL, {1.5, 1.5}), -0.5);
}

}  // namespace
}  // namespace wiggle
