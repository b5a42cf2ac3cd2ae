// A pose from one frame of tracked markers: checks, the fit, outlier rejection, uncertainty.
#include <collido/pose/marker_fit.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <set>
#include <sstream>

#include <Eigen/SVD>

#include <collido/random/portable_random.h>

#include "point_fit.h"

namespace collido::pose {
namespace {

using detail::PointSet;

std::string idList(const std::vector<int>& ids) {
  std::ostringstream out;
  for (std::size_t i = 0; i < ids.size(); ++i)
    out << (i == 0 ? "" : ", ") << ids[i];
  return out.str();
}

std::size_t minimalSet(PoseSolver solver) {
  return solver == PoseSolver::kAffine ? 4 : 3;
}

// The layout's condition number for the solver: the largest spread over the smallest one the
// solver needs (a line has no second, a plane no third).
double conditionOf(const PointSet& set, PoseSolver solver) {
  const Eigen::Vector3d spread = detail::layoutSpread(set);
  const double needed = solver == PoseSolver::kAffine ? spread(2) : spread(1);
  if (!(needed > 0.0)) return std::numeric_limits<double>::infinity();
  return spread(0) / needed;
}

Status degenerate(const std::vector<int>& ids, PoseSolver solver, double condition, double limit) {
  std::ostringstream out;
  out << "markers " << idList(ids)
      << (solver == PoseSolver::kAffine ? " lie in one plane (or on a line)" : " lie on a line")
      << ": condition number " << condition << " > " << limit << "; the " << poseSolverName(solver)
      << " fit needs " << minimalSet(solver) << " markers not "
      << (solver == PoseSolver::kAffine ? "in one plane" : "on one line");
  return {StatusCode::kInvalidArgument, out.str()};
}

PointSet subset(const PointSet& all, const std::vector<std::size_t>& which) {
  PointSet out;
  out.model.resize(3, static_cast<Eigen::Index>(which.size()));
  out.world.resize(3, static_cast<Eigen::Index>(which.size()));
  out.weights.resize(static_cast<Eigen::Index>(which.size()));
  for (std::size_t k = 0; k < which.size(); ++k) {
    const auto i = static_cast<Eigen::Index>(which[k]);
    const auto j = static_cast<Eigen::Index>(k);
    out.model.col(j) = all.model.col(i);
    out.world.col(j) = all.world.col(i);
    out.weights(j) = all.weights(i);
  }
  return out;
}

Eigen::Affine3d fit(const PointSet& set, PoseSolver solver) {
  return solver == PoseSolver::kAffine ? detail::fitAffine(set) : detail::fitRigid(set);
}

// Calls `visit` with every minimal subset of n points when there are at most `limit`, else
// with `limit` seeded random ones.
template <typename Visit>
void minimalSubsets(std::size_t n, std::size_t size, int limit, std::uint64_t seed, Visit&& visit) {
  double count = 1.0;  // n choose size, in double: it only decides enumerate vs draw
  for (std::size_t k = 0; k < size; ++k)
    count = count * static_cast<double>(n - k) / static_cast<double>(k + 1);
  std::vector<std::size_t> pick(size);
  if (count <= static_cast<double>(limit)) {
    std::iota(pick.begin(), pick.end(), 0);
    for (;;) {
      visit(pick);
      std::size_t k = size;
      while (k > 0 && pick[k - 1] == n - size + k - 1)
        --k;
      if (k == 0) return;
      ++pick[k - 1];
      for (std::size_t j = k; j < size; ++j)
        pick[j] = pick[j - 1] + 1;
    }
  }
  PortableRandom random(seed);
  for (int draw = 0; draw < limit; ++draw) {
    std::vector<std::size_t> all(n);
    std::iota(all.begin(), all.end(), 0);
    for (std::size_t k = 0; k < size; ++k) {  // partial Fisher-Yates
      const std::size_t j = k + static_cast<std::size_t>(random.bits() % (n - k));
      std::swap(all[k], all[j]);
    }
    pick.assign(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(size));
    visit(pick);
  }
}

// RANSAC with a truncated-squares score (MSAC): the inliers of the best minimal fit, refined
// once by a fit on them. Empty when no minimal set is well conditioned.
std::vector<std::size_t> consensus(const PointSet& all, const FitOptions& options) {
  const std::size_t n = static_cast<std::size_t>(all.model.cols());
  const double threshold2 = options.inlier_threshold * options.inlier_threshold;
  const auto inliersOf = [&](const Eigen::Affine3d& map) {
    const Eigen::VectorXd r = detail::residuals(map, all);
    std::vector<std::size_t> in;
    double cost = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const double r2 = r(static_cast<Eigen::Index>(i)) * r(static_cast<Eigen::Index>(i));
      if (r2 <= threshold2) in.push_back(i);
      cost += std::min(r2, threshold2);
    }
    return std::make_pair(in, cost);
  };
  std::vector<std::size_t> best;
  double best_cost = std::numeric_limits<double>::infinity();
  minimalSubsets(n, minimalSet(options.solver), options.ransac_iterations, options.seed,
                 [&](const std::vector<std::size_t>& pick) {
                   const PointSet minimal = subset(all, pick);
                   if (conditionOf(minimal, options.solver) > options.max_condition) return;
                   auto [in, cost] = inliersOf(fit(minimal, options.solver));
                   if (in.size() > best.size() || (in.size() == best.size() && cost < best_cost)) {
                     best = std::move(in);
                     best_cost = cost;
                   }
                 });
  if (best.size() < minimalSet(options.solver)) return {};
  const PointSet chosen = subset(all, best);
  if (conditionOf(chosen, options.solver) > options.max_condition) return best;
  std::vector<std::size_t> refined = inliersOf(fit(chosen, options.solver)).first;
  return refined.size() >= best.size() ? refined : best;
}

Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d s;
  s << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return s;
}

}  // namespace

