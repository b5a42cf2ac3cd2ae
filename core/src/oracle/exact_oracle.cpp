// The exact reference oracle.
//
// Cases of a triangle (after exact classification):
//   triangle - three non-collinear corners;
//   segment  - collinear corners, not all equal: the segment between the two extreme corners;
//   point    - all corners equal.
// A pair of elements is decided by a 3x3 dispatch table of CGAL do_intersect/has_on calls, all
// exact with the Epeck kernel. The world coordinates R*v + t are Epeck lazy numbers, so they are
// exact too; their interval approximations give conservative boxes for the grid prefilter.
#include <collido/oracle/exact_oracle.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/intersections.h>
#include <CGAL/squared_distance_3.h>

#include <collido/assert.h>
#include <collido/oracle/distance_oracle.h>

namespace collido {
namespace {

using EK = CGAL::Exact_predicates_exact_constructions_kernel;
using Point = EK::Point_3;
using FT = EK::FT;

enum ElementKind { kTriangleElement = 0, kSegmentElement = 1, kPointElement = 2 };

struct Box {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = Eigen::Vector3d::Constant(-std::numeric_limits<double>::infinity());

  void add(const Box& o) {
    lo = lo.cwiseMin(o.lo);
    hi = hi.cwiseMax(o.hi);
  }
  bool overlaps(const Box& o) const {
    return (lo.array() <= o.hi.array()).all() && (o.lo.array() <= hi.array()).all();
  }
  bool empty() const { return (lo.array() > hi.array()).any(); }
};

struct Element {
  ElementKind kind = kTriangleElement;
  Point p[3];  // triangle corners; a segment uses p[0], p[1]; a point p[0]
  Box box;
};

struct PosedMesh {
  std::vector<Element> elements;
  Box bounds;
};

Box boxOf(const Point& p) {
  Box b;
  for (int k = 0; k < 3; ++k) {
    const std::pair<double, double> range = CGAL::to_interval(p[k]);
    b.lo[k] = range.first;
    b.hi[k] = range.second;
  }
  return b;
}

std::vector<Point> poseVertices(const TriangleMesh& mesh, const Pose& pose) {
  const Eigen::Matrix3d& r = pose.linear();
  const Eigen::Vector3d& t = pose.translation();
  const bool identity = r == Eigen::Matrix3d::Identity() && t == Eigen::Vector3d::Zero();
  std::vector<Point> points;
  points.reserve(mesh.vertexCount());
  for (Eigen::Index v = 0; v < mesh.vertices.cols(); ++v) {
    const Eigen::Vector3d x = mesh.vertices.col(v);
    if (identity) {
      points.emplace_back(x.x(), x.y(), x.z());
      continue;
    }
    FT world[3];
    for (int row = 0; row < 3; ++row) {
      world[row] = FT(r(row, 0)) * FT(x.x()) + FT(r(row, 1)) * FT(x.y()) +
                   FT(r(row, 2)) * FT(x.z()) + FT(t[row]);
    }
    points.emplace_back(world[0], world[1], world[2]);
  }
  return points;
}

Element classify(const Point& a, const Point& b, const Point& c) {
  Element e;
  if (!CGAL::collinear(a, b, c)) {
    e.kind = kTriangleElement;
    e.p[0] = a;
    e.p[1] = b;
    e.p[2] = c;
  } else {
    Point sorted[3] = {a, b, c};
    std::sort(std::begin(sorted), std::end(sorted), [](const Point& x, const Point& y) {
      return CGAL::compare_xyz(x, y) == CGAL::SMALLER;
    });
    if (sorted[0] == sorted[2]) {
      e.kind = kPointElement;
      e.p[0] = sorted[0];
    } else {
      e.kind = kSegmentElement;
      e.p[0] = sorted[0];
      e.p[1] = sorted[2];
    }
  }
  e.box = boxOf(a);
  e.box.add(boxOf(b));
  e.box.add(boxOf(c));
  return e;
}

PosedMesh poseMesh(const TriangleMesh& mesh, const Pose& pose) {
  const std::vector<Point> points = poseVertices(mesh, pose);
  PosedMesh out;
  out.elements.reserve(mesh.triangleCount());
  for (Eigen::Index t = 0; t < mesh.triangles.cols(); ++t) {
    out.elements.push_back(classify(points[static_cast<std::size_t>(mesh.triangles(0, t))],
                                    points[static_cast<std::size_t>(mesh.triangles(1, t))],
                                    points[static_cast<std::size_t>(mesh.triangles(2, t))]));
    out.bounds.add(out.elements.back().box);
  }
  return out;
}

EK::Triangle_3 triangleOf(const Element& e) {
  return {e.p[0], e.p[1], e.p[2]};
}
EK::Segment_3 segmentOf(const Element& e) {
  return {e.p[0], e.p[1]};
}

bool triTri(const Element& x, const Element& y) {
  return CGAL::do_intersect(triangleOf(x), triangleOf(y));
}
bool triSeg(const Element& x, const Element& y) {
  return CGAL::do_intersect(triangleOf(x), segmentOf(y));
}
bool triPoint(const Element& x, const Element& y) {
  return triangleOf(x).has_on(y.p[0]);
}
bool segTri(const Element& x, const Element& y) {
  return triSeg(y, x);
}
bool segSeg(const Element& x, const Element& y) {
  return CGAL::do_intersect(segmentOf(x), segmentOf(y));
}
bool segPoint(const Element& x, const Element& y) {
  return segmentOf(x).has_on(y.p[0]);
}
bool pointTri(const Element& x, const Element& y) {
  return triPoint(y, x);
}
bool pointSeg(const Element& x, const Element& y) {
  return segPoint(y, x);
}
bool pointPoint(const Element& x, const Element& y) {
  return x.p[0] == y.p[0];
}

using ExactTest = bool (*)(const Element&, const Element&);
constexpr ExactTest kExactTests[3][3] = {
    {&triTri, &triSeg, &triPoint},
    {&segTri, &segSeg, &segPoint},
    {&pointTri, &pointSeg, &pointPoint},
};

bool elementsIntersect(const Element& x, const Element& y) {
  return kExactTests[x.kind][y.kind](x, y);
}

// Exact squared distances, by the same dispatch; 0 for elements that share a point.
FT triTriDistance(const Element& x, const Element& y) {
  if (triTri(x, y)) return FT(0);
  return CGAL::squared_distance(triangleOf(x), triangleOf(y));
}
FT triSegDistance(const Element& x, const Element& y) {
  if (triSeg(x, y)) return FT(0);
  const EK::Triangle_3 t = triangleOf(x);
  const EK::Segment_3 s = segmentOf(y);
  FT best = CGAL::min(CGAL::squared_distance(s.source(), t), CGAL::squared_distance(s.target(), t));
  for (int i = 0; i < 3; ++i)
    best = CGAL::min(best, CGAL::squared_distance(s, EK::Segment_3(x.p[i], x.p[(i + 1) % 3])));
  return best;
}
FT triPointDistance(const Element& x, const Element& y) {
  return CGAL::squared_distance(y.p[0], triangleOf(x));
}
FT segTriDistance(const Element& x, const Element& y) {
  return triSegDistance(y, x);
}
FT segSegDistance(const Element& x, const Element& y) {
  return CGAL::squared_distance(segmentOf(x), segmentOf(y));
}
FT segPointDistance(const Element& x, const Element& y) {
  return CGAL::squared_distance(y.p[0], segmentOf(x));
}
FT pointTriDistance(const Element& x, const Element& y) {
  return triPointDistance(y, x);
}
FT pointSegDistance(const Element& x, const Element& y) {
  return segPointDistance(y, x);
}
FT pointPointDistance(const Element& x, const Element& y) {
  return CGAL::squared_distance(x.p[0], y.p[0]);
}

// --- exact closest points --------------------------------------------------------------------

// The corners of an element: 3, 2 or 1.
int cornerCount(const Element& e) {
  return e.kind == kTriangleElement ? 3 : e.kind == kSegmentElement ? 2 : 1;
}

FT clamp01(const FT& x) {
  if (x < FT(0)) return FT(0);
  if (x > FT(1)) return FT(1);
  return x;
}

// The closest points of segments [p0, p1] and [q0, q1] (either may be a point), exactly: the
// minimiser over the parameter square, clamped (parallel segments take s = 0 first).
void closestOnSegments(const Point& p0, const Point& p1, const Point& q0, const Point& q1,
                       Point& on_p, Point& on_q) {
  const EK::Vector_3 u = p1 - p0;
  const EK::Vector_3 v = q1 - q0;
  const EK::Vector_3 r = p0 - q0;
  const FT a = u * u;
  const FT e = v * v;
  const FT f = v * r;
  FT s(0);
  FT t(0);
  if (a == FT(0) && e == FT(0)) {
    // two points
  } else if (a == FT(0)) {
    t = clamp01(f / e);
  } else {
    const FT c = u * r;
    if (e == FT(0)) {
      s = clamp01(-c / a);
    } else {
      const FT b = u * v;
      const FT denominator = a * e - b * b;
      s = denominator > FT(0) ? clamp01((b * f - c * e) / denominator) : FT(0);
      t = (b * s + f) / e;
      if (t < FT(0)) {
        t = FT(0);
        s = clamp01(-c / a);
      } else if (t > FT(1)) {
        t = FT(1);
        s = clamp01((b - c) / a);
      }
    }
  }
  on_p = p0 + s * u;
  on_q = q0 + t * v;
}

// The edges of an element as segments (a segment's one, a point's degenerate one).
std::vector<std::pair<Point, Point>> edgesOf(const Element& e) {
  if (e.kind == kPointElement) return {{e.p[0], e.p[0]}};
  if (e.kind == kSegmentElement) return {{e.p[0], e.p[1]}};
  return {{e.p[0], e.p[1]}, {e.p[1], e.p[2]}, {e.p[2], e.p[0]}};
}

// The closest points of two elements that do not meet: for disjoint closed triangles (segments,
// points) the minimum is attained between two edges or between a corner and the other's face.
void closestPointsOfElements(const Element& x, const Element& y, Point& on_x, Point& on_y) {
  bool found = false;
  FT best(0);
  const auto consider = [&](const Point& p, const Point& q) {
    const FT d2 = CGAL::squared_distance(p, q);
    if (!found || d2 < best) {
      found = true;
      best = d2;
      on_x = p;
      on_y = q;
    }
  };
  for (const auto& [p0, p1] : edgesOf(x)) {
    for (const auto& [q0, q1] : edgesOf(y)) {
      Point p;
      Point q;
      closestOnSegments(p0, p1, q0, q1, p, q);
      consider(p, q);
    }
  }
  // A corner against the other's face, where its projection falls inside the face.
  const auto corner_face = [&](const Element& face, const Element& corners, bool face_is_x) {
    if (face.kind != kTriangleElement) return;
    const EK::Plane_3 plane(face.p[0], face.p[1], face.p[2]);
    const EK::Triangle_3 triangle = triangleOf(face);
    for (int i = 0; i < cornerCount(corners); ++i) {
      const Point projected = plane.projection(corners.p[i]);
      if (!triangle.has_on(projected)) continue;
      if (face_is_x) {
        consider(projected, corners.p[i]);
      } else {
        consider(corners.p[i], projected);
      }
    }
  };
  corner_face(x, y, true);
  corner_face(y, x, false);
}

// The points of an exact intersection result: a point, a segment's ends, a triangle's corners
// or a polygon's (CGAL 5.5: a boost::optional of a boost::variant over those).
template <typename Result>
void collectPoints(const Result& result, std::vector<Point>& points) {
  if (!result) return;
  if (const Point* p = boost::get<Point>(&*result)) {
    points.push_back(*p);
  } else if (const EK::Segment_3* s = boost::get<EK::Segment_3>(&*result)) {
    points.push_back(s->source());
    points.push_back(s->target());
  }
}

std::vector<Point> intersectionPoints(const Element& x, const Element& y) {
  std::vector<Point> points;
  if (x.kind == kPointElement) return {x.p[0]};
  if (y.kind == kPointElement) return {y.p[0]};
  if (x.kind == kTriangleElement && y.kind == kTriangleElement) {
    const auto result = CGAL::intersection(triangleOf(x), triangleOf(y));
    if (!result) return points;
    if (const EK::Triangle_3* t = boost::get<EK::Triangle_3>(&*result)) {
      for (int k = 0; k < 3; ++k)
        points.push_back(t->vertex(k));
    } else if (const auto* polygon = boost::get<std::vector<Point>>(&*result)) {
      points = *polygon;
    } else {
      collectPoints(result, points);
    }
  } else if (x.kind == kTriangleElement) {
    collectPoints(CGAL::intersection(triangleOf(x), segmentOf(y)), points);
  } else if (y.kind == kTriangleElement) {
    collectPoints(CGAL::intersection(triangleOf(y), segmentOf(x)), points);
  } else {
    collectPoints(CGAL::intersection(segmentOf(x), segmentOf(y)), points);
  }
  return points;
}

using ExactDistance = FT (*)(const Element&, const Element&);
constexpr ExactDistance kExactDistances[3][3] = {
    {&triTriDistance, &triSegDistance, &triPointDistance},
    {&segTriDistance, &segSegDistance, &segPointDistance},
    {&pointTriDistance, &pointSegDistance, &pointPointDistance},
};

// One triangle given by its model corners, posed exactly and classified.
Element posedElement(const std::array<Eigen::Vector3d, 3>& corners, const Pose& pose) {
  TriangleMesh single;
  single.vertices.resize(3, 3);
  for (int k = 0; k < 3; ++k)
    single.vertices.col(k) = corners[static_cast<std::size_t>(k)];
  single.triangles = Eigen::Matrix3Xi(3, 1);
  single.triangles.col(0) << 0, 1, 2;
  return poseMesh(single, pose).elements.front();
}

Element posedElement(const TriangleMesh& mesh, const Pose& pose, std::int32_t t) {
  std::array<Eigen::Vector3d, 3> corners;
  for (int k = 0; k < 3; ++k)
    corners[static_cast<std::size_t>(k)] = mesh.corner(static_cast<std::size_t>(t), k);
  return posedElement(corners, pose);
}

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
  const PosedMesh posed_a = poseMesh(a, pose_a);
  const PosedMesh posed_b = poseMesh(b, pose_b);
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
      if (!elementsIntersect(ea, eb)) return true;
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
  return elementsIntersect(posedElement(a, pose_a, pair.a), posedElement(b, pose_b, pair.b));
}

double exactPairSquaredDistance(const TriangleMesh& a, const Pose& pose_a, const TriangleMesh& b,
                                const Pose& pose_b, const TrianglePair& pair) {
  const Element x = posedElement(a, pose_a, pair.a);
  const Element y = posedElement(b, pose_b, pair.b);
  const FT d2 = kExactDistances[x.kind][y.kind](x, y);
  return CGAL::to_double(d2.exact());
}

ExactClosestPoints exactPosedClosestPoints(const std::array<Eigen::Vector3d, 3>& a,
                                           const Pose& pose_a,
                                           const std::array<Eigen::Vector3d, 3>& b,
                                           const Pose& pose_b) {
  const Element x = posedElement(a, pose_a);
  const Element y = posedElement(b, pose_b);
  ExactClosestPoints answer;
  const auto rounded = [](const Point& p) {
    return Eigen::Vector3d(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  };
  Point best_a;
  Point best_b;
  if (elementsIntersect(x, y)) {
    const std::vector<Point> shared = intersectionPoints(x, y);
    COLLIDO_ASSERT(!shared.empty(), "exact intersection of intersecting elements is empty");
    best_a = shared.front();  // a point both share
    best_b = best_a;
  } else {
    closestPointsOfElements(x, y, best_a, best_b);
  }
  const FT d2 = CGAL::squared_distance(best_a, best_b);
  const auto& exact = d2.exact();
  const std::pair<double, double> bounds = CGAL::to_interval(exact);
  answer.squared_distance = ExactInterval{bounds.first, CGAL::to_double(exact), bounds.second};
  answer.point_a = rounded(best_a);
  answer.point_b = rounded(best_b);
  return answer;
}

ExactIntersection exactPairIntersection(const TriangleMesh& a, const Pose& pose_a,
                                        const TriangleMesh& b, const Pose& pose_b,
                                        const TrianglePair& pair) {
  const Element x = posedElement(a, pose_a, pair.a);
  const Element y = posedElement(b, pose_b, pair.b);
  ExactIntersection answer;
  if (!elementsIntersect(x, y)) return answer;
  const std::vector<Point> points = intersectionPoints(x, y);
  for (const Point& p : points) {
    answer.points.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()),
                               CGAL::to_double(p.z()));
  }
  answer.shape = points.empty()       ? ExactIntersection::Shape::kEmpty
                 : points.size() == 1 ? ExactIntersection::Shape::kPoint
                 : points.size() == 2 ? ExactIntersection::Shape::kSegment
                                      : ExactIntersection::Shape::kPolygon;
  return answer;
}

bool exactTrianglesIntersect(const std::array<Eigen::Vector3d, 3>& t1,
                             const std::array<Eigen::Vector3d, 3>& t2) {
  const auto point = [](const Eigen::Vector3d& p) { return Point(p.x(), p.y(), p.z()); };
  return elementsIntersect(classify(point(t1[0]), point(t1[1]), point(t1[2])),
                           classify(point(t2[0]), point(t2[1]), point(t2[2])));
}

}  // namespace collido
