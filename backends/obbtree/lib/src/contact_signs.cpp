#include "contact_signs.h"

#include <cmath>
#include <limits>

#include "filtered_predicates.h"

namespace collido::obbtree::detail {

PosedCorner posedCorner(const Eigen::Vector3d& model, const Eigen::Isometry3d& pose,
                        bool pose_in_range) {
  constexpr double kUnit = std::numeric_limits<double>::epsilon() / 2.0;
  const Eigen::Matrix3d& r = pose.linear();
  const Eigen::Vector3d& t = pose.translation();
  PosedCorner corner;
  corner.exact = PosedModelPoint(model, pose);
  corner.tracked = LazyWorldPoint(model, pose, pose_in_range);
  for (int row = 0; row < 3; ++row) {
    // Error-free transformations tell whether every product and sum was exact: then the double
    // is the exact world coordinate (radius 0, and the filter's exact predicates on doubles
    // settle zeros: faces at exact offsets, the usual CAD case).
    double sum = t[row];
    double magnitude = std::abs(t[row]);
    bool exact = true;
    for (int k = 0; k < 3; ++k) {
      const double product = r(row, k) * model[k];
      exact = exact && std::fma(r(row, k), model[k], -product) == 0.0;
      const double next = sum + product;
      const double product_part = next - sum;  // Knuth's TwoSum: the addition's exact error
      const double sum_part = next - product_part;
      exact = exact && (sum - sum_part) + (product - product_part) == 0.0;
      sum = next;
      magnitude += std::abs(product);
    }
    corner.world.p[row] = sum;
    // Four roundings of a sum of four terms: within 4u/(1 - 4u) of the sum of their magnitudes;
    // 5u covers that and the rounding of the magnitudes' own sum.
    corner.world.error[row] = exact ? 0.0 : 5.0 * kUnit * magnitude;
  }
  return corner;
}

int ContactSignKernel::settle(const std::optional<int>& sign) {
  if (sign) return *sign;
  failed_ = true;
  return 0;
}

namespace {

bool trackedInRange(const PosedCorner* corner) {
  return corner->tracked.inRange();
}

}  // namespace

int ContactSignKernel::orient2d(const Point& a, const Point& b, const Point& c, int drop) {
  FilteredKernel filter;
  const int sign = filter.orient2d(a->world, b->world, c->world, drop);
  if (!filter.unsure()) return sign;
  if (trackedInRange(a) && trackedInRange(b) && trackedInRange(c)) {
    const std::optional<int> tracked = certainSignOf(
        trackedOrient2d(a->tracked.world(), b->tracked.world(), c->tracked.world(), drop));
    if (tracked) return *tracked;
  }
  return settle(posedOrient2dByExpansions(a->exact, b->exact, c->exact, drop));
}

int ContactSignKernel::compare(const Point& a, const Point& b, int k) {
  FilteredKernel filter;
  const int sign = filter.compare(a->world, b->world, k);
  if (!filter.unsure()) return sign;
  if (trackedInRange(a) && trackedInRange(b)) {
    const std::optional<int> tracked =
        certainSignOf(a->tracked.world().x[k] - b->tracked.world().x[k]);
    if (tracked) return *tracked;
  }
  return settle(posedCompareByExpansions(a->exact, b->exact, k));
}

std::optional<TrackedDoubleDouble> PlaneSides::tracked(std::size_t side, std::size_t k) {
  std::optional<TrackedDoubleDouble>& determinant = determinants_[side][k];
  if (determinant) return determinant;
  const PosedTriangle& plane = side == 0 ? a_ : b_;
  const PosedCorner* corner = side == 0 ? b_[k] : a_[k];
  if (!trackedInRange(plane[0]) || !trackedInRange(plane[1]) || !trackedInRange(plane[2]) ||
      !trackedInRange(corner))
    return std::nullopt;
  // Kept for the query by the plane's triangle and the corner's vertex, where named.
  const bool named = known_ != nullptr && names_ != nullptr;
  const int object = static_cast<int>(side);
  const std::int32_t triangle = named ? names_->triangle[side] : 0;
  const std::int32_t vertex = named ? names_->vertices[1 - side][k] : 0;
  if (named) {
    if (const TrackedDoubleDouble* kept = known_->determinant(object, triangle, vertex)) {
      determinant = *kept;
      return determinant;
    }
  }
  std::optional<TrackedPlane>& tracked_plane = planes_[side];
  if (!tracked_plane) {
    const TrackedPlane* kept = named ? known_->plane(object, triangle) : nullptr;
    if (kept != nullptr) {
      tracked_plane = *kept;
    } else {
      tracked_plane.emplace(plane[0]->tracked.world(), plane[1]->tracked.world(),
                            plane[2]->tracked.world());
      if (named) known_->keepPlane(object, triangle, *tracked_plane);
    }
  }
  determinant = tracked_plane->orient3d(corner->tracked.world());
  if (named) known_->keepDeterminant(object, triangle, vertex, *determinant);
  return determinant;
}

std::optional<double> PlaneSides::value(std::size_t side, std::size_t k) {
  Memo& memo = values_[side][k];
  if (!memo.computed) {
    // hi is the double nearest the tracked value; a radius within an ulp of it keeps hi within
    // 1.5 ulps of the exact determinant (an exact zero has radius 0).
    const std::optional<TrackedDoubleDouble> close = tracked(side, k);
    if (close && close->radius <= std::abs(close->hi) * 0x1p-52) {
      memo.value = close->hi;
      memo.computed = true;
      return memo.value;
    }
    const PosedTriangle& plane = side == 0 ? a_ : b_;
    const PosedCorner* corner = side == 0 ? b_[k] : a_[k];
    memo.value = posedOrient3dValueByExpansions(plane[0]->exact, plane[1]->exact, plane[2]->exact,
                                                corner->exact);
    memo.computed = true;
  }
  return memo.value;
}

std::optional<PlaneSigns> PlaneSides::signs() {
  PlaneSigns signs{};
  for (std::size_t side = 0; side < 2; ++side) {
    const PosedTriangle& plane = side == 0 ? a_ : b_;
    const PosedTriangle& other = side == 0 ? b_ : a_;
    for (std::size_t k = 0; k < 3; ++k) {
      FilteredKernel filter;
      signs[side][k] =
          filter.orient3d(plane[0]->world, plane[1]->world, plane[2]->world, other[k]->world);
      if (!filter.unsure()) continue;
      // A sign the filter cannot settle: the corner's vertex against the plane's face, if kept.
      const int object = static_cast<int>(side);
      const std::int32_t face = names_ ? names_->face[side] : 0;
      const std::int32_t vertex = names_ ? names_->vertices[1 - side][k] : 0;
      const int turn = names_ ? names_->turn[side] : 1;
      if (cache_) {
        const int kept = cache_->find(object, face, vertex);
        if (kept != FaceSignCache::kNone) {
          signs[side][k] = kept * turn;
          continue;
        }
      }
      const std::optional<TrackedDoubleDouble> close = tracked(side, k);
      const std::optional<int> tracked_sign = close ? certainSignOf(*close) : std::nullopt;
      if (tracked_sign) {
        signs[side][k] = *tracked_sign;
      } else {
        // An expansion's rounded value keeps its exact sign: its largest component outweighs
        // the others together, and the inputs' range keeps it from underflowing to zero.
        const std::optional<double> exact = value(side, k);
        if (!exact) return std::nullopt;
        signs[side][k] = (*exact > 0.0) - (*exact < 0.0);
      }
      if (cache_) cache_->store(object, face, vertex, signs[side][k] * turn);
    }
  }
  return signs;
}

}  // namespace collido::obbtree::detail
