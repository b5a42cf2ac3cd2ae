// The least-change constraint solver on a chain of links, each link's base coincident with the
// previous link's tip, the first one's base sliding on a plane and the last one's tip dragged by
// (−0.3, 0.4, 0.2):
//   constraints/chain/<parameters>   6 parameters per link (1, 10, 100 and 500 links).
// Counters: equations, Newton iterations, edit steps and the normalised change of the answer.
#include <benchmark/benchmark.h>

#include <collido/constraints/solve.h>
#include <collido/random/portable_random.h>

namespace collido::bench {
namespace {

using constraints::kWorld;
using constraints::PointRef;

constraints::Problem draggedChain(int links) {
  constraints::Problem problem(1.0);
  const Eigen::Vector3d base(-0.5, 0.0, 0.0);
  const Eigen::Vector3d tip(0.5, 0.0, 0.0);
  // Each link turned 0.4 rad from the previous one about a seeded axis (a straight chain is
  // singular: its tip cannot move along it to first order).
  PortableRandom random(7);
  Eigen::Vector3d joint = Eigen::Vector3d::Zero();
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  for (int i = 0; i < links; ++i) {
    rotation = rotation * Eigen::AngleAxisd(0.4, random.direction()).toRotationMatrix();
    Pose pose = Pose::Identity();
    pose.linear() = rotation;
    pose.translation() = joint - rotation * base;
    joint = pose * tip;
    const int body = problem.addBody("link " + std::to_string(i), pose, 0.5).value();
    if (i == 0) {
      // The first base slides on the floor: one link alone can still be dragged.
      (void)problem.addPointOnPlane(
          "base on floor", PointRef{body, base},
          constraints::Plane{PointRef{kWorld, Eigen::Vector3d::Zero()},
                             constraints::DirectionRef{kWorld, Eigen::Vector3d::UnitZ()}});
    } else {
      (void)problem.addCoincident("joint " + std::to_string(i), PointRef{body, base},
                                  PointRef{body - 1, tip});
    }
  }
  (void)problem.addCoincident("drag", PointRef{links - 1, tip},
                              PointRef{kWorld, joint + Eigen::Vector3d(-0.3, 0.4, 0.2)});
  return problem;
}

void chain(benchmark::State& state) {
  const int links = static_cast<int>(state.range(0)) / 6;
  const constraints::Problem start = draggedChain(links);
  constraints::SolveReport last;
  for (auto _ : state) {
    state.PauseTiming();
    constraints::Problem problem = start;
    state.ResumeTiming();
    Result<constraints::SolveReport> report = constraints::solve(problem);
    if (!report.ok()) {
      state.SkipWithError(report.status().message().c_str());
      return;
    }
    last = report.value();
  }
  state.counters["equations"] = last.equations;
  state.counters["iterations"] = last.iterations;
  state.counters["edit_steps"] = last.edit_steps;
  state.counters["change"] = last.change;
}

BENCHMARK(chain)
    ->Name("constraints/chain")
    ->Arg(6)
    ->Arg(60)
    ->Arg(600)
    ->Arg(3000)
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace collido::bench
