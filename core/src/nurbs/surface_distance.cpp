// The seed method's minimum distance between NURBS surfaces: best-first subdivision with hull
// (or box) lower bounds and corner / descent upper bounds.
#include <collido/nurbs/surface_distance.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <deque>
#include <queue>

#include <Eigen/Dense>

#include <collido/convex/gjk.h>

namespace collido::nurbs {
namespace {

using Clock = std::chrono::steady_clock;

// A sub-patch of one surface, its control net's points and box, and its four children once split.
struct Patch {
  NurbsSurface surface;
  Eigen::Matrix3Xd points;
  Eigen::Vector3d lo;
  Eigen::Vector3d hi;
  int depth = 0;
  std::array<int, 4> children{-1, -1, -1, -1};
  // A clamped patch passes through its corner control points: four surface points for free,
  // with their parameters, found once (each patch meets many others).
  std::array<Eigen::Vector3d, 4> corners;
  std::array<Eigen::Vector2d, 4> corner_params;
};

class PatchTree {
 public:
  explicit PatchTree(const NurbsSurface& root) { add(root, 0); }

  const Patch& at(int index) const { return patches_[static_cast<std::size_t>(index)]; }

  const std::array<int, 4>& children(int index) {
    if (patches_[static_cast<std::size_t>(index)].children[0] < 0) {
      const std::array<NurbsSurface, 4> parts =
          splitInFour(patches_[static_cast<std::size_t>(index)].surface);
      const int depth = patches_[static_cast<std::size_t>(index)].depth + 1;
      std::array<int, 4> made{};
      for (std::size_t k = 0; k < 4; ++k)
        made[k] = add(parts[k], depth);
      patches_[static_cast<std::size_t>(index)].children = made;
    }
    return patches_[static_cast<std::size_t>(index)].children;
  }

 private:
  int add(const NurbsSurface& surface, int depth) {
    Patch p;
    p.surface = surface;
    p.points = surface.controlPoints();
    p.lo = p.points.rowwise().minCoeff();
    p.hi = p.points.rowwise().maxCoeff();
    p.depth = depth;
    for (int k = 0; k < 4; ++k) {
      const int i = (k & 2) != 0 ? surface.count_u - 1 : 0;
      const int j = (k & 1) != 0 ? surface.count_v - 1 : 0;
      p.corners[static_cast<std::size_t>(k)] = surface.point(i, j);
      p.corner_params[static_cast<std::size_t>(k)] =
          Eigen::Vector2d((k & 2) != 0 ? surface.uMax() : surface.uMin(),
                          (k & 1) != 0 ? surface.vMax() : surface.vMin());
    }
    patches_.push_back(std::move(p));
    return static_cast<int>(patches_.size()) - 1;
  }

  std::deque<Patch> patches_;  // a deque: references stay valid as patches are added
};

struct Pending {
  double bound;
  int a;
  int b;
  bool operator>(const Pending& o) const { return bound > o.bound; }
};

// The closest pair found so far.
struct Best {
  double distance = std::numeric_limits<double>::infinity();
  Eigen::Vector2d params_a = Eigen::Vector2d::Zero();
  Eigen::Vector2d params_b = Eigen::Vector2d::Zero();
  Eigen::Vector3d point_a = Eigen::Vector3d::Zero();
  Eigen::Vector3d point_b = Eigen::Vector3d::Zero();

