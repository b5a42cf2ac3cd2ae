// The pose-error sweep: exact without noise, refusals counted with their reason, layouts as
// named, the given layout's counts, and the rigid fit's advantage where the affine one is
// known to be weak (few markers close together).
#include <collido/pose/error_sweep.h>

#include <cmath>

#include <gtest/gtest.h>

#include <collido/mesh/procedural.h>

namespace collido::pose {
namespace {

Eigen::Matrix3Xd torusVertices() {
  TorusParams torus;
  torus.major_segments = 24;
  torus.minor_segments = 12;
  return makeTorus(torus).value().vertices;
}

TEST(ErrorSweep, ExactWithoutNoiseAndRefusalsCounted) {
  ErrorSweepOptions options;
  options.noises = {0.0};
  options.marker_counts = {3, 4};
  options.trials = 20;
  const Result<std::vector<ErrorSweepRow>> rows = runErrorSweep(torusVertices(), options);
  ASSERT_TRUE(rows.ok()) << rows.status().message();
  ASSERT_EQ(rows.value().size(), 2u * 3u * 2u);  // solvers x layouts x counts
  for (const ErrorSweepRow& r : rows.value()) {
    SCOPED_TRACE(std::string(poseSolverName(r.solver)) + " " + layoutKindName(r.layout) + " " +
                 std::to_string(r.markers));
    const bool refused =
        (r.solver == PoseSolver::kAffine && (r.markers < 4 || r.layout == LayoutKind::kPlanar));
    if (refused) {
      EXPECT_EQ(r.failed, r.trials);
      EXPECT_FALSE(r.first_failure.empty());
      EXPECT_TRUE(std::isnan(r.worst_vertex_median));
    } else {
      EXPECT_EQ(r.failed, 0) << r.first_failure;
      EXPECT_LT(r.worst_vertex_p90, 1e-9);
      EXPECT_LT(r.pose_worst_vertex_median, 1e-9);
    }
  }
}

TEST(ErrorSweep, TheRigidFitBeatsTheAffineOnFewCloseMarkers) {
  ErrorSweepOptions options;
  options.layouts = {LayoutKind::kCompact};
  options.marker_counts = {4};
  options.noises = {0.001};
  options.trials = 100;
  const Result<std::vector<ErrorSweepRow>> rows = runErrorSweep(torusVertices(), options);
  ASSERT_TRUE(rows.ok()) << rows.status().message();
  ASSERT_EQ(rows.value().size(), 2u);
  const ErrorSweepRow& rigid = rows.value()[0];
  const ErrorSweepRow& affine = rows.value()[1];
  ASSERT_EQ(rigid.solver, PoseSolver::kRigid);
  EXPECT_GT(affine.worst_vertex_median, 2.0 * rigid.worst_vertex_median);
  // More noise, more error: the same poses with ten times the noise.
  options.noises = {0.01};
  options.solvers = {PoseSolver::kRigid};
  const Result<std::vector<ErrorSweepRow>> noisier = runErrorSweep(torusVertices(), options);
  ASSERT_TRUE(noisier.ok());
  EXPECT_NEAR(noisier.value()[0].worst_vertex_median / rigid.worst_vertex_median, 10.0, 1.0);
}

TEST(ErrorSweep, TheGivenLayoutHasTheMarkersItHas) {
  ErrorSweepOptions options;
  options.layouts = {LayoutKind::kGiven};
  options.solvers = {PoseSolver::kRigid};
  options.marker_counts = {3, 4, 12};
  options.given = {{7, {1, 0, 0}}, {8, {0, 1, 0}}, {9, {0, 0, 0.2}}, {10, {-1, 0, 0}}};
  options.trials = 5;
  const Result<std::vector<ErrorSweepRow>> rows = runErrorSweep(torusVertices(), options);
  ASSERT_TRUE(rows.ok());
  ASSERT_EQ(rows.value().size(), 2u);  // 12 > 4 markers: no row
  EXPECT_EQ(rows.value()[1].markers, 4);
}

TEST(ErrorSweep, BadOptionsAreErrors) {
  ErrorSweepOptions options;
  options.trials = 0;
  EXPECT_FALSE(runErrorSweep(torusVertices(), options).ok());
  EXPECT_FALSE(runErrorSweep(Eigen::Matrix3Xd(3, 0), ErrorSweepOptions{}).ok());
}

}  // namespace
}  // namespace collido::pose
