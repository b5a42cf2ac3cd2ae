// The seed method's certified distance between NURBS surfaces, to 1e-6 of the model's size:
//   nurbs_distance/<case>/<hull|box>        with the descent refining the upper bound;
//   nurbs_distance/<case>/<hull|box>/seed   corners only, as the seed method was published.
// Counters: patch pairs bounded and opened, levels, the certified gap upper - lower, and whether
// it met the tolerance within 200,000 bounded pairs (boxes often do not: their bound is loose by
// the patch size, the hull's by its square).
#include <string>

#include <benchmark/benchmark.h>

#include <collido/nurbs/surface_distance.h>
#include <collido/nurbs/surface_generators.h>

namespace collido::bench {
namespace {

using nurbs::NurbsSurface;

struct SurfacePair {
  const char* name;
  NurbsSurface a;
  NurbsSurface b;
  double size;  // of the model, for the tolerance
};

SurfacePair makeSurfacePair(int which) {
  switch (which) {
    case 0:  // the seed's experiment: two convex patches facing each other
      return {"sphere_zones", nurbs::sphereZone(Eigen::Vector3d::Zero(), 1.0, -45.0),
              nurbs::sphereZone(Eigen::Vector3d(3.0, 0.4, 0.2), 0.8, 150.0), 4.0};
    case 1:  // a saddle under a spherical cap
      return {"saddle_cap", nurbs::saddle(Eigen::Vector3d::Zero(), 1.0, 0.3),
              nurbs::sphereZone(Eigen::Vector3d(0.2, -0.1, 1.6), 1.0, 200.0), 3.0};
    case 2:  // interleaved wavy sheets: many local minima
      return {"wavy_sheets", nurbs::wavySheet(Eigen::Vector3d::Zero(), 4.0, 12, 2.0, 0.2, 0.0),
              nurbs::wavySheet(Eigen::Vector3d(0, 0, 0.45), 4.0, 12, 2.0, 0.2, 0.0), 4.0};
    default:  // two twisted blades side by side
      return {"blades", nurbs::sweptBlade(Eigen::Vector3d::Zero(), 1.0, 0.12, 3.0, 35.0),
              nurbs::sweptBlade(Eigen::Vector3d(0.15, 0.6, 0.0), 1.0, 0.12, 3.0, 35.0), 3.0};
  }
}

void distanceBenchmark(benchmark::State& state, int which, nurbs::PatchBound bound, bool refine) {
  const SurfacePair pair = makeSurfacePair(which);
  nurbs::SurfaceDistanceOptions options;
  options.bound = bound;
  options.refine = refine;
  options.tolerance = 1e-6 * pair.size;
  options.max_pairs = 200'000;
  nurbs::SurfaceDistance last;
  for (auto _ : state) {
    last = nurbs::minimumDistance(pair.a, pair.b, options);
    benchmark::DoNotOptimize(last.upper);
  }
  state.counters["converged"] = last.converged ? 1.0 : 0.0;
  state.counters["pairs_bounded"] = static_cast<double>(last.pairs_bounded);
  state.counters["pairs_opened"] = static_cast<double>(last.pairs_opened);
  state.counters["levels"] = static_cast<double>(last.levels.size());
  state.counters["gap"] = last.upper - last.lower;
  state.counters["distance"] = last.upper;
}

[[maybe_unused]] const bool nurbs_registered = [] {
  for (int which = 0; which < 4; ++which) {
    const std::string name = std::string("nurbs_distance/") + makeSurfacePair(which).name;
    for (const auto& [bound, bound_name] : {std::pair{nurbs::PatchBound::kConvexHull, "hull"},
                                            std::pair{nurbs::PatchBound::kBox, "box"}}) {
      for (const bool refine : {true, false}) {
        benchmark::RegisterBenchmark((name + "/" + bound_name + (refine ? "" : "/seed")).c_str(),
                                     [which, bound = bound, refine](benchmark::State& state) {
                                       distanceBenchmark(state, which, bound, refine);
                                     })
            ->Unit(benchmark::kMicrosecond);
      }
    }
  }
  return true;
}();

}  // namespace
}  // namespace collido::bench
