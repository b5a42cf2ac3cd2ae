// The seed method's guaranteed collision test between two FRep solids: best-first octree
// subdivision of the common bounds with interval bounds of both functions.
#include <collido/frep/collision.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <stdexcept>

#include "bounds_util.h"

namespace collido::frep {
namespace {

struct Cell {
  Eigen::AlignedBox3d box;
  int depth;
  double priority;  // upper bound of min(f1, f2) over the cell: the most promising first
};

struct LowerPriority {
  bool operator()(const Cell& a, const Cell& b) const { return a.priority < b.priority; }
};

bool provedInsideBoth(const Solid& a, const Solid& b, const Eigen::Vector3d& p) {
  const IntervalBox at = IntervalBox::ofPoint(p);
  return a.range(at).lower() >= 0.0 && b.range(at).lower() >= 0.0;
}

// Levels until the longest side is at most the precision; capped where doubles would stop
// halving a cell anyway (2^-1074 of its size).
int depthFor(const Eigen::AlignedBox3d& domain, double precision) {
  const double longest = domain.sizes().maxCoeff();
  if (!(longest > precision)) return 0;
  return static_cast<int>(std::min(1100.0, std::ceil(std::log2(longest / precision))));
}

// A bound that rounding or overflow made NaN says nothing: the whole line.
Interval knownOrUnbounded(const Interval& range) {
  if (std::isnan(range.lower()) || std::isnan(range.upper()))
    return Interval(-std::numeric_limits<double>::infinity(),
                    std::numeric_limits<double>::infinity());
  return range;
}

}  // namespace

const char* verdictName(CollisionVerdict verdict) {
  switch (verdict) {
    case CollisionVerdict::kColliding:
      return "colliding";
    case CollisionVerdict::kSeparated:
      return "separated";
    case CollisionVerdict::kTouching:
      return "touching";
    case CollisionVerdict::kUndecided:
      return "undecided";
  }
  return "undecided";
}

std::optional<CollisionVerdict> parseVerdict(const std::string& name) {
  for (const CollisionVerdict verdict :
       {CollisionVerdict::kColliding, CollisionVerdict::kSeparated, CollisionVerdict::kTouching,
        CollisionVerdict::kUndecided}) {
    if (name == verdictName(verdict)) return verdict;
  }
  return std::nullopt;
}

CollisionResult collide(const Solid& a, const Solid& b, const CollisionOptions& options) {
  if (!(options.precision > 0) || !std::isfinite(options.precision))
    throw std::invalid_argument("collision precision must be finite and > 0");
  CollisionResult result;
  result.domain = detail::intersectionOf(a.bounds(), b.bounds());
  if (result.domain.isEmpty()) {
    result.verdict = CollisionVerdict::kSeparated;
    return result;
  }
  if (!detail::isFinite(result.domain)) {
    throw std::invalid_argument(
        "the two solids' common bounds are unbounded: intersect an unbounded solid (a half-space, "
        "an open cylinder or cone, a projection) with a bounded one");
  }
  result.max_depth = depthFor(result.domain, options.precision);
  result.levels.resize(static_cast<std::size_t>(result.max_depth) + 1);

  std::priority_queue<Cell, std::vector<Cell>, LowerPriority> open;
  const auto visit = [&](const Eigen::AlignedBox3d& box, int depth) {
    CollisionLevel& level = result.levels[static_cast<std::size_t>(depth)];
    ++level.cells;
    ++result.cells;
    const IntervalBox cell = IntervalBox::of(box);
    const Interval fa = knownOrUnbounded(a.range(cell));
    if (fa.upper() < 0.0) {
      ++level.discarded;
      return false;
    }
    const Interval fb = knownOrUnbounded(b.range(cell));
    if (fb.upper() < 0.0) {
      ++level.discarded;
      return false;
    }
    const Eigen::Vector3d centre = box.center();  // not finite only for boxes near DBL_MAX
    if ((fa.lower() >= 0.0 && fb.lower() >= 0.0 && centre.allFinite()) ||
        (centre.allFinite() && provedInsideBoth(a, b, centre))) {
      result.verdict = CollisionVerdict::kColliding;
      result.witness = centre;
      return true;
    }
    open.push(Cell{box, depth, std::min(fa.upper(), fb.upper())});
    return false;
  };

  if (visit(result.domain, 0)) return result;
  while (!open.empty()) {
    const Cell cell = open.top();
    open.pop();
    if (cell.depth >= result.max_depth) {
      ++result.undecided_cells;
      if (result.touching_cells.size() < CollisionResult::kMaxKeptCells)
        result.touching_cells.push_back(cell.box);
      continue;
    }
    if (result.cells + 8 > options.max_cells) {
      result.verdict = CollisionVerdict::kUndecided;
      return result;
    }
    ++result.levels[static_cast<std::size_t>(cell.depth)].split;
    const Eigen::Vector3d centre = cell.box.center();
    for (int corner = 0; corner < 8; ++corner) {
      const Eigen::Vector3d far =
          cell.box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(corner));
      const Eigen::AlignedBox3d child(centre.cwiseMin(far), centre.cwiseMax(far));
      if (visit(child, cell.depth + 1)) return result;
    }
  }
  result.verdict =
      result.undecided_cells > 0 ? CollisionVerdict::kTouching : CollisionVerdict::kSeparated;
  return result;
}

}  // namespace collido::frep
