// GJK between convex point sets (16 random points each, the size of a NURBS patch's control net):
// ours (core/convex) against FCL's two GJK solvers (libccd and its independent one) on the same
// 1,000 separated pairs. Reports the time per query and, against a reference from the hulls'
// faces, how often and by how much each distance exceeds the true one: a distance used as a
// pruning bound must never exceed it, or the pair holding the minimum can be dropped.
//   build/release/bench/collido_gjk_bench --benchmark_repetitions=5
//       --benchmark_report_aggregates_only=true
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

#include <benchmark/benchmark.h>
#include <fcl/geometry/shape/convex.h>
#include <fcl/narrowphase/collision_object.h>
#include <fcl/narrowphase/distance.h>

#include <collido/convex/gjk.h>
#include <collido/oracle/triangle_distance.h>
#include <collido/random/portable_random.h>

namespace collido::bench {
namespace {

constexpr int kPoints = 16;
constexpr int kCases = 1000;

struct Case {
  Eigen::Matrix3Xd a;
  Eigen::Matrix3Xd b;
  std::vector<std::array<int, 3>> faces_a;  // hull triangles, outward
  std::vector<std::array<int, 3>> faces_b;
  double reference = 0.0;  // the hulls' distance, from their faces
  double size = 0.0;       // the pair's extent, the scale of rounding
};

// The hull's faces by brute force (points in general position): a triple is a face when every
// other point lies on one side of its plane; oriented so that side is behind.
std::vector<std::array<int, 3>> hullFaces(const Eigen::Matrix3Xd& p) {
  std::vector<std::array<int, 3>> faces;
  const int n = static_cast<int>(p.cols());
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      for (int k = j + 1; k < n; ++k) {
        const Eigen::Vector3d normal = (p.col(j) - p.col(i)).cross(p.col(k) - p.col(i));
        int above = 0;
        int below = 0;
        for (int m = 0; m < n; ++m) {
          if (m == i || m == j || m == k) continue;
          const double side = normal.dot(p.col(m) - p.col(i));
          (side > 0.0 ? above : below) += 1;
        }
        if (above == 0) faces.push_back({i, j, k});
        if (below == 0) faces.push_back({i, k, j});
      }
    }
  }
  return faces;
}

double hullDistance(const Case& c) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& fa : c.faces_a) {
    const std::array<Eigen::Vector3d, 3> ta{c.a.col(fa[0]), c.a.col(fa[1]), c.a.col(fa[2])};
    for (const auto& fb : c.faces_b) {
      const std::array<Eigen::Vector3d, 3> tb{c.b.col(fb[0]), c.b.col(fb[1]), c.b.col(fb[2])};
      const TriangleClosestPoints closest = closestPointsOfTriangles(ta, tb);
      best = std::min(best, closest.distance);
    }
  }
  return best;
}

// Pairs of 16-point sets in cubes of side 2, B moved along a random direction until their
// bounding spheres are 1e-3 to 1 apart (so the hulls are separated, often by much more).
const std::vector<Case>& cases() {
  static const std::vector<Case> all = [] {
    PortableRandom random(20261124);
    std::vector<Case> out;
    for (int trial = 0; trial < kCases; ++trial) {
      Case c;
      c.a.resize(3, kPoints);
      c.b.resize(3, kPoints);
      for (int i = 0; i < kPoints; ++i) {
        for (int r = 0; r < 3; ++r) {
          c.a(r, i) = random.uniform(-1.0, 1.0);
          c.b(r, i) = random.uniform(-1.0, 1.0);
        }
      }
      const double radius_a = c.a.colwise().norm().maxCoeff();
      const double radius_b = c.b.colwise().norm().maxCoeff();
      const Eigen::Vector3d offset =
          random.direction() * (radius_a + radius_b + std::pow(10.0, random.uniform(-3.0, 0.0)));
      c.b.colwise() += offset;
      c.faces_a = hullFaces(c.a);
      c.faces_b = hullFaces(c.b);
      c.reference = hullDistance(c);
      c.size = offset.norm() + radius_a + radius_b;
      out.push_back(std::move(c));
    }
    return out;
  }();
  return all;
}

