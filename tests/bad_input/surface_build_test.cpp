// NURBS surfaces across the plugin interface: the adapter refuses malformed nets before a
// backend sees them, naming the field; a backend refuses shape kinds it does not build.
#include <cmath>
#include <limits>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include <collido/host/backend_instance.h>
#include <collido/host/plugin_library.h>
#include <collido/mesh/procedural.h>
#include <collido/nurbs/surface_generators.h>

#include "bad_input/rejection.h"

extern "C" const CollidoPluginTable* collido_plugin_table_nurbs(void);
extern "C" const CollidoPluginTable* collido_plugin_table_obbtree(void);

namespace collido::test {
namespace {

std::unique_ptr<BackendInstance> instanceOf(const CollidoPluginTable* table,
                                            const std::string& variant) {
  Result<std::shared_ptr<PluginLibrary>> library = PluginLibrary::fromTable(table, variant);
  EXPECT_TRUE(library.ok());
  Result<std::unique_ptr<BackendInstance>> instance =
      BackendInstance::create(library.value(), variant);
  EXPECT_TRUE(instance.ok()) << instance.status().message();
  return std::move(instance).value();
}

const BuildNeeds kDistance{QueryKindSet(QueryKind::kDistance)};

class SurfaceBuild : public ::testing::Test {
 protected:
  std::unique_ptr<BackendInstance> seed = instanceOf(collido_plugin_table_nurbs(), "nurbs:hull");
  nurbs::NurbsSurface zone = nurbs::sphereZone(Eigen::Vector3d::Zero(), 1.0, 0.0);
};

TEST_F(SurfaceBuild, AWellFormedSurfaceIsBuiltAndAnswers) {
  // Zones of unit spheres facing each other along x, centres 3 apart: the distance is 1.
  const nurbs::NurbsSurface facing_x = nurbs::sphereZone(Eigen::Vector3d::Zero(), 1.0, -45.0);
  const nurbs::NurbsSurface facing_minus_x = nurbs::sphereZone(Eigen::Vector3d::Zero(), 1.0, 135.0);
  Result<ModelHandle> a = seed->build(nurbs::viewOf(facing_x), kDistance);
  Result<ModelHandle> b = seed->build(nurbs::viewOf(facing_minus_x), kDistance);
  ASSERT_TRUE(a.ok() && b.ok());
  Pose pose_b = Pose::Identity();
  pose_b.translation().x() = 3.0;
  QueryRequest request;
  request.kind = QueryKind::kDistance;
  request.abs_tolerance = 1e-9;
  QueryResult result;
  ASSERT_TRUE(seed->query(a.value(), Pose::Identity(), b.value(), pose_b, request, result).ok());
  EXPECT_NEAR(result.distance.distance, 1.0, 1e-9);
  EXPECT_NEAR(result.distance.point_a.x(), 1.0, 1e-4);
  EXPECT_NEAR(result.distance.point_b.x(), 2.0, 1e-4);
  ASSERT_TRUE(result.distance.params_a && result.distance.params_b);
  ASSERT_TRUE(result.distance.lower && result.distance.upper);
  EXPECT_LE(*result.distance.lower, 1.0 + 1e-12);
  EXPECT_GE(*result.distance.upper, 1.0 - 1e-12);
}

// A kind outside the capabilities (the seed method answers distance only) is unsupported, not
// invalid, at build ("nurbs:hull: the scene needs contacts but the backend answers distance")
// and at query.
TEST_F(SurfaceBuild, BuildNeedingAnUnsupportedQueryIsUnsupported) {
  EXPECT_TRUE(test::hasCodeAndWords(
      seed->build(nurbs::viewOf(zone), BuildNeeds{QueryKind::kContacts, false}),
      StatusCode::kUnsupported, {"nurbs:hull", "contacts"}));
}

TEST_F(SurfaceBuild, AQueryKindTheBackendDoesNotAnswerIsUnsupported) {
  Result<ModelHandle> a = seed->build(nurbs::viewOf(zone), kDistance);
  ASSERT_TRUE(a.ok());
  QueryResult result;
  EXPECT_TRUE(test::hasCodeAndWords(
      seed->query(a.value(), Pose::Identity(), a.value(), Pose::Identity(), QueryRequest{}, result),
      StatusCode::kUnsupported, {"nurbs:hull", "boolean"}));
}

TEST_F(SurfaceBuild, ANonPositiveWeightIsRefusedNamingTheControlPoint) {
  zone.at(1, 2).w() = -1.0;
  EXPECT_TRUE(rejected(seed->build(nurbs::viewOf(zone), kDistance),
                       {"nurbs:hull", "control point (1, 2)", "weight"}));
}

TEST_F(SurfaceBuild, ANonFiniteControlPointIsRefused) {
  zone.at(0, 0).x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(rejected(seed->build(nurbs::viewOf(zone), kDistance),
                       {"control point (0, 0)", "not finite"}));
}

TEST_F(SurfaceBuild, DecreasingKnotsAreRefusedNamingTheVector) {
  zone.knots_v[2] = zone.knots_v[4] + 1.0;
  EXPECT_TRUE(
      rejected(seed->build(nurbs::viewOf(zone), kDistance), {"knots_v[3]", "non-decreasing"}));
}

TEST_F(SurfaceBuild, TooFewControlPointsForTheDegreeAreRefused) {
  zone.degree_u = 5;
  EXPECT_TRUE(rejected(seed->build(nurbs::viewOf(zone), kDistance), {"control points", "degree"}));
}

TEST_F(SurfaceBuild, AnUnclampedKnotVectorIsRefusedByTheBackend) {
  zone.knots_u.front() = -1.0;  // still non-decreasing, no longer clamped
  EXPECT_TRUE(rejected(seed->build(nurbs::viewOf(zone), kDistance), {"knots_u"}));
}

TEST_F(SurfaceBuild, AMeshBackendRefusesSurfacesAndASurfaceBackendMeshes) {
  std::unique_ptr<BackendInstance> obbtree = instanceOf(collido_plugin_table_obbtree(), "obbtree");
  EXPECT_EQ(obbtree->build(nurbs::viewOf(zone), kDistance).status().code(),
            StatusCode::kUnsupported);
  Result<TriangleMesh> sphere = makeSphere(SphereParams{1.0, 8, 4});
  ASSERT_TRUE(sphere.ok());
  EXPECT_TRUE(hasCodeAndWords(seed->build(sphere.value().view(), kDistance),
                              StatusCode::kUnsupported, {"triangle meshes"}));
}

TEST_F(SurfaceBuild, SurfacesDoNotDeform) {
  const BuildNeeds deforming{QueryKindSet(QueryKind::kDistance), true};
  EXPECT_TRUE(hasCodeAndWords(seed->build(nurbs::viewOf(zone), deforming), StatusCode::kUnsupported,
                              {"deform"}));
}

}  // namespace
}  // namespace collido::test
