// The pose-error sweep: how tracking noise, marker count, layout and dropouts turn into pose
// error, per solver, on one object's mesh.
#include <collido/pose/error_sweep.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include <collido/pose/pose_error.h>
#include <collido/pose/synthetic_markers.h>
#include <collido/random/portable_random.h>

namespace collido::pose {
namespace {

double quantile(std::vector<double> values, double q) {
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(values.begin(), values.end());
  // The nearest rank (this library links nothing but Eigen, so not the runner's statistics).
  const auto at = static_cast<std::size_t>(std::lround(q * static_cast<double>(values.size() - 1)));
  return values[std::min(at, values.size() - 1)];
}

// Farthest-point sampling from `first`: each next marker is the vertex farthest from those
// chosen, so the markers spread over the whole object.
std::vector<Eigen::Vector3d> farthest(const Eigen::Ref<const Eigen::Matrix3Xd>& candidates,
                                      Eigen::Index first, int count) {
  std::vector<Eigen::Vector3d> chosen{candidates.col(first)};
  Eigen::VectorXd distance = (candidates.colwise() - candidates.col(first)).colwise().norm();
  while (static_cast<int>(chosen.size()) < count &&
         chosen.size() < static_cast<std::size_t>(candidates.cols())) {
    Eigen::Index next = 0;
    distance.maxCoeff(&next);
    chosen.emplace_back(candidates.col(next));
    distance = distance.cwiseMin(
        (candidates.colwise() - candidates.col(next)).colwise().norm().transpose());
  }
  return chosen;
}

Result<MarkerLayout> makeLayout(const Eigen::Ref<const Eigen::Matrix3Xd>& vertices, LayoutKind kind,
                                int count, const MarkerLayout& given, PortableRandom& random) {
  const Eigen::Vector3d low = vertices.rowwise().minCoeff();
  const Eigen::Vector3d high = vertices.rowwise().maxCoeff();
  const double size = (high - low).norm();
  std::vector<Eigen::Vector3d> points;
  const auto start =
      static_cast<Eigen::Index>(random.bits() % static_cast<std::uint64_t>(vertices.cols()));
  switch (kind) {
    case LayoutKind::kSpread:
      points = farthest(vertices, start, count);
      break;
    case LayoutKind::kCompact: {
      std::vector<Eigen::Index> near;
      for (Eigen::Index v = 0; v < vertices.cols(); ++v) {
        if ((vertices.col(v) - vertices.col(start)).norm() <= 0.1 * size) near.push_back(v);
      }
      Eigen::Matrix3Xd local(3, static_cast<Eigen::Index>(near.size()));
      for (std::size_t k = 0; k < near.size(); ++k)
        local.col(static_cast<Eigen::Index>(k)) = vertices.col(near[k]);
      points = farthest(local, 0, count);
      break;
    }
    case LayoutKind::kPlanar:
      // A flat panel on the top face of the bounding box.
      for (int k = 0; k < count; ++k) {
        const double x = random.uniform(low.x(), high.x());
        const double y = random.uniform(low.y(), high.y());
        points.emplace_back(x, y, high.z());
      }
      break;
    case LayoutKind::kGiven:
      for (const auto& [id, p] : given) {
        if (static_cast<int>(points.size()) == count) break;
        points.push_back(p);
      }
      break;
  }
  if (static_cast<int>(points.size()) < count) {
    return Status(StatusCode::kInvalidArgument, std::string("the ") + layoutKindName(kind) +
                                                    " layout has " + std::to_string(points.size()) +
                                                    " distinct markers, not " +
                                                    std::to_string(count));
  }
  MarkerLayout layout;
  for (int k = 0; k < count; ++k)
    layout[k + 1] = points[static_cast<std::size_t>(k)];
  return layout;
}

}  // namespace

const char* layoutKindName(LayoutKind kind) {
  switch (kind) {
    case LayoutKind::kSpread:
      return "spread";
    case LayoutKind::kCompact:
      return "compact";
    case LayoutKind::kPlanar:
      return "planar";
    case LayoutKind::kGiven:
      return "given";
  }
  return "?";
}

Result<std::vector<ErrorSweepRow>> runErrorSweep(const Eigen::Ref<const Eigen::Matrix3Xd>& vertices,
                                                 const ErrorSweepOptions& options) {
  if (vertices.cols() == 0) return Status(StatusCode::kInvalidArgument, "the mesh has no vertices");
  if (options.trials < 1) return Status(StatusCode::kInvalidArgument, "trials must be >= 1");
  const double size = (vertices.rowwise().maxCoeff() - vertices.rowwise().minCoeff()).norm();
  std::vector<ErrorSweepRow> rows;
  for (const PoseSolver solver : options.solvers) {
    for (const LayoutKind kind : options.layouts) {
      for (const int count : options.marker_counts) {
        // A given layout has the markers it has: larger counts are not rows.
        if (kind == LayoutKind::kGiven && count > static_cast<int>(options.given.size())) continue;
        // One layout per (layout kind, count), the same for every solver, noise and dropout.
        PortableRandom layout_random(options.seed * 7919 + static_cast<std::uint64_t>(count) * 31 +
                                     static_cast<std::uint64_t>(kind));
        Result<MarkerLayout> layout =
            makeLayout(vertices, kind, count, options.given, layout_random);
        if (!layout.ok()) return layout.status();
        for (const double noise : options.noises) {
          for (const double dropout : options.dropouts) {
            ErrorSweepRow row;
            row.solver = solver;
            row.layout = kind;
            row.markers = count;
            row.noise = noise;
            row.dropout = dropout;
            row.trials = options.trials;
            MarkerNoise noise_model;
            noise_model.noise = noise;
            noise_model.dropout = dropout;
            noise_model.outliers = options.outliers;
            noise_model.outlier_offset = options.outlier_offset;
            FitOptions fit;
            fit.solver = solver;
            fit.reject_outliers = options.reject_outliers > 0.0;
            fit.inlier_threshold = options.reject_outliers;
            // The same true poses and noise for every solver: a paired comparison.
            PortableRandom random(options.seed);
            std::vector<double> rotation, translation, worst, pose_worst, solve;
            for (int trial = 0; trial < options.trials; ++trial) {
              Pose truth = Pose::Identity();
              truth.linear() = random.rotation();
              const Eigen::Vector3d shift = random.direction();
              truth.translation() = 3.0 * size * shift;
              const std::vector<MarkerObservation> seen =
                  observeMarkers(layout.value(), truth, noise_model, random);
              const auto begin = std::chrono::steady_clock::now();
              const Result<PoseEstimate> estimate = fitPose(layout.value(), seen, fit);
              const auto end = std::chrono::steady_clock::now();
              if (!estimate.ok()) {
                if (row.failed++ == 0) row.first_failure = estimate.status().message();
                continue;
              }
              solve.push_back(std::chrono::duration<double, std::micro>(end - begin).count());
              const PoseError e = poseError(estimate.value().transform, truth, vertices);
              rotation.push_back(e.rotation_deg);
              translation.push_back(e.translation);
              worst.push_back(e.worst_vertex);
              // The rigid fit's map is its pose; only the affine fit's pose differs.
              pose_worst.push_back(
                  solver == PoseSolver::kRigid
                      ? e.worst_vertex
                      : poseError(Eigen::Affine3d(estimate.value().pose.matrix()), truth, vertices)
                            .worst_vertex);
            }
            row.rotation_deg_median = quantile(rotation, 0.5);
            row.rotation_deg_p90 = quantile(rotation, 0.9);
            row.translation_median = quantile(translation, 0.5);
            row.translation_p90 = quantile(translation, 0.9);
            row.worst_vertex_median = quantile(worst, 0.5);
            row.worst_vertex_p90 = quantile(worst, 0.9);
            row.pose_worst_vertex_median = quantile(pose_worst, 0.5);
            row.solve_us_median = quantile(solve, 0.5);
            rows.push_back(row);
          }
        }
      }
    }
  }
  return rows;
}

}  // namespace collido::pose
