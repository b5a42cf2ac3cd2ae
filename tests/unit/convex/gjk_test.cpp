// Our GJK against brute-force hull distances, Coal's capsule/sphere cases, and degenerate and
// near-touching inputs: the distance within tolerance of the truth, the lower bound never above
// it, the witnesses in the sets and the distance apart.
#include <deque>
#include <fstream>
#include <random>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <collido/convex/gjk.h>
#include <collido/oracle/triangle_distance.h>

#include "support/test_paths.h"

namespace collido::convex {
namespace {

// The distance between the hulls of two separated point sets: the smallest distance between
// their hull faces, found by brute force (a triangle of the points is a face when every point
// lies on one side of it; points in general position).
std::vector<std::array<Eigen::Vector3d, 3>> hullFaces(const Eigen::Matrix3Xd& p) {
  std::vector<std::array<Eigen::Vector3d, 3>> out;
  const Eigen::Index n = p.cols();
  if (n < 3) {
    for (Eigen::Index i = 0; i < n; ++i) {
      for (Eigen::Index j = i; j < n; ++j)
        out.push_back({p.col(i), p.col(j), p.col(j)});
    }
    return out;
  }
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index j = i + 1; j < n; ++j) {
      for (Eigen::Index k = j + 1; k < n; ++k) {
        const Eigen::Vector3d normal = (p.col(j) - p.col(i)).cross(p.col(k) - p.col(i));
        const Eigen::VectorXd side = normal.transpose() * (p.colwise() - p.col(i));
        const double slack = 1e-12 * normal.norm();
        if (side.maxCoeff() <= slack || side.minCoeff() >= -slack)
          out.push_back({p.col(i), p.col(j), p.col(k)});
      }
    }
  }
  return out;
}

double bruteForce(const Eigen::Matrix3Xd& a, const Eigen::Matrix3Xd& b) {
  double best = std::numeric_limits<double>::infinity();
  const auto faces_b = hullFaces(b);
  for (const auto& ta : hullFaces(a)) {
    for (const auto& tb : faces_b)
      best = std::min(best, closestPointsOfTriangles(ta, tb).distance);
  }
  return best;
}

// Whether p lies in the hull of `points` (within slack): no direction separates it.
bool inHull(const Eigen::Vector3d& p, const Eigen::Matrix3Xd& points, double slack) {
  std::mt19937_64 rng(1);
  std::normal_distribution<double> n;
  for (int k = 0; k < 200; ++k) {
    const Eigen::Vector3d d = Eigen::Vector3d(n(rng), n(rng), n(rng)).normalized();
    if (d.dot(p) > (d.transpose() * points).maxCoeff() + slack) return false;
  }
  return true;
}

Eigen::Matrix3Xd randomSet(std::mt19937_64& rng, int count, const Eigen::Vector3d& lo,
                           const Eigen::Vector3d& hi) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Eigen::Matrix3Xd p(3, count);
  for (int c = 0; c < count; ++c) {
    for (int k = 0; k < 3; ++k)
      p(k, c) = lo[k] + (hi[k] - lo[k]) * u(rng);
  }
  return p;
}

TEST(Gjk, MatchesBruteForceOnRandomSeparatedSets) {
  std::mt19937_64 rng(11);
  int checked = 0;
  int lower_above = 0;
  double worst = 0.0;
  for (int trial = 0; trial < 400; ++trial) {
    const double gap = trial % 4 == 0 ? 1e-9 : 0.05 * (trial % 7);
    const Eigen::Matrix3Xd a = randomSet(rng, 3 + trial % 5, {-1, -1, -1}, {0, 1, 1});
    const Eigen::Matrix3Xd b = randomSet(rng, 3 + trial % 6, {gap, -1, -1}, {gap + 1, 1, 1});
    const PointSetSupport sa(a);
    const PointSetSupport sb(b);
    GjkOptions options;
    options.abs_tolerance = 1e-12;
    const GjkResult r = gjkDistance(sa, sb, options);
    const double truth = bruteForce(a, b);
    ++checked;
    if (r.lower_bound > truth + 1e-15) ++lower_above;
    worst = std::max(worst, r.distance - truth);
    EXPECT_LE(r.lower_bound, truth + 1e-15) << "trial " << trial;
    EXPECT_NEAR(r.distance, truth, 1e-9) << "trial " << trial;
    EXPECT_NEAR((r.point_a - r.point_b).norm(), r.distance, 1e-12) << "trial " << trial;
    EXPECT_TRUE(inHull(r.point_a, a, 1e-12)) << "trial " << trial;
    EXPECT_TRUE(inHull(r.point_b, b, 1e-12)) << "trial " << trial;
  }
  std::cout << checked << " cases, lower bound above the truth in " << lower_above
            << ", worst distance - truth " << worst << "\n";
}

