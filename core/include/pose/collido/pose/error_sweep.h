#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

#include <collido/pose/marker_fit.h>
#include <collido/status.h>

namespace collido::pose {

/// Where markers sit on an object, relative to its mesh (MarkerLayoutKind names).
enum class LayoutKind {
  kSpread,   ///< mesh vertices spread over the whole object (farthest-point sampling)
  kCompact,  ///< mesh vertices within a tenth of the object's size around one vertex
  kPlanar,   ///< points on one face of the bounding box (a flat panel): one plane
  kGiven,    ///< a layout given by the caller (e.g. a scene's), its first `count` markers
             ///< (counts beyond its size give no row)
};

/// "spread", "compact", "planar", "given".
const char* layoutKindName(LayoutKind kind);

/// The settings of a pose-error sweep: every combination of solver, layout, marker count,
/// noise and dropout rate gets `trials` random true poses, each fitted once.
struct ErrorSweepOptions {
  std::vector<PoseSolver> solvers{PoseSolver::kRigid, PoseSolver::kAffine};
  std::vector<LayoutKind> layouts{LayoutKind::kSpread, LayoutKind::kCompact, LayoutKind::kPlanar};
  std::vector<int> marker_counts{3, 4, 6, 12};
  std::vector<double> noises{0.001};  ///< per-axis standard deviation (Gaussian)
  std::vector<double> dropouts{0.0};  ///< chance a marker is not seen
  double outliers = 0.0;              ///< chance a seen marker is mis-identified
  double outlier_offset = 0.05;       ///< how far it lands
  double reject_outliers = 0.0;       ///< > 0: FitOptions::inlier_threshold (RANSAC on)
  int trials = 200;
  std::uint64_t seed = 1;
  MarkerLayout given;  ///< the layout of LayoutKind::kGiven (ids in order)
};

/// The errors of one combination over its trials (medians and 90th percentiles over the
/// trials whose fit succeeded).
struct ErrorSweepRow {
  PoseSolver solver = PoseSolver::kRigid;
  LayoutKind layout = LayoutKind::kSpread;
  int markers = 0;
  double noise = 0.0;
  double dropout = 0.0;
  int trials = 0;
  int failed = 0;             ///< fits refused: too few markers seen, or a degenerate layout
  std::string first_failure;  ///< the first refusal's message (why they fail)
  double rotation_deg_median = 0.0;
  double rotation_deg_p90 = 0.0;
  double translation_median = 0.0;
  double translation_p90 = 0.0;
  /// Per trial the largest displacement over the mesh by the fit's own map (for the affine
  /// fit, its 12 coefficients: the dissertation's method).
  double worst_vertex_median = 0.0;
  double worst_vertex_p90 = 0.0;
  /// The same for the rigid pose that drives the collision query (PoseEstimate::pose).
  double pose_worst_vertex_median = 0.0;
  double solve_us_median = 0.0;  ///< one fitPose call, steady clock
};

/// Runs the sweep on an object whose mesh vertices (its own frame) are `vertices`: markers per
/// layout, tracks from random true poses (seeded), fits, errors over the vertices. Rows in the
/// order solver, layout, markers, noise, dropout. Errors: an empty mesh, no trials, a given
/// layout asked for without markers.
Result<std::vector<ErrorSweepRow>> runErrorSweep(const Eigen::Ref<const Eigen::Matrix3Xd>& vertices,
                                                 const ErrorSweepOptions& options);

}  // namespace collido::pose
