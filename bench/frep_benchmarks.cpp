// The FRep seed method's guaranteed collision test across shapes and orientations:
//   frep_collision/<pair>/<precision>
// Each iteration runs the test on 32 seeded orientations of the second solid (turned about its
// centre, near contact with the first). Counters: the octree's cells per query (median, p90 and
// the largest over the orientations), its depth, the verdicts, and the spread of one query's time
// over the orientations (µs, last iteration). The seed claims a step count bounded by the
// precision whatever the shapes; the cells show the bound holds, the time adds each shape's cost
// per evaluation (a blob with 300 bumps evaluates 300 bumps per cell).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include <collido/frep/collision.h>

namespace collido::bench {
namespace {

using frep::SolidPtr;

constexpr int kOrientations = 32;

SolidPtr blob(int bumps, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<frep::Bump> list;
  for (int i = 0; i < bumps; ++i) {
    Eigen::Vector3d direction(unit(random), unit(random), unit(random));
    direction = direction.norm() > 1e-3 ? direction.normalized() : Eigen::Vector3d::UnitX();
    const double radius = 0.6 / std::sqrt(1.0 + bumps / 10.0);
    list.push_back({0.6 * direction, radius, 0.15 * (0.5 + 0.5 * unit(random))});
  }
  return frep::perturbed(frep::sphere(Eigen::Vector3d::Zero(), 0.6), list);
}

struct SolidPair {
  std::string name;
  SolidPtr a;
  SolidPtr b;             // centred at the origin; turned, then moved to `place`
  Eigen::Vector3d place;  // near contact with a
};

SolidPair makePair(int which) {
  switch (which) {
    case 0:
      return {"spheres", frep::sphere(Eigen::Vector3d::Zero(), 1.0),
              frep::sphere(Eigen::Vector3d::Zero(), 0.5), Eigen::Vector3d(1.51, 0.0, 0.0)};
    case 1: {
      Eigen::Matrix3d a = Eigen::Vector3d(-1.0, -2.04, -4.0).asDiagonal();
      return {"quadric_3_bumps",
              frep::perturbed(
                  frep::quadric(a, Eigen::Vector3d::Zero(), 1.0),
                  {{{0, 0, -0.5}, 0.4, 1.2}, {{0, 0, 0.5}, 0.3, -0.5}, {{1, 0, 0}, 0.3, 0.5}}),
              frep::block(Eigen::Vector3d::Zero(), Eigen::Vector3d(0.3, 0.3, 0.1)),
              Eigen::Vector3d(0.0, 0.0, -0.85)};
    }
    case 2:
      return {"blob_30_bumps", frep::torus(Eigen::Vector3d::Zero(), 1.2, 0.3), blob(30, 3),
              Eigen::Vector3d::Zero()};
    case 3:
      return {"blob_300_bumps", frep::torus(Eigen::Vector3d::Zero(), 1.2, 0.3), blob(300, 3),
              Eigen::Vector3d::Zero()};
    default:
      return {"twisted_bar_ring", frep::torus(Eigen::Vector3d(0.01, 0, 0), 1.0, 0.2),
              frep::twisted(frep::block(Eigen::Vector3d::Zero(), Eigen::Vector3d(0.55, 0.55, 1.5)),
                            1.0),
              Eigen::Vector3d::Zero()};
  }
}

double quantileOf(std::vector<double> values, double q) {
  std::sort(values.begin(), values.end());
  return values[static_cast<std::size_t>(std::lround(q * static_cast<double>(values.size() - 1)))];
}

void collisionBenchmark(benchmark::State& state, int which, double precision) {
  const SolidPair pair = makePair(which);
  std::mt19937_64 random(20261124);
  std::vector<SolidPtr> turned;
  for (int i = 0; i < kOrientations; ++i) {
    // Uniform rotations: normalised Gaussian quaternions from the seeded generator.
    std::normal_distribution<double> gauss;
    const Eigen::Quaterniond q =
        Eigen::Quaterniond(gauss(random), gauss(random), gauss(random), gauss(random)).normalized();
    Eigen::Affine3d pose = Eigen::Affine3d::Identity();
    pose.translate(pair.place);
    pose.rotate(q);
    turned.push_back(frep::transformed(pair.b, pose));
  }
  frep::CollisionOptions options;
  options.precision = precision;
  std::vector<double> cells(kOrientations);
  std::vector<double> micros(kOrientations);
  int colliding = 0;
  int touching = 0;
  int max_depth = 0;
  for (auto _ : state) {
    colliding = touching = 0;
    for (int i = 0; i < kOrientations; ++i) {
      const auto start = std::chrono::steady_clock::now();
      const frep::CollisionResult result = frep::collide(*pair.a, *turned[i], options);
      micros[i] =
          std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start)
              .count();
      cells[i] = static_cast<double>(result.cells);
      max_depth = result.max_depth;
      colliding += result.verdict == frep::CollisionVerdict::kColliding ? 1 : 0;
      touching += result.verdict == frep::CollisionVerdict::kTouching ? 1 : 0;
      benchmark::DoNotOptimize(result.witness);
    }
  }
  state.counters["queries"] = kOrientations;
  state.counters["cells_p50"] = quantileOf(cells, 0.5);
  state.counters["cells_p90"] = quantileOf(cells, 0.9);
  state.counters["cells_max"] = quantileOf(cells, 1.0);
  state.counters["depth"] = max_depth;
  state.counters["colliding"] = colliding;
  state.counters["touching"] = touching;
  state.counters["us_p50"] = quantileOf(micros, 0.5);
  state.counters["us_p90"] = quantileOf(micros, 0.9);
  state.counters["us_max"] = quantileOf(micros, 1.0);
}

[[maybe_unused]] const bool frep_registered = [] {
  for (int which = 0; which < 5; ++which) {
    for (const double precision : {1e-2, 1e-3}) {
      const std::string name =
          "frep_collision/" + makePair(which).name + "/" + (precision == 1e-2 ? "1e-2" : "1e-3");
      benchmark::RegisterBenchmark(name.c_str(), [which, precision](benchmark::State& state) {
        collisionBenchmark(state, which, precision);
      })->Unit(benchmark::kMillisecond);
    }
  }
  return true;
}();

}  // namespace
}  // namespace collido::bench