// The lower bound is what a pruning search relies on: over many 16-point sets at random
// poses, it never exceeds the true distance (checked by brute force on the same sets).
TEST(Gjk, TheLowerBoundNeverExceedsTheTruthOnSixteenPointSets) {
  std::mt19937_64 rng(29);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int above = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const Eigen::Matrix3Xd a = randomSet(rng, 16, {-1, -1, -1}, {1, 1, 1});
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear() =
        Eigen::Quaterniond(u(rng), u(rng), u(rng), u(rng)).normalized().toRotationMatrix();
    pose.translation() = Eigen::Vector3d(2.5 + 1.5 * u(rng), u(rng), u(rng));
    const Eigen::Matrix3Xd b = pose * randomSet(rng, 16, {-1, -1, -1}, {1, 1, 1});
    const GjkResult r = gjkDistance(PointSetSupport(a), PointSetSupport(b));
    if (r.intersecting) continue;
    const double truth = bruteForce(a, b);
    above += r.lower_bound > truth ? 1 : 0;
    EXPECT_NEAR(r.distance, truth, 1e-9 * (1 + truth)) << "trial " << trial;
  }
  EXPECT_EQ(above, 0);
}

TEST(Gjk, DegenerateSetsPointsSegmentsAndRepeats) {
  Eigen::Matrix3Xd point(3, 1);
  point << 0, 0, 2;
  Eigen::Matrix3Xd segment(3, 4);  // repeated and collinear points
  segment << -1, 1, 1, 0,          //
      0, 0, 0, 0,                  //
      0, 0, 0, 0;
  Eigen::Matrix3Xd square(3, 4);  // coplanar
  square << -1, 1, 1, -1,         //
      -1, -1, 1, 1,               //
      0.5, 0.5, 0.5, 0.5;
  EXPECT_NEAR(gjkDistance(PointSetSupport(point), PointSetSupport(segment)).distance, 2.0, 1e-15);
  EXPECT_NEAR(gjkDistance(PointSetSupport(point), PointSetSupport(square)).distance, 1.5, 1e-15);
  EXPECT_NEAR(gjkDistance(PointSetSupport(segment), PointSetSupport(square)).distance, 0.5, 1e-15);
  // The same set twice: intersecting.
  EXPECT_TRUE(gjkDistance(PointSetSupport(square), PointSetSupport(square)).intersecting);
  // Parallel squares: every point pair of the overlap is closest.
  Eigen::Matrix3Xd lifted = square;
  lifted.row(2).array() += 1e-3;
  const GjkResult parallel = gjkDistance(PointSetSupport(square), PointSetSupport(lifted));
  EXPECT_NEAR(parallel.distance, 1e-3, 1e-15);
  EXPECT_LE(parallel.lower_bound, 1e-3);
}

