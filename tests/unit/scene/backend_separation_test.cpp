// Clearance constraints through a backend's distance query (BackendSeparation): the placement
// the solve finds, checked with the exact oracle's distance; a start in overlap refused; and a
// backend without distances refused.
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include <collido/constraints/backend_separation.h>
#include <collido/constraints/solve.h>
#include <collido/host/plugin_library.h>
#include <collido/mesh/procedural.h>
#include <collido/oracle/distance_oracle.h>

#include "support/test_paths.h"

namespace collido {
namespace {

using namespace constraints;

std::unique_ptr<BackendInstance> backend(const std::string& plugin, const std::string& variant) {
  Result<std::shared_ptr<PluginLibrary>> library =
      PluginLibrary::open(test::pluginDirectory() + "/libcollido_plugin_" + plugin + ".so");
  EXPECT_TRUE(library.ok()) << library.status().message();
  if (!library.ok()) return nullptr;
  Result<std::unique_ptr<BackendInstance>> instance =
      BackendInstance::create(library.value(), variant);
  EXPECT_TRUE(instance.ok()) << instance.status().message();
  return instance.ok() ? std::move(instance.value()) : nullptr;
}

std::shared_ptr<const TriangleMesh> sphere(double radius) {
  SphereParams params;
  params.radius = radius;
  params.slices = 24;
  params.stacks = 12;
  return std::make_shared<const TriangleMesh>(makeSphere(params).value());
}

/// Sphere b held on the x axis and `clearance` from fixed sphere a, starting at x = `start`;
/// returns the exact distance where the solve put it.
double placeThrough(BackendInstance& instance, double start, double clearance) {
  const std::vector<std::shared_ptr<const TriangleMesh>> meshes = {sphere(1.0), sphere(0.5)};
  Result<std::unique_ptr<BackendSeparation>> query = BackendSeparation::create(instance, meshes);
  EXPECT_TRUE(query.ok()) << query.status().message();
  if (!query.ok()) return -1.0;
  Problem problem(1.0);
  Pose b_pose = Pose::Identity();
  b_pose.translation() = Eigen::Vector3d(start, 0.15, -0.1);
  const int a = problem.addBody("a", Pose::Identity(), 1.0).value();
  const int b = problem.addBody("b", b_pose, 0.5).value();
  EXPECT_TRUE(problem.fixBody(a).ok());
  EXPECT_TRUE(problem
                  .addPointOnLine("on axis", PointRef{b, Eigen::Vector3d::Zero()},
                                  Axis{PointRef{kWorld, Eigen::Vector3d::Zero()},
                                       DirectionRef{kWorld, Eigen::Vector3d::UnitX()}})
                  .ok());
  EXPECT_TRUE(problem.addClearance("gap", a, b, Target{clearance}).ok());
  problem.setSeparationQuery(std::move(query.value()));
  const Result<SolveReport> report = solve(problem);
  EXPECT_TRUE(report.ok()) << report.status().message();
  if (!report.ok()) return -1.0;
  return exactMeshDistance(*meshes[0], problem.bodies()[a].pose, *meshes[1],
                           problem.bodies()[b].pose)
      .distance;
}

TEST(BackendSeparation, TheObbTreesDistancePlacesExactly) {
  const auto instance = backend("obbtree", "obbtree");
  ASSERT_NE(instance, nullptr);
  EXPECT_NEAR(placeThrough(*instance, 2.4, 0.25), 0.25, 1e-12);
}

#ifdef COLLIDO_HAS_FCL
TEST(BackendSeparation, FclsDistancePlacesToItsPrecision) {
  const auto instance = backend("fcl", "fcl:obbrss");
  ASSERT_NE(instance, nullptr);
  EXPECT_NEAR(placeThrough(*instance, 2.4, 0.25), 0.25, 1e-12);
}
#endif

TEST(BackendSeparation, ABodyWithoutAMeshIsRefusedWhenMeasured) {
  const auto instance = backend("obbtree", "obbtree");
  ASSERT_NE(instance, nullptr);
  // Meshless bodies are fine until a clearance names them.
  Result<std::unique_ptr<BackendSeparation>> query =
      BackendSeparation::create(*instance, {sphere(1.0), nullptr});
  ASSERT_TRUE(query.ok());
  const Result<Separation> measured =
      query.value()->measure(0, Pose::Identity(), 1, Pose::Identity());
  ASSERT_FALSE(measured.ok());
  EXPECT_NE(measured.status().message().find("without a mesh"), std::string::npos);
}

#ifdef COLLIDO_HAS_ODE
TEST(BackendSeparation, ABackendWithoutDistancesIsRefused) {
  const auto instance = backend("ode", "ode");
  ASSERT_NE(instance, nullptr);
  const Result<std::unique_ptr<BackendSeparation>> query =
      BackendSeparation::create(*instance, {sphere(1.0), sphere(0.5)});
  ASSERT_FALSE(query.ok());
  EXPECT_EQ(query.status().message(),
            "ode does not answer distance queries, which clearances need");
}
#endif

}  // namespace
}  // namespace collido
