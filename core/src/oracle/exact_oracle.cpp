// The exact reference oracle: every intersecting triangle pair of two posed meshes, candidates
// from a uniform grid over conservative boxes, each decided by exact predicates
// (exact_elements.h).
#include <collido/oracle/exact_oracle.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "exact_elements.h"

namespace collido {
namespace {

using exact::Box;
using exact::Element;
using exact::Point;
using exact::PosedMesh;

// A uniform grid over the region where the two meshes' bounds overlap, holding A's elements.
class Grid {
 public:
  Grid(const PosedMesh& a, const PosedMesh& b, const Box& region) : region_(region) {
    // Cell size from the mean element extent of both meshes, so that a typical element covers
    // a few cells; the cell count is capped relative to the element count.
    Eigen::Vector3d extent_sum = Eigen::Vector3d::Zero();
    std::size_t count = 0;
    for (const PosedMesh* m : {&a, &b}) {
      for (const Element& e : m->elements) {
        if (!e.box.overlaps(region)) continue;
        extent_sum += e.box.hi - e.box.lo;
        ++count;
      }
    }
    const Eigen::Vector3d size = region.hi - region.lo;
    const double max_cells = 4.0 * static_cast<double>(std::max<std::size_t>(count, 1)) + 8.0;
    Eigen::Vector3d cell = extent_sum / static_cast<double>(std::max<std::size_t>(count, 1));
    for (int k = 0; k < 3; ++k) {
      cell[k] = std::max(cell[k], size[k] * 1e-6);
      if (!(cell[k] > 0.0)) cell[k] = 1.0;
    }
    for (;;) {
      for (int k = 0; k < 3; ++k) {
        dims_[k] = static_cast<int>(std::clamp(std::floor(size[k] / cell[k]) + 1.0, 1.0, 1024.0));
      }
      if (static_cast<double>(dims_[0]) * dims_[1] * dims_[2] <= max_cells) break;
      cell *= 1.5;
    }
    for (int k = 0; k < 3; ++k)
      inv_cell_[k] = dims_[k] / std::max(size[k], 1e-300);

    // Counting sort of A's elements into cells (CSR layout).
    const std::size_t cells = static_cast<std::size_t>(dims_[0]) * dims_[1] * dims_[2];
    start_.assign(cells + 1, 0);
    forEachCellOfA(a, [&](std::size_t cell_index, std::size_t) { ++start_[cell_index + 1]; });
    for (std::size_t c = 0; c < cells; ++c)
      start_[c + 1] += start_[c];
    items_.resize(start_[cells]);
    std::vector<std::size_t> fill(start_.begin(), start_.end() - 1);
    forEachCellOfA(a, [&](std::size_t cell_index, std::size_t element) {
      items_[fill[cell_index]++] = static_cast<std::uint32_t>(element);
    });
  }

  // Calls visit(a_element) for every A element sharing a cell with `box` (with repeats).
  template <typename Visit>
  bool forEachNear(const Box& box, Visit&& visit) const {
    int lo[3];
    int hi[3];
    if (!cellRange(box, lo, hi)) return true;
    for (int z = lo[2]; z <= hi[2]; ++z) {
      for (int y = lo[1]; y <= hi[1]; ++y) {
        for (int x = lo[0]; x <= hi[0]; ++x) {
          const std::size_t c = index(x, y, z);
          for (std::size_t i = start_[c]; i < start_[c + 1]; ++i) {
            if (!visit(items_[i])) return false;
          }
        }
      }
    }
    return true;
  }

 private:
  template <typename Add>
  void forEachCellOfA(const PosedMesh& a, Add&& add) const {
    for (std::size_t e = 0; e < a.elements.size(); ++e) {
      int lo[3];
      int hi[3];
      if (!cellRange(a.elements[e].box, lo, hi)) continue;
      for (int z = lo[2]; z <= hi[2]; ++z) {
        for (int y = lo[1]; y <= hi[1]; ++y) {
          for (int x = lo[0]; x <= hi[0]; ++x)
            add(index(x, y, z), e);
        }
      }
    }
  }

  bool cellRange(const Box& box, int lo[3], int hi[3]) const {
    if (!box.overlaps(region_)) return false;
    for (int k = 0; k < 3; ++k) {
      const double from = (std::max(box.lo[k], region_.lo[k]) - region_.lo[k]) * inv_cell_[k];
      const double to = (std::min(box.hi[k], region_.hi[k]) - region_.lo[k]) * inv_cell_[k];
      lo[k] = std::clamp(static_cast<int>(std::floor(from)), 0, dims_[k] - 1);
      hi[k] = std::clamp(static_cast<int>(std::floor(to)), 0, dims_[k] - 1);
    }
    return true;
  }

  std::size_t index(int x, int y, int z) const {
    return (static_cast<std::size_t>(z) * dims_[1] + y) * dims_[0] + x;
  }

  Box region_;
  int dims_[3] = {1, 1, 1};
  Eigen::Vector3d inv_cell_ = Eigen::Vector3d::Ones();
  std::vector<std::size_t> start_;
  std::vector<std::uint32_t> items_;
};

}  // namespace

OracleAnswer exactIntersectingPairs(const TriangleMesh& a, const Pose& pose_a,
                                    const TriangleMesh& b, const Pose& pose_b, OracleMode mode) {
  OracleAnswer answer;
  const PosedMesh posed_a = exact::poseMesh(a, pose_a);
  const PosedMesh posed_b = exact::poseMesh(b, pose_b);
  Box region;
  region.lo = posed_a.bounds.lo.cwiseMax(posed_b.bounds.lo);
  region.hi = posed_a.bounds.hi.cwiseMin(posed_b.bounds.hi);
  if (region.empty()) return answer;

  const Grid grid(posed_a, posed_b, region);
  std::vector<std::uint32_t> last_visit(posed_a.elements.size(),
                                        std::numeric_limits<std::uint32_t>::max());
  for (std::size_t j = 0; j < posed_b.elements.size(); ++j) {
    const Element& eb = posed_b.elements[j];
    const bool go_on = grid.forEachNear(eb.box, [&](std::uint32_t i) {
      if (last_visit[i] == j) return true;  // already seen through another cell
      last_visit[i] = static_cast<std::uint32_t>(j);
      const Element& ea = posed_a.elements[i];
      if (!ea.box.overlaps(eb.box)) return true;
      ++answer.candidate_pairs;
      ++answer.exact_tests;
      if (!exact::elementsIntersect(ea, eb)) return true;
      answer.pairs.push_back(
          TrianglePair{static_cast<std::int32_t>(i), static_cast<std::int32_t>(j)});
      return mode == OracleMode::kAllPairs;
    });
    if (!go_on) break;
  }
  std::sort(answer.pairs.begin(), answer.pairs.end());
  answer.intersecting = !answer.pairs.empty();
  return answer;
}

bool exactPairIntersects(const TriangleMesh& a, const Pose& pose_a, const TriangleMesh& b,
                         const Pose& pose_b, const TrianglePair& pair) {
  return exact::elementsIntersect(exact::posedElement(a, pose_a, pair.a),
                                  exact::posedElement(b, pose_b, pair.b));
}

bool exactTrianglesIntersect(const std::array<Eigen::Vector3d, 3>& t1,
                             const std::array<Eigen::Vector3d, 3>& t2) {
  const auto point = [](const Eigen::Vector3d& p) { return Point(p.x(), p.y(), p.z()); };
  return exact::elementsIntersect(exact::classify(point(t1[0]), point(t1[1]), point(t1[2])),
                                  exact::classify(point(t2[0]), point(t2[1]), point(t2[2])));
}

}  // namespace collido