  void offer(const Eigen::Vector2d& pa, const Eigen::Vector3d& xa, const Eigen::Vector2d& pb,
             const Eigen::Vector3d& xb) {
    const double d = (xa - xb).norm();
    if (d < distance) {
      distance = d;
      params_a = pa;
      params_b = pb;
      point_a = xa;
      point_b = xb;
    }
  }
};

// Every pair of the two patches' corners is a candidate closest pair.
void offerCorners(const Patch& a, const Patch& b, Best& best) {
  for (std::size_t ka = 0; ka < 4; ++ka) {
    for (std::size_t kb = 0; kb < 4; ++kb)
      best.offer(a.corner_params[ka], a.corners[ka], b.corner_params[kb], b.corners[kb]);
  }
}

// Damped Gauss-Newton (Levenberg-Marquardt) on |S_a(u1, v1) - S_b(u2, v2)|^2 from the centres
// of two sub-patches, the parameters kept inside the whole surfaces' domains.
void refine(const NurbsSurface& a, const NurbsSurface& b, const Patch& pa, const Patch& pb,
            Best& best, std::size_t& evaluations) {
  Eigen::Vector4d x(
      0.5 * (pa.surface.uMin() + pa.surface.uMax()), 0.5 * (pa.surface.vMin() + pa.surface.vMax()),
      0.5 * (pb.surface.uMin() + pb.surface.uMax()), 0.5 * (pb.surface.vMin() + pb.surface.vMax()));
  const Eigen::Vector4d lo(a.uMin(), a.vMin(), b.uMin(), b.vMin());
  const Eigen::Vector4d hi(a.uMax(), a.vMax(), b.uMax(), b.vMax());
  const auto evaluateAt = [&](const Eigen::Vector4d& at, SurfacePoint& sa, SurfacePoint& sb) {
    sa = evaluateWithDerivatives(a, at[0], at[1]);
    sb = evaluateWithDerivatives(b, at[2], at[3]);
    evaluations += 2;
    best.offer(at.head<2>(), sa.point, at.tail<2>(), sb.point);
    return (sa.point - sb.point).squaredNorm();
  };
  SurfacePoint sa;
  SurfacePoint sb;
  double f = evaluateAt(x, sa, sb);
  double lambda = 1e-3;
  for (int iteration = 0; iteration < 12; ++iteration) {
    Eigen::Matrix<double, 3, 4> jacobian;
    jacobian << sa.du, sa.dv, -sb.du, -sb.dv;
    const Eigen::Vector3d residual = sa.point - sb.point;
    const Eigen::Matrix4d normal = jacobian.transpose() * jacobian;
    const Eigen::Vector4d gradient = jacobian.transpose() * residual;
    if (gradient.norm() <= 1e-300) break;
    bool improved = false;
    for (int attempt = 0; attempt < 6 && !improved; ++attempt) {
      Eigen::Matrix4d damped = normal;
      damped.diagonal() += lambda * (normal.diagonal().array() + 1e-12).matrix();
      const Eigen::Vector4d step = damped.ldlt().solve(-gradient);
      const Eigen::Vector4d next = (x + step).cwiseMax(lo).cwiseMin(hi);
      SurfacePoint na;
      SurfacePoint nb;
      const double fn = evaluateAt(next, na, nb);
      if (fn < f) {
        const double gain = f - fn;
        x = next;
        f = fn;
        sa = na;
        sb = nb;
        lambda = std::max(lambda * 0.3, 1e-9);
        improved = true;
        if (gain <= 1e-30 + 1e-16 * f) return;
      } else {
        lambda *= 10.0;
      }
    }
    if (!improved) return;
  }
}

}  // namespace

SurfaceDistance minimumDistance(const NurbsSurface& a, const NurbsSurface& b,
                                const SurfaceDistanceOptions& options) {
  SurfaceDistance out;
  PatchTree tree_a(a);
  PatchTree tree_b(b);
  const double magnitude = std::max({tree_a.at(0).points.cwiseAbs().maxCoeff(),
                                     tree_b.at(0).points.cwiseAbs().maxCoeff(), 1e-300});
  // The subdivided nets and the evaluations are rounded: allow 1e-14 of the model's size per
  // level below the bounds and once above the upper bound.
  const auto slack = [&](int depth) { return 1e-14 * magnitude * (depth + 1); };
  Best best;
  offerCorners(tree_a.at(0), tree_b.at(0), best);
  if (options.refine) refine(a, b, tree_a.at(0), tree_b.at(0), best, out.surface_evaluations);

  const auto level = [&](int depth) -> LevelWork& {
    if (out.levels.size() <= static_cast<std::size_t>(depth))
      out.levels.resize(static_cast<std::size_t>(depth) + 1);
    return out.levels[static_cast<std::size_t>(depth)];
  };
  const auto upper = [&] { return best.distance + slack(0); };
  const auto bound = [&](int ia, int ib) {
    const Patch& pa = tree_a.at(ia);
    const Patch& pb = tree_b.at(ib);
    ++out.pairs_bounded;
    ++level(std::max(pa.depth, pb.depth)).pairs_bounded;
    const double box_gap =
        (pa.lo - pb.hi).cwiseMax(pb.lo - pa.hi).cwiseMax(Eigen::Vector3d::Zero()).norm();
    double lower = box_gap;
    if (options.bound == PatchBound::kConvexHull && box_gap < best.distance - options.tolerance) {
      const convex::PointSetSupport support_a(pa.points);
      const convex::PointSetSupport support_b(pb.points);
      convex::GjkOptions gjk;
      gjk.abs_tolerance = 0.25 * options.tolerance;
      // From B's box centre towards A's: the first support pair starts near the closest one.
      gjk.initial_direction = (pa.lo + pa.hi) - (pb.lo + pb.hi);
      // A bound that reaches the pruning cutoff drops the pair: no need to tighten it further
      // (the cutoff only falls later, so the pair stays dropped and its bound stays valid).
      gjk.stop_when_lower_reaches =
          upper() - options.tolerance + slack(std::max(pa.depth, pb.depth));
      const convex::GjkResult hull = convex::gjkDistance(support_a, support_b, gjk);
      lower = std::max(lower, hull.lower_bound);
    }
    return std::max(0.0, lower - slack(std::max(pa.depth, pb.depth)));
  };

  std::priority_queue<Pending, std::vector<Pending>, std::greater<>> queue;
  queue.push(Pending{bound(0, 0), 0, 0});
  // The true distance is at least the smallest bound of any pair left unopened: those still
  // queued, those too deep to split, and those dropped for reaching the upper bound less the
  // tolerance.
  double unresolved = std::numeric_limits<double>::infinity();
  int refined_depth = 0;
  while (!queue.empty()) {
    const Pending next = queue.top();
    if (next.bound >= upper() - options.tolerance) break;
    queue.pop();
    const int depth = std::max(tree_a.at(next.a).depth, tree_b.at(next.b).depth);
    if (depth >= options.max_depth || out.pairs_bounded >= options.max_pairs) {
      unresolved = std::min(unresolved, next.bound);
      continue;
    }
    const Clock::time_point start = Clock::now();
    ++out.pairs_opened;
    ++level(depth).pairs_opened;
    const std::array<int, 4> children_a = tree_a.children(next.a);
    const std::array<int, 4> children_b = tree_b.children(next.b);
    Pending closest{std::numeric_limits<double>::infinity(), -1, -1};
    std::array<Pending, 16> made{};
    int made_count = 0;
    for (int ca : children_a) {
      for (int cb : children_b) {
        offerCorners(tree_a.at(ca), tree_b.at(cb), best);
        const Pending child{bound(ca, cb), ca, cb};
        made[static_cast<std::size_t>(made_count++)] = child;
        if (child.bound < closest.bound) closest = child;
      }
    }
    // One descent per level, from the first pair opened there: each level's first pair is the
    // most promising one yet, and further descents mostly land on the same minimum.
    if (options.refine && closest.a >= 0 && depth >= refined_depth) {
      refined_depth = depth + 1;
      refine(a, b, tree_a.at(closest.a), tree_b.at(closest.b), best, out.surface_evaluations);
    }
    for (int k = 0; k < made_count; ++k) {
      const Pending& child = made[static_cast<std::size_t>(k)];
      if (child.bound < upper() - options.tolerance) {
        queue.push(child);
      } else {
        unresolved = std::min(unresolved, child.bound);
      }
    }
    level(depth).seconds += std::chrono::duration<double>(Clock::now() - start).count();
  }
  double lower = std::min(unresolved, upper());
  if (!queue.empty()) lower = std::min(lower, queue.top().bound);
  out.lower = lower;
  out.upper = upper();
  out.converged = out.upper - out.lower <= options.tolerance;
  out.params_a = best.params_a;
  out.params_b = best.params_b;
  out.point_a = best.point_a;
  out.point_b = best.point_b;
  return out;
}

}  // namespace collido::nurbs
