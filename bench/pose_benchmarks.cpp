// Solve time of a pose from one frame of tracked markers, per solver and marker count:
//   pose/<solver>/<markers>          the fit (1 mm noise);
//   pose_ransac/<solver>/<markers>   with outlier rejection (one marker displaced 10 cm).
// The markers sit on a 1 m module, a fixed seeded layout, not in one plane.
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include <collido/pose/marker_fit.h>
#include <collido/random/portable_random.h>

namespace collido::bench {
namespace {

struct Frame {
  pose::MarkerLayout layout;
  std::vector<pose::MarkerObservation> seen;
};

Frame makeFrame(int markers, bool with_outlier) {
  PortableRandom random(static_cast<std::uint64_t>(markers) + 41);
  Frame frame;
  Pose truth = Pose::Identity();
  truth.linear() = random.rotation();
  truth.translation() = Eigen::Vector3d(2.0, -1.0, 0.5);
  for (int id = 1; id <= markers; ++id) {
    const Eigen::Vector3d p(random.uniform(-0.5, 0.5), random.uniform(-0.3, 0.3),
                            random.uniform(-0.2, 0.2));
    frame.layout[id] = p;
    pose::MarkerObservation o;
    o.id = id;
    o.position = truth * p + 0.001 * random.direction();
    frame.seen.push_back(o);
  }
  if (with_outlier) frame.seen[0].position += Eigen::Vector3d(0.1, 0.0, 0.0);
  return frame;
}

void fitBenchmark(benchmark::State& state, pose::PoseSolver solver, bool ransac) {
  const Frame frame = makeFrame(static_cast<int>(state.range(0)), ransac);
  pose::FitOptions options;
  options.solver = solver;
  options.reject_outliers = ransac;
  options.inlier_threshold = 0.01;
  for (auto _ : state) {
    Result<pose::PoseEstimate> fit = pose::fitPose(frame.layout, frame.seen, options);
    if (!fit.ok()) {
      state.SkipWithError(fit.status().message().c_str());
      return;
    }
    benchmark::DoNotOptimize(fit.value().pose);
  }
}

void rigid(benchmark::State& state) {
  fitBenchmark(state, pose::PoseSolver::kRigid, false);
}
void affine(benchmark::State& state) {
  fitBenchmark(state, pose::PoseSolver::kAffine, false);
}
void rigidRansac(benchmark::State& state) {
  fitBenchmark(state, pose::PoseSolver::kRigid, true);
}
void affineRansac(benchmark::State& state) {
  fitBenchmark(state, pose::PoseSolver::kAffine, true);
}

BENCHMARK(rigid)->Name("pose/rigid")->Arg(4)->Arg(6)->Arg(12)->Arg(32);
BENCHMARK(affine)->Name("pose/affine")->Arg(4)->Arg(6)->Arg(12)->Arg(32);
BENCHMARK(rigidRansac)->Name("pose_ransac/rigid")->Arg(6)->Arg(12)->Arg(32);
BENCHMARK(affineRansac)->Name("pose_ransac/affine")->Arg(6)->Arg(12)->Arg(32);

}  // namespace
}  // namespace collido::bench