// How often and how far the answers exceed the reference (beyond 1e-12 of the size).
struct Accuracy {
  int over = 0;
  double worst_over = 0.0;  // relative to the reference
  int under = 0;            // below the reference: a distance that is not one
  void add(double answer, const Case& c) {
    const double rounding = 1e-12 * c.size;
    if (answer > c.reference + rounding) {
      ++over;
      worst_over = std::max(worst_over, (answer - c.reference) / c.reference);
    }
    if (answer < c.reference - rounding) ++under;
  }
  void report(benchmark::State& state) const {
    state.counters["cases"] = kCases;
    state.counters["over_share"] = static_cast<double>(over) / kCases;
    state.counters["worst_over_rel"] = worst_over;
    state.counters["under"] = under;
  }
};

void oursBenchmark(benchmark::State& state, bool use_lower_bound) {
  const std::vector<Case>& all = cases();
  Accuracy accuracy;
  bool measured = false;
  for (auto _ : state) {
    for (const Case& c : all) {
      const convex::PointSetSupport sa(c.a);
      const convex::PointSetSupport sb(c.b);
      const convex::GjkResult r = convex::gjkDistance(sa, sb);
      benchmark::DoNotOptimize(r.distance);
      if (!measured) accuracy.add(use_lower_bound ? r.lower_bound : r.distance, c);
    }
    measured = true;
  }
  accuracy.report(state);
  state.counters["per_query"] = benchmark::Counter(
      kCases, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

std::shared_ptr<fcl::CollisionGeometryd> fclConvex(const Eigen::Matrix3Xd& points,
                                                   const std::vector<std::array<int, 3>>& faces) {
  auto vertices = std::make_shared<std::vector<fcl::Vector3d>>();
  for (Eigen::Index i = 0; i < points.cols(); ++i)
    vertices->push_back(points.col(i));
  auto polygons = std::make_shared<std::vector<int>>();
  for (const auto& f : faces)
    polygons->insert(polygons->end(), {3, f[0], f[1], f[2]});
  return std::make_shared<fcl::Convexd>(vertices, static_cast<int>(faces.size()), polygons);
}

void fclBenchmark(benchmark::State& state, fcl::GJKSolverType solver, double tolerance) {
  const std::vector<Case>& all = cases();
  // One object pair per case, at addresses that stay put.
  std::vector<
      std::pair<std::unique_ptr<fcl::CollisionObjectd>, std::unique_ptr<fcl::CollisionObjectd>>>
      objects;
  objects.reserve(all.size());
  for (const Case& c : all)
    objects.emplace_back(std::make_unique<fcl::CollisionObjectd>(fclConvex(c.a, c.faces_a)),
                         std::make_unique<fcl::CollisionObjectd>(fclConvex(c.b, c.faces_b)));
  fcl::DistanceRequestd request;
  request.gjk_solver_type = solver;
  request.distance_tolerance = tolerance;
  Accuracy accuracy;
  bool measured = false;
  for (auto _ : state) {
    for (std::size_t k = 0; k < all.size(); ++k) {
      fcl::DistanceResultd result;
      // The returned distance: reading result.min_distance after a call whose return value
      // was dropped gave garbage at -O3 here (FCL 0.7.0, GCC 12), so the figure is taken from
      // the return value, which is min_distance too.
      const double returned =
          fcl::distance(objects[k].first.get(), objects[k].second.get(), request, result);
      benchmark::DoNotOptimize(returned);
      if (!measured) accuracy.add(returned, all[k]);
    }
    measured = true;
  }
  accuracy.report(state);
  state.counters["per_query"] = benchmark::Counter(
      kCases, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

BENCHMARK_CAPTURE(oursBenchmark, ours_distance, false)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(oursBenchmark, ours_lower_bound, true)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(fclBenchmark, fcl_libccd_tol_1e - 6, fcl::GST_LIBCCD, 1e-6)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(fclBenchmark, fcl_indep_tol_1e - 6, fcl::GST_INDEP, 1e-6)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(fclBenchmark, fcl_libccd_tol_1e - 12, fcl::GST_LIBCCD, 1e-12)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(fclBenchmark, fcl_indep_tol_1e - 12, fcl::GST_INDEP, 1e-12)
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace collido::bench

BENCHMARK_MAIN();
