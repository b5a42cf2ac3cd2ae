// The exact triangle test of the collision query's last stages, with the sides of corners
// against planar faces kept for the query (face_signs.h).
#include "face_signs.h"

#include <collido/oracle/triangle_test.h>

#include "filtered_predicates.h"
#include "static_orientation.h"

namespace collido::obbtree::detail {

namespace {

// The orientation of corners sa, sb, sc, sd of the pair (0 to 2 A's, 3 to 5 B's): where the
// first three are one triangle's corners and the fourth is the other's, its face's sign, kept
// for the query, else `decide()`. `decide` returns kUnsure when it cannot; nothing is kept then.
template <typename Decide>
int keptOrDecided(const FaceSignPair& pair, FaceSignCache& cache, int sa, int sb, int sc, int sd,
                  Decide&& decide) {
  const int object = sa / 3;
  const bool keyed =
      sb / 3 == object && sc / 3 == object && sa != sb && sa != sc && sb != sc && sd / 3 != object;
  if (!keyed) return decide();
  const ObbTree& tree = *pair.tree[object];
  const std::int32_t triangle = pair.triangle[object];
  const std::int32_t face = tree.faceOf(triangle);
  // +1 when a, b, c follow the triangle's own turn, -1 the other way; and the triangle's turn
  // against its face's.
  const int factor = ((sb - sa + 3) % 3 == 1 ? 1 : -1) * tree.faceTurn(triangle);
  const std::int32_t vertex =
      pair.tree[1 - object]->orderedTriangles()(sd % 3, pair.triangle[1 - object]);
  const int kept = cache.find(object, face, vertex);
  if (kept != FaceSignCache::kNone) return kept * factor;
  const int sign = decide();
  if (sign != TrackedDoubleDouble::kUnsure) cache.store(object, face, vertex, sign * factor);
  return sign;
}

// Every corner exact in A's frame: the triangle test on the doubles themselves, each sign by
// the static filter (static_orientation.h), else by the exact predicate, the orientations of
// one triangle's plane against a corner of the other kept per face. Points are the pair's own
// corners, named by address.
class ModelFrameKernel {
 public:
  using Point = const UncertainPoint*;

  ModelFrameKernel(const FaceSignPair& pair, FaceSignCache& cache) : pair_(pair), cache_(cache) {}

  int orient3d(const Point& a, const Point& b, const Point& c, const Point& d) {
    const int sign = staticOrient3d(a->p, b->p, c->p, d->p);
    if (sign != kUndecidedSign) return sign;
    return keptOrDecided(pair_, cache_, slotOf(a), slotOf(b), slotOf(c), slotOf(d),
                         [&] { return exact::orient3d(a->p, b->p, c->p, d->p); });
  }

  int orient2d(const Point& a, const Point& b, const Point& c, int drop) {
    const int sign = staticOrient2d(a->p, b->p, c->p, drop);
    return sign != kUndecidedSign ? sign : exact::orient2d(a->p, b->p, c->p, drop);
  }

  bool collinear(const Point& a, const Point& b, const Point& c) {
    for (int drop = 0; drop < 3; ++drop) {
      if (orient2d(a, b, c, drop) != 0) return false;
    }
    return true;
  }

  int compare(const Point& a, const Point& b, int k) {
    const double x = a->p[k];
    const double y = b->p[k];
    return (x > y) - (x < y);
  }

 private:
  int slotOf(const Point& p) const {
    const UncertainPoint* a = pair_.corners[0];
    if (p == a) return 0;
    if (p == a + 1) return 1;
    if (p == a + 2) return 2;
    return 3 + static_cast<int>(p - pair_.corners[1]);
  }

  const FaceSignPair& pair_;
  FaceSignCache& cache_;
};

// The world positions as tracked double-doubles (TrackedWorldKernel), behind the certified
// filter on the corners in A's frame (orientations agree there). Points are the pair's own
// corners, named by address.
class WorldSignKernel {
 public:
  using Point = const UncertainPoint*;

  WorldSignKernel(const FaceSignPair& pair, FaceSignCache& cache) : pair_(pair), cache_(cache) {}

  bool unsure() const { return world_.unsure(); }

  int orient3d(const Point& a, const Point& b, const Point& c, const Point& d) {
    FilteredKernel filter;
    const int sign = filter.orient3d(*a, *b, *c, *d);
    if (!filter.unsure()) return sign;
    // Once the world kernel is unsure the answer is dropped, and nothing more is kept.
    const int decided =
        keptOrDecided(pair_, cache_, slotOf(a), slotOf(b), slotOf(c), slotOf(d), [&] {
          const int world_sign = world_.orient3d(world(a), world(b), world(c), world(d));
          return world_.unsure() ? TrackedDoubleDouble::kUnsure : world_sign;
        });
    return decided != TrackedDoubleDouble::kUnsure ? decided : 0;
  }

  // 2D orientations and coordinate comparisons depend on the frame: the world's.
  int orient2d(const Point& a, const Point& b, const Point& c, int drop) {
    return world_.orient2d(world(a), world(b), world(c), drop);
  }

  bool collinear(const Point& a, const Point& b, const Point& c) {
    FilteredKernel filter;  // collinearity is the same in every frame
    const bool answer = filter.collinear(*a, *b, *c);
    if (!filter.unsure()) return answer;
    return world_.collinear(world(a), world(b), world(c));
  }

  int compare(const Point& a, const Point& b, int k) {
    return world_.compare(world(a), world(b), k);
  }

 private:
  int slotOf(const Point& p) const {
    int slot = 0;
    while (slot < 5 && &pair_.mapped(slot) != p)
      ++slot;
    return slot;
  }

  const TrackedPoint& world(const Point& p) const { return pair_.world[slotOf(p)]->world(); }

  const FaceSignPair& pair_;
  FaceSignCache& cache_;
  TrackedWorldKernel world_;
};

// The pair's corners as the kernels name them (by address), and its known sides.
template <typename Kernel>
bool intersectOnKernel(const FaceSignPair& pair, Kernel& kernel) {
  using Test = exact::TriangleTest<Kernel>;
  const UncertainPoint* const a = pair.corners[0];
  const UncertainPoint* const b = pair.corners[1];
  const UncertainPoint* const t1[3] = {&a[0], &a[1], &a[2]};
  const UncertainPoint* const t2[3] = {&b[0], &b[1], &b[2]};
  static_assert(Test::kUnknownSide == kUndecidedSign, "one mark for a side not settled");
  return Test(kernel).intersectKnowingSides(t1, pair.sides_of_a, pair.proper[0], t2,
                                            pair.sides_of_b, pair.proper[1]);
}

}  // namespace

std::optional<bool> trianglesIntersectWithFaceSigns(const FaceSignPair& pair, ExactFrame frame,
                                                    FaceSignCache& cache) {
  if (frame == ExactFrame::kModelOfA) {
    ModelFrameKernel kernel(pair, cache);
    return intersectOnKernel(pair, kernel);
  }
  WorldSignKernel kernel(pair, cache);
  const bool answer = intersectOnKernel(pair, kernel);
  if (kernel.unsure()) return std::nullopt;
  return answer;
}

}  // namespace collido::obbtree::detail
