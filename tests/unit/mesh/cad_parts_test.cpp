// The cylinder, tube and flange generators: counts, closed and outward surfaces of the right
// genus, exact volumes and the flat faces that the contact scenes rely on.
#include <collido/mesh/procedural.h>

#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/mesh_checks.h"
#include "support/numbers.h"

namespace collido {
namespace {

using test::kPi;

using test::build;
using test::enclosedVolume;
using test::expectBox;
using test::expectInvalid;
using test::expectWatertight;

// Area of the regular n-gon inscribed in a circle of radius r.
double polygonArea(int n, double r) {
  return 0.5 * n * r * r * std::sin(2.0 * kPi / n);
}

TEST(ProceduralCylinder, SolidAndTubeAreClosedWithTheirPrismsVolume) {
  const TriangleMesh solid = build(makeCylinder({0.5, 2.0, 12, 0.0}));
  EXPECT_EQ(solid.vertexCount(), 2u * 12u + 2u);
  EXPECT_EQ(solid.triangleCount(), 4u * 12u);
  expectWatertight(solid, 2, 1e-6);
  EXPECT_NEAR(enclosedVolume(solid), polygonArea(12, 0.5) * 2.0, 1e-12);
  expectBox(solid, {-0.5, -0.5, -1.0}, {0.5, 0.5, 1.0});

  const TriangleMesh tube = build(makeCylinder({0.5, 2.0, 12, 0.375}));
  EXPECT_EQ(tube.vertexCount(), 4u * 12u);
  EXPECT_EQ(tube.triangleCount(), 8u * 12u);
  expectWatertight(tube, 0, 1e-6);  // genus 1
  EXPECT_NEAR(enclosedVolume(tube), (polygonArea(12, 0.5) - polygonArea(12, 0.375)) * 2.0, 1e-12);
}

TEST(ProceduralCylinder, ABoreOfTheShanksRadiusSharesItsFacets) {
  // A round nut on a bolt: the same segments and radius put the bore's corners on the shank's.
  const TriangleMesh shank = build(makeCylinder({0.25, 2.0, 16, 0.0}));
  const TriangleMesh nut = build(makeCylinder({0.5, 0.5, 16, 0.25}));
  for (int i = 0; i < 16; ++i) {
    EXPECT_EQ(nut.vertices.col(2 * 16 + i).head<2>(), shank.vertices.col(i).head<2>()) << i;
  }
}

TEST(ProceduralCylinder, RejectsBadParameters) {
  expectInvalid(makeCylinder({0.0, 1.0, 8, 0.0}), "cylinder", "radius = 0");
  expectInvalid(makeCylinder({1.0, std::numeric_limits<double>::quiet_NaN(), 8, 0.0}), "cylinder",
                "height");
  expectInvalid(makeCylinder({1.0, 1.0, 2, 0.0}), "cylinder", "segments = 2, must be >= 3");
  expectInvalid(makeCylinder({1.0, 1.0, 8, 1.0}), "cylinder", "inner_radius = 1");
  expectInvalid(makeCylinder({1.0, 1.0, 8, -0.5}), "cylinder", "inner_radius = -0.5");
  expectInvalid(makeCylinder({1.0, 1.0, 1 << 30, 0.5}), "cylinder", "triangles");
}

FlangeParams flangeParams(int holes, int arc, int radial) {
  FlangeParams p;
  p.bolt_holes = holes;
  p.arc_segments = arc;
  p.radial_segments = radial;
  return p;
}

// The polygon area of hole k's top-face ring (the layout of procedural.h), by the shoelace
// formula.
double holeArea(const TriangleMesh& mesh, const FlangeParams& p, int k) {
  const int ring = p.bolt_holes * p.arc_segments;
  const int outline = 2 * (p.arc_segments + p.radial_segments);
  const int per_layer = 2 * ring + p.bolt_holes * (p.radial_segments - 1) + p.bolt_holes * outline;
  const int first = per_layer + 2 * ring + p.bolt_holes * (p.radial_segments - 1) + k * outline;
  double twice_area = 0.0;
  for (int m = 0; m < outline; ++m) {
    const Eigen::Vector3d a = mesh.vertices.col(first + m);
    const Eigen::Vector3d b = mesh.vertices.col(first + (m + 1) % outline);
    twice_area += a.x() * b.y() - a.y() * b.x();
  }
  return 0.5 * twice_area;
}

TEST(ProceduralFlange, IsClosedWithGenusOneMoreThanItsHoles) {
  for (const auto& [holes, arc, radial] :
       std::vector<std::array<int, 3>>{{3, 2, 1}, {4, 3, 2}, {6, 4, 2}, {8, 5, 3}}) {
    SCOPED_TRACE(std::to_string(holes) + " holes, " + std::to_string(arc) + " x " +
                 std::to_string(radial));
    FlangeParams p = flangeParams(holes, arc, radial);
    if (holes <= 4) {  // the sectors seen from the hole centres: bore < 0.75 cos(pi / holes)
      p.bore_radius = 0.3;
      p.hole_radius = 0.06;
    }
    const TriangleMesh mesh = build(makeFlange(p));
    const int outline = 2 * (arc + radial);
    EXPECT_EQ(
        mesh.vertexCount(),
        static_cast<std::size_t>(2 * (2 * holes * arc + holes * (radial - 1) + holes * outline)));
    EXPECT_EQ(mesh.triangleCount(),
              static_cast<std::size_t>(6 * holes * outline + 4 * holes * arc));
    expectWatertight(mesh, -2L * holes, 1e-9);
  }
}

TEST(ProceduralFlange, VolumeIsThePlateLessItsBoreAndHoles) {
  const FlangeParams p = flangeParams(6, 4, 2);
  const TriangleMesh mesh = build(makeFlange(p));
  const int ring = p.bolt_holes * p.arc_segments;
  double area = polygonArea(ring, p.outer_radius) - polygonArea(ring, p.bore_radius);
  for (int k = 0; k < p.bolt_holes; ++k) {
    const double hole = holeArea(mesh, p, k);
    // Inscribed in the hole's circle, and not far from it at 12 points.
    EXPECT_LT(hole, kPi * p.hole_radius * p.hole_radius);
    EXPECT_GT(hole, polygonArea(12, p.hole_radius) * 0.9);
    area -= hole;
  }
  EXPECT_NEAR(enclosedVolume(mesh), area * p.thickness, 1e-12);
}

TEST(ProceduralFlange, FacesAreFlatAndHolesOnTheirCircles) {
  const FlangeParams p = flangeParams(8, 3, 2);
  const TriangleMesh mesh = build(makeFlange(p));
  // The rim's 24 corners start at -pi / 8, so none lies on an axis: the nearest are pi / 24 off.
  const double reach = p.outer_radius * std::cos(kPi / 24.0);
  expectBox(mesh, {-reach, -reach, -p.thickness / 2}, {reach, reach, p.thickness / 2});
  int on_holes = 0;
  for (Eigen::Index v = 0; v < mesh.vertices.cols(); ++v) {
    const Eigen::Vector3d x = mesh.vertices.col(v);
    EXPECT_EQ(std::abs(x.z()), p.thickness / 2) << "vertex " << v;
    for (int k = 0; k < p.bolt_holes; ++k) {
      const double angle = 2.0 * kPi * k / p.bolt_holes;
      const Eigen::Vector2d centre =
          p.bolt_circle_radius * Eigen::Vector2d(std::cos(angle), std::sin(angle));
      if (std::abs((x.head<2>() - centre).norm() - p.hole_radius) < 1e-12) ++on_holes;
    }
  }
  EXPECT_EQ(on_holes, 2 * p.bolt_holes * 2 * (p.arc_segments + p.radial_segments));
}

TEST(ProceduralFlange, RejectsBadParameters) {
  const std::string name = "flange";
  FlangeParams p;
  p.outer_radius = -1.0;
  expectInvalid(makeFlange(p), name, "outer_radius = -1");
  p = {};
  p.thickness = std::numeric_limits<double>::infinity();
  expectInvalid(makeFlange(p), name, "thickness");
  p = {};
  p.bolt_holes = 2;
  expectInvalid(makeFlange(p), name, "bolt_holes = 2, must be >= 3");
  p = {};
  p.arc_segments = 0;
  expectInvalid(makeFlange(p), name, "arc_segments = 0");
  p = {};
  p.radial_segments = 0;
  expectInvalid(makeFlange(p), name, "radial_segments = 0");
  p = {};
  p.bore_radius = 0.7;  // 0.75 cos 30 deg = 0.65
  expectInvalid(makeFlange(p), name, "bore_radius = 0.7, must be < bolt_circle_radius");
  p = {};
  p.bolt_circle_radius = 1.0;
  expectInvalid(makeFlange(p), name, "bolt_circle_radius = 1, must be < outer_radius");
  p = {};
  p.hole_radius = 0.2;  // the bore is 0.75 cos 30 deg - 0.5 = 0.15 from a hole's centre
  expectInvalid(makeFlange(p), name, "hole_radius = 0.2, must be < the clearance to the bore");
  p = {};
  p.bolt_holes = 40;
  p.bore_radius = 0.7;
  p.hole_radius = 0.05;  // 0.75 sin(4.5 deg) = 0.059 to the sector's edges, 0.05 to the bore
  expectInvalid(makeFlange(p), name, "hole_radius = 0.05, must be < the clearance to the bore");
  p.hole_radius = 0.04;
  EXPECT_TRUE(makeFlange(p).ok());
  p.hole_radius = 0.07;
  p.bore_radius = 0.5;
  expectInvalid(makeFlange(p), name, "hole_radius = 0.07, must be < the clearance to the sector");
  p = {};
  p.arc_segments = 1 << 20;
  p.radial_segments = 1 << 20;
  expectInvalid(makeFlange(p), name, "triangles");
}

}  // namespace
}  // namespace collido