TEST(Gjk, NearlyTouchingFarFromTheOrigin) {
  const Eigen::Vector3d far(1e6, -2e6, 5e5);
  Eigen::Matrix3Xd cube(3, 8);
  for (int c = 0; c < 8; ++c)
    cube.col(c) = Eigen::Vector3d(c & 1, (c >> 1) & 1, (c >> 2) & 1);
  for (const double gap : {1e-3, 1e-6, 1e-9}) {
    Eigen::Isometry3d a = Eigen::Isometry3d::Identity();
    a.translation() = far;
    Eigen::Isometry3d b = a;
    b.translation().x() += 1.0 + gap;
    const GjkResult r = gjkDistance(PointSetSupport(cube, a), PointSetSupport(cube, b));
    // Coordinates near 2e6 carry 4.7e-10 of rounding each.
    EXPECT_NEAR(r.distance, gap, 2e-9) << gap;
    EXPECT_LE(r.lower_bound, gap + 1e-9) << gap;
  }
}

// Coal's capsule–triangle and sphere–sphere cases (tests/data/peer_cases/coal_gjk_shapes.json):
// a capsule is a segment inflated by its radius, a sphere a point inflated by its radius plus
// the swept-sphere radius.
TEST(Gjk, CoalCapsuleAndSphereCases) {
  std::ifstream in(test::sourcePath("tests/data/peer_cases/coal_gjk_shapes.json"));
  const nlohmann::json cases = nlohmann::json::parse(in)["cases"];
  ASSERT_EQ(cases.size(), 17u);
  const auto vec = [](const nlohmann::json& j) {
    return Eigen::Vector3d(j[0].get<double>(), j[1].get<double>(), j[2].get<double>());
  };
  for (const nlohmann::json& c : cases) {
    const std::string id = c["id"];
    const nlohmann::json& expected = c["expected"];
    double ssr = 0.0;
    if (id.find("_ssr") != std::string::npos) {
      ssr = std::stod(
          id.substr(id.find("_ssr") + 4, id.find("_c", id.find("_ssr")) - id.find("_ssr") - 4));
    }
    std::deque<Eigen::Matrix3Xd> cores;  // the supports refer to them: they must stay put
    std::vector<std::unique_ptr<PointSetSupport>> shapes;
    Eigen::Vector3d triangle_shift = Eigen::Vector3d::Zero();
    for (const nlohmann::json& s : c["shapes"]) {
      const Eigen::Vector3d t = vec(s["t"]);
      Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
      pose.translation() = t;
      const std::string type = s["type"];
      if (type == "capsule") {
        Eigen::Matrix3Xd& core = cores.emplace_back(3, 2);
        const double half = 0.5 * s["length"].get<double>();
        core << 0, 0, 0, 0, -half, half;
        shapes.push_back(std::make_unique<PointSetSupport>(core, pose, s["radius"].get<double>()));
      } else if (type == "sphere") {
        const Eigen::Matrix3Xd& core = cores.emplace_back(Eigen::Matrix3Xd::Zero(3, 1));
        shapes.push_back(
            std::make_unique<PointSetSupport>(core, pose, s["radius"].get<double>() + ssr));
      } else {
        Eigen::Matrix3Xd& core = cores.emplace_back(3, 3);
        for (int k = 0; k < 3; ++k)
          core.col(k) = vec(s["vertices_local"][k]);
        shapes.push_back(std::make_unique<PointSetSupport>(core, pose));
        triangle_shift = t;
      }
    }
    const GjkResult r = gjkDistance(*shapes[0], *shapes[1]);
    EXPECT_EQ(r.intersecting, expected["collision"].get<bool>()) << id;
    if (expected["collision"].get<bool>()) continue;
    const double tolerance = expected["tolerance"].get<double>();
    const double distance = expected.contains("signed_distance")
                                ? expected["signed_distance"].get<double>()
                                : expected["implied_signed_distance"].get<double>();
    EXPECT_NEAR(r.distance, distance, tolerance) << id;
    EXPECT_LE(r.lower_bound, distance + tolerance) << id;
    EXPECT_LT((r.point_a - vec(expected["w0"])).norm(), tolerance) << id;
    const Eigen::Vector3d w1 = expected.contains("w1")
                                   ? vec(expected["w1"])
                                   : vec(expected["w1_minus_T"]) + triangle_shift;
    EXPECT_LT((r.point_b - w1).norm(), tolerance) << id;
  }
}

}  // namespace
}  // namespace collido::convex