const char* poseSolverName(PoseSolver solver) {
  return solver == PoseSolver::kAffine ? "affine" : "rigid";
}

double PoseEstimate::pointSigma(const Eigen::Vector3d& p) const {
  if (covariance.size() == 0) return std::numeric_limits<double>::quiet_NaN();
  if (solver == PoseSolver::kAffine) {
    // Each coordinate is row_k . [p - centroid; 1], every row with covariance C.
    Eigen::Vector4d a;
    a << p - model_centroid, 1.0;
    return std::sqrt(std::max(0.0, a.dot(covariance * a)));
  }
  // world = R p + t; a small rotation d (left) and shift s move it by -[R p]x d + s.
  Eigen::Matrix<double, 3, 6> jacobian;
  jacobian << -skew(pose.linear() * p), Eigen::Matrix3d::Identity();
  const double trace = (jacobian * covariance * jacobian.transpose()).trace();
  return std::sqrt(std::max(0.0, trace / 3.0));
}

Result<PoseEstimate> fitPose(const MarkerLayout& layout,
                             const std::vector<MarkerObservation>& observed,
                             const FitOptions& options) {
  const std::size_t needed = minimalSet(options.solver);
  const auto bad = [](const std::string& text) {
    return Status(StatusCode::kInvalidArgument, text);
  };
  if (!(options.max_condition >= 1.0)) return bad("max_condition must be at least 1");
  if (options.reject_outliers && !(options.inlier_threshold > 0.0)) {
    return bad("outlier rejection needs inlier_threshold > 0 (a marker's residual limit)");
  }
  if (!(options.noise_sigma >= 0.0)) return bad("noise_sigma must be >= 0");

  // Match observations to the layout.
  std::set<int> seen;
  std::vector<int> ids;
  PointSet all;
  all.model.resize(3, static_cast<Eigen::Index>(observed.size()));
  all.world.resize(3, static_cast<Eigen::Index>(observed.size()));
  all.weights.resize(static_cast<Eigen::Index>(observed.size()));
  for (std::size_t k = 0; k < observed.size(); ++k) {
    const MarkerObservation& o = observed[k];
    const std::string which = "marker " + std::to_string(o.id);
    const auto found = layout.find(o.id);
    if (found == layout.end()) return bad(which + " is not in the object's marker layout");
    if (!seen.insert(o.id).second) return bad(which + " is observed twice in one frame");
    if (!o.position.allFinite()) return bad(which + " has a non-finite position");
    if (!(o.weight > 0.0) || !std::isfinite(o.weight)) {
      return bad(which + " has weight " + std::to_string(o.weight) + "; weights must be > 0");
    }
    const auto i = static_cast<Eigen::Index>(k);
    all.model.col(i) = found->second;
    all.world.col(i) = o.position;
    all.weights(i) = o.weight;
    ids.push_back(o.id);
  }
  if (observed.size() < needed) {
    return bad(std::to_string(observed.size()) + " marker(s) seen" +
               (ids.empty() ? "" : " (" + idList(ids) + ")") + "; the " +
               poseSolverName(options.solver) + " fit needs at least " + std::to_string(needed) +
               " not " + (options.solver == PoseSolver::kAffine ? "in one plane" : "on one line"));
  }

  std::vector<std::size_t> used(observed.size());
  std::iota(used.begin(), used.end(), 0);
  if (options.reject_outliers) {
    used = consensus(all, options);
    if (used.size() < needed) {
      return bad("no " + std::to_string(needed) + " of markers " + idList(ids) + " agree within " +
                 std::to_string(options.inlier_threshold) +
                 " (or every such set is degenerate): too many outliers for the " +
                 poseSolverName(options.solver) + " fit");
    }
  }
  const PointSet inliers = subset(all, used);
  std::vector<int> inlier_ids;
  inlier_ids.reserve(used.size());
  for (std::size_t i : used)
    inlier_ids.push_back(ids[i]);
  const double condition = conditionOf(inliers, options.solver);
  if (condition > options.max_condition) {
    std::sort(inlier_ids.begin(), inlier_ids.end());
    return degenerate(inlier_ids, options.solver, condition, options.max_condition);
  }

  PoseEstimate estimate;
  estimate.solver = options.solver;
  estimate.condition = condition;
  Eigen::Matrix4d normal_inverse = Eigen::Matrix4d::Zero();
  estimate.transform = options.solver == PoseSolver::kAffine
                           ? detail::fitAffine(inliers, &normal_inverse)
                           : detail::fitRigid(inliers);
  estimate.model_centroid = detail::weightedCentroid(inliers.model, inliers.weights);
  if (options.solver == PoseSolver::kAffine) {
    // The nearest rotation to the linear part (polar decomposition), placed so the markers'
    // centroid lands where the affine map sends it.
    const Eigen::JacobiSVD<Eigen::Matrix3d> svd(estimate.transform.linear(),
                                                Eigen::ComputeFullU | Eigen::ComputeFullV);
    Eigen::Vector3d signs(1.0, 1.0, 1.0);
    if ((svd.matrixU() * svd.matrixV().transpose()).determinant() < 0.0) signs(2) = -1.0;
    const Eigen::Matrix3d rotation = svd.matrixU() * signs.asDiagonal() * svd.matrixV().transpose();
    estimate.pose.linear() = rotation;
    estimate.pose.translation() =
        estimate.transform * estimate.model_centroid - rotation * estimate.model_centroid;
  } else {
    estimate.pose.linear() = estimate.transform.linear();
    estimate.pose.translation() = estimate.transform.translation();
  }

  const Eigen::VectorXd r = detail::residuals(estimate.transform, inliers);
  const double weight_sum = inliers.weights.sum();
  const double weighted_squares = inliers.weights.dot(r.cwiseProduct(r));
  estimate.rms_residual = std::sqrt(weighted_squares / weight_sum);
  estimate.max_residual = r.maxCoeff();

  // Noise per axis: given, or from the residuals over the redundant coordinates (3 per marker,
  // less the map's 6 or 12 parameters), with weights read as relative inverse variances whose
  // mean is 1.
  const double parameters = options.solver == PoseSolver::kAffine ? 12.0 : 6.0;
  const double redundancy = 3.0 * static_cast<double>(used.size()) - parameters;
  const double mean_weight = weight_sum / static_cast<double>(used.size());
  if (options.noise_sigma > 0.0) {
    estimate.noise_sigma = options.noise_sigma;
  } else if (redundancy > 0.0) {
    estimate.noise_sigma = std::sqrt(weighted_squares / mean_weight / redundancy);
  } else {
    estimate.noise_sigma = std::numeric_limits<double>::quiet_NaN();  // no redundancy
  }
  if (std::isfinite(estimate.noise_sigma)) {
    const double variance = estimate.noise_sigma * estimate.noise_sigma;
    if (options.solver == PoseSolver::kAffine) {
      estimate.covariance = variance * mean_weight * normal_inverse;
    } else {
      Eigen::Matrix<double, 6, 6> information = Eigen::Matrix<double, 6, 6>::Zero();
      for (Eigen::Index i = 0; i < inliers.model.cols(); ++i) {
        Eigen::Matrix<double, 3, 6> jacobian;
        jacobian << -skew(estimate.pose.linear() * inliers.model.col(i)),
            Eigen::Matrix3d::Identity();
        information += inliers.weights(i) / mean_weight * jacobian.transpose() * jacobian;
      }
      estimate.covariance = variance * information.inverse();
    }
  }
  std::sort(inlier_ids.begin(), inlier_ids.end());
  estimate.inliers = inlier_ids;
  for (int id : ids) {
    if (!std::binary_search(inlier_ids.begin(), inlier_ids.end(), id))
      estimate.outliers.push_back(id);
  }
  std::sort(estimate.outliers.begin(), estimate.outliers.end());
  return estimate;
}

}  // namespace collido::pose
