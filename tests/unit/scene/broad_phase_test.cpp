// The shared broad phase of group queries: conservative against the exact oracle (a pair it
// culls never intersects, exactly touching pairs included), ordered, and a group query run end
// to end through the runner with the OBB tree matching the oracle pair for pair.
#include <collido/scene/broad_phase.h>

#include <random>
#include <set>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include <collido/mesh/procedural.h>
#include <collido/oracle/exact_oracle.h>
#include <collido/runner/runner.h>

#include "support/runs/run_plugin.h"

namespace collido {
namespace {

using PairList = std::vector<std::pair<std::size_t, std::size_t>>;

std::shared_ptr<const TriangleMesh> sphere(double radius, int slices, int stacks) {
  Result<TriangleMesh> mesh = makeSphere(SphereParams{radius, slices, stacks});
  EXPECT_TRUE(mesh.ok());
  return std::make_shared<const TriangleMesh>(std::move(mesh).value());
}

std::shared_ptr<const TriangleMesh> torus() {
  Result<TriangleMesh> mesh = makeTorus(TorusParams{0.5, 0.15, 16, 8});
  EXPECT_TRUE(mesh.ok());
  return std::make_shared<const TriangleMesh>(std::move(mesh).value());
}

// A scene of `count` objects (spheres and tori alternating) at random poses in a box of side
// `spread`, `frames` frames, with one group query over all of them.
Scene randomPile(std::size_t count, std::size_t frames, double spread, unsigned seed) {
  Scene scene;
  scene.name = "random_pile";
  scene.frames = frames;
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> position(0.0, spread);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const auto shapes = std::vector<std::shared_ptr<const TriangleMesh>>{sphere(0.4, 12, 6), torus()};
  for (std::size_t i = 0; i < count; ++i) {
    SceneObject object;
    object.name = "o" + std::to_string(i);
    object.mesh = shapes[i % shapes.size()];
    for (std::size_t f = 0; f < frames; ++f) {
      const Eigen::Quaterniond q =
          Eigen::Quaterniond(unit(random), unit(random), unit(random), unit(random)).normalized();
      Pose pose = Pose::Identity();
      pose.linear() = q.toRotationMatrix();
      pose.translation() = Eigen::Vector3d(position(random), position(random), position(random));
      object.poses.push_back(pose);
    }
    scene.objects.push_back(object);
  }
  SceneQuery query;
  query.name = "all";
  query.request.kind = QueryKind::kAllPairs;
  for (std::size_t i = 0; i < count; ++i)
    query.among.push_back(i);
  scene.queries.push_back(query);
  return scene;
}

TEST(BroadPhase, NeverCullsAnIntersectingPair) {
  const Scene scene = randomPile(16, 4, 2.5, 7);
  const BroadPhase broad_phase(scene, scene.queries[0]);
  std::size_t intersecting = 0;
  for (std::size_t f = 0; f < scene.frames; ++f) {
    const PairList candidates = broad_phase.pairsAt(f);
    const std::set<std::pair<std::size_t, std::size_t>> passed(candidates.begin(),
                                                               candidates.end());
    EXPECT_EQ(passed.size(), candidates.size()) << "a pair is listed twice";
    EXPECT_TRUE(std::is_sorted(candidates.begin(), candidates.end()));
    EXPECT_LT(candidates.size(), 16u * 15u / 2u) << "the broad phase culled nothing";
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
      for (std::size_t j = i + 1; j < scene.objects.size(); ++j) {
        const SceneObject& a = scene.objects[i];
        const SceneObject& b = scene.objects[j];
        const bool truth = exactIntersectingPairs(*a.mesh, a.poseAt(f), *b.mesh, b.poseAt(f),
                                                  OracleMode::kFirstPair)
                               .intersecting;
        intersecting += truth ? 1 : 0;
        if (truth) {
          EXPECT_TRUE(passed.count({i, j})) << "frame " << f << ": culled " << i << "-" << j;
        }
      }
    }
  }
  EXPECT_GT(intersecting, 0u) << "the test pile has no contact to check";
}

// A tetrahedron with its apex at the origin, opening towards -x (side = -1) or +x (side = 1).
std::shared_ptr<const TriangleMesh> tetrahedron(double side) {
  TriangleMesh mesh;
  mesh.vertices.resize(3, 4);
  mesh.vertices << 0, side, side, side,  //
      0, 1, -1, 0,                       //
      0, 0, 0, 1;
  mesh.triangles.resize(3, 4);
  mesh.triangles << 0, 0, 0, 1,  //
      1, 2, 3, 2,                //
      2, 3, 1, 3;
  return std::make_shared<const TriangleMesh>(mesh);
}

// Two tetrahedra touching apex to apex only, far from the origin: their boxes touch in one
// face plane, and the pair must pass.
TEST(BroadPhase, KeepsAnExactlyTouchingPair) {
  Scene scene;
  scene.frames = 1;
  for (double side : {-1.0, 1.0}) {
    SceneObject object;
    object.mesh = tetrahedron(side);
    Pose pose = Pose::Identity();
    pose.translation() = Eigen::Vector3d(1e6, 0.0, 0.0);
    object.poses = {pose};
    scene.objects.push_back(object);
  }
  const SceneObject& a = scene.objects[0];
  const SceneObject& b = scene.objects[1];
  ASSERT_TRUE(exactIntersectingPairs(*a.mesh, a.poseAt(0), *b.mesh, b.poseAt(0)).intersecting);
  SceneQuery query;
  query.among = {0, 1};
  EXPECT_EQ(BroadPhase(scene, query).pairsAt(0), (PairList{{0, 1}}));
}

TEST(BroadPhase, CullsSeparatedObjectsAndReportsOverlapsOnce) {
  Scene scene;
  scene.frames = 1;
  for (double x : {0.0, 1.5, 10.0}) {  // 0 and 1 overlap, 2 is far away
    SceneObject object;
    object.mesh = sphere(1.0, 8, 4);
    Pose pose = Pose::Identity();
    pose.translation() = Eigen::Vector3d(x, 0.0, 0.0);
    object.poses = {pose};
    scene.objects.push_back(object);
  }
  SceneQuery query;
  query.among = {0, 1, 2};
  EXPECT_EQ(BroadPhase(scene, query).pairsAt(0), (PairList{{0, 1}}));
  query.among = {0, 2};
  EXPECT_TRUE(BroadPhase(scene, query).pairsAt(0).empty());
  // An object that does not exist in the frame (scene key "frames") is in no pair.
  scene.objects[1].present.ranges = {{1, 1}};
  query.among = {0, 1, 2};
  EXPECT_TRUE(BroadPhase(scene, query).pairsAt(0).empty());
}

// The runner asks the backend every candidate pair and sums the answers: the exact OBB tree
// matches the oracle on every frame, and each frame records how many object pairs it asked.
TEST(GroupQuery, TheObbTreeMatchesTheOracleOnARandomPile) {
  Scene scene = randomPile(12, 3, 2.0, 11);
  const RunReport report = test::runPlugin(scene, "obbtree", "obbtree", test::repeated(1));
  ASSERT_EQ(report.measurements.size(), 1u);
  const QueryMeasurement& m = report.measurements[0];
  ASSERT_TRUE(m.ok()) << m.status;
  ASSERT_EQ(m.frames.size(), scene.frames);
  EXPECT_EQ(m.disagreements, 0u);
  const BroadPhase broad_phase(scene, scene.queries[0]);
  std::size_t pairs = 0;
  for (const FrameRecord& f : m.frames) {
    EXPECT_EQ(f.object_pairs, broad_phase.pairsAt(f.frame).size());
    EXPECT_EQ(f.matched_pairs, f.oracle_pairs);
    EXPECT_EQ(f.reported_pairs, f.oracle_pairs);
    pairs += f.oracle_pairs;
  }
  EXPECT_GT(pairs, 0u);
  std::size_t triangles = 0;
  for (const SceneObject& o : scene.objects)
    triangles += o.mesh->triangleCount();
  EXPECT_EQ(m.triangles, triangles);
}

}  // namespace
}  // namespace collido
