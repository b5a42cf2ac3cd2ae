#include "box_frame_search.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <optional>

#include <Eigen/Geometry>

namespace collido::obbtree::detail {
namespace {

// A candidate must beat the covariance's frame by this factor: ties keep it, and a frame must
// be clearly better to be worth a change.
constexpr double kClearMargin = 0.98;
// Points between checks of a candidate against the best so far.
constexpr std::size_t kGiveUpCheck = 8;

// The box of points (about the node's mean) on one frame: its extremes along each axis.
struct FrameBox {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = -Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());

  // Its surface over 8 (h0 h1 + h1 h2 + h2 h0, h the half extents).
  double surface() const {
    const Eigen::Vector3d h = 0.5 * (hi - lo);
    return h.x() * h.y() + h.y() * h.z() + h.z() * h.x();
  }
};

// The box of `points` on `axes`; once its surface exceeds `give_up_above`, a box of some of the
// points whose surface is above that.
FrameBox boxOnFrame(const Eigen::Matrix3d& axes, const std::vector<Eigen::Vector3d>& points,
                    double give_up_above) {
  FrameBox box;
  const Eigen::Matrix3d axes_t = axes.transpose();
  for (std::size_t k = 0; k < points.size(); ++k) {
    const Eigen::Vector3d u = axes_t * points[k];
    box.lo = box.lo.cwiseMin(u);
    box.hi = box.hi.cwiseMax(u);
    // The surface only grows as points are added: a losing frame is known before the end.
    if (k % kGiveUpCheck == kGiveUpCheck - 1 && box.surface() > give_up_above) return box;
  }
  return box;
}

}  // namespace

void extremesFirst(std::vector<Eigen::Vector3d>& points, const Eigen::Matrix3d& axes) {
  if (points.empty()) return;
  std::size_t extreme[6] = {};
  Eigen::Vector3d lo = axes.transpose() * points[0];
  Eigen::Vector3d hi = lo;
  for (std::size_t k = 1; k < points.size(); ++k) {
    const Eigen::Vector3d u = axes.transpose() * points[k];
    for (int j = 0; j < 3; ++j) {
      if (u[j] < lo[j]) {
        lo[j] = u[j];
        extreme[2 * j] = k;
      }
      if (u[j] > hi[j]) {
        hi[j] = u[j];
        extreme[2 * j + 1] = k;
      }
    }
  }
  // In increasing order, each distinct index to the next front slot: slot i <= index i, and no
  // earlier swap touched a later index.
  std::sort(std::begin(extreme), std::end(extreme));
  std::size_t front = 0;
  for (std::size_t i = 0; i < 6; ++i) {
    if (i > 0 && extreme[i] == extreme[i - 1]) continue;
    std::swap(points[front++], points[extreme[i]]);
  }
}

std::optional<Eigen::Matrix3d> edgeFrame(const Eigen::Vector3d* corners, int e) {
  const Eigen::Vector3d normal = (corners[1] - corners[0]).cross(corners[2] - corners[0]);
  const Eigen::Vector3d edge = corners[(e + 1) % 3] - corners[e];
  // Eigen leaves a zero vector as it is when asked to normalise it: a frame of zeros would
  // measure every box as empty. Unit vectors nearly orthogonal only, then.
  if (!(normal.squaredNorm() > 0.0) || !(edge.squaredNorm() > 0.0)) return std::nullopt;
  Eigen::Matrix3d frame;
  frame.col(0) = edge.normalized();
  const Eigen::Vector3d side = normal.normalized().cross(frame.col(0));
  if (!(side.squaredNorm() > 0.5)) return std::nullopt;
  frame.col(1) = side.normalized();
  frame.col(2) = frame.col(0).cross(frame.col(1));
  if (!frame.allFinite()) return std::nullopt;
  return frame;
}

std::optional<Eigen::Matrix3d> longestEdgeFrame(const Eigen::Vector3d* corners) {
  int longest = 0;
  for (int e = 1; e < 3; ++e) {
    if ((corners[(e + 1) % 3] - corners[e]).squaredNorm() >
        (corners[(longest + 1) % 3] - corners[longest]).squaredNorm())
      longest = e;
  }
  return edgeFrame(corners, longest);
}

Eigen::Matrix3d leastSurfaceFrame(const Eigen::Matrix3d& axes, double surface,
                                  const std::vector<Eigen::Vector3d>& points,
                                  const std::vector<Eigen::Vector3d>& triangle_corners) {
  double best = kClearMargin * surface;
  Eigen::Matrix3d best_axes = axes;
  for (std::size_t t = 0; t + 2 < triangle_corners.size(); t += 3) {
    for (int e = 0; e < 3; ++e) {
      const std::optional<Eigen::Matrix3d> frame = edgeFrame(&triangle_corners[t], e);
      if (!frame) continue;
      const double candidate = boxOnFrame(*frame, points, best).surface();
      if (candidate < best) {
        best = candidate;
        best_axes = *frame;
      }
    }
  }
  return best_axes;
}

}  // namespace collido::obbtree::detail
