// The 15-axis separating-axis test against a brute-force box-box test that does not use
// separating axes: two closed boxes intersect iff an edge of one meets the other box (segment
// clipping against the slabs) or one contains the other (then it contains its centre).
//
// The brute force rounds too (by a few ulps of the boxes' size), so it is trusted only where its
// rounding cannot matter:
//  - when it says "intersect" and the SAT says "separated", an exact referee decides: the linear
//    program "some point of B (centre + R w, |w| <= half_b) lies in A", solved by Fourier-Motzkin
//    elimination in rational arithmetic on the very doubles the SAT was given. The SAT is wrong
//    only if that program is feasible (no tolerance at all in this direction);
//  - when A widened by a gap `delta` (1e-9 relative) still misses B, the boxes are clearly apart
//    and the SAT must say "separated" (its margin is ~1e-12 relative).
#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <CGAL/Exact_rational.h>
#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <collido/obbtree/separating_axis.h>

namespace collido::obbtree {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

// A box B given in A's box frame, as boxesOverlap takes it; A is axis-aligned at the origin.
struct BoxPair {
  Matrix3d rotation = Matrix3d::Identity();  // B's axes as columns
  Vector3d translation = Vector3d::Zero();   // B's centre
  Vector3d half_a = Vector3d::Ones();
  Vector3d half_b = Vector3d::Ones();
};

std::string describe(const BoxPair& p) {
  std::ostringstream out;
  out.precision(17);
  out << "half_a " << p.half_a.transpose() << ", half_b " << p.half_b.transpose()
      << ", translation " << p.translation.transpose() << ", rotation rows [" << p.rotation.row(0)
      << "; " << p.rotation.row(1) << "; " << p.rotation.row(2) << "]";
  return out.str();
}

bool sat(const BoxPair& p) {
  return boxesOverlap(p.rotation, p.translation, p.half_a, p.half_b);
}

// Brute force in plain scalars (it runs ~10^5 times per test in Debug builds).
using P3 = std::array<double, 3>;

// Whether the closed segment u-v meets the closed box |x_k| <= half_k, both in the box's frame
// (Liang-Barsky clipping of the parameter interval [0, 1] against the three slabs).
bool segmentMeetsBox(const P3& u, const P3& v, const P3& half) {
  double lo = 0.0;
  double hi = 1.0;
  for (std::size_t k = 0; k < 3; ++k) {
    const double d = v[k] - u[k];
    if (d == 0.0) {
      if (std::abs(u[k]) > half[k]) return false;
      continue;
    }
    double t0 = (-half[k] - u[k]) / d;
    double t1 = (half[k] - u[k]) / d;
    if (t0 > t1) std::swap(t0, t1);
    lo = std::max(lo, t0);
    hi = std::min(hi, t1);
    if (lo > hi) return false;
  }
  return true;
}

// The corners (+-half) of a box mapped by x -> m x + c (m applied transposed when `transpose`).
std::array<P3, 8> mappedCorners(const Matrix3d& m, bool transpose, const P3& half, const P3& c) {
  std::array<P3, 8> out;
  for (int i = 0; i < 8; ++i) {
    const P3 s{(i & 1) ? half[0] : -half[0], (i & 2) ? half[1] : -half[1],
               (i & 4) ? half[2] : -half[2]};
    for (int r = 0; r < 3; ++r) {
      double sum = 0.0;
      for (int k = 0; k < 3; ++k) {
        sum += (transpose ? m(k, r) : m(r, k)) *
               (s[static_cast<std::size_t>(k)] + c[static_cast<std::size_t>(k)]);
      }
      out[static_cast<std::size_t>(i)][static_cast<std::size_t>(r)] = sum;
    }
  }
  return out;
}

// Whether an edge of the box with these corners (in the other box's frame) meets the other box.
bool edgesMeetBox(const std::array<P3, 8>& corner, const P3& other_half) {
  for (int i = 0; i < 8; ++i) {
    for (int k = 0; k < 3; ++k) {
      const int j = i | (1 << k);
      if (j == i) continue;  // each edge once: from the corner with bit k clear
      if (segmentMeetsBox(corner[static_cast<std::size_t>(i)], corner[static_cast<std::size_t>(j)],
                          other_half)) {
        return true;
      }
    }
  }
  return false;
}

// Brute-force intersection of A (widened by `delta` on every side) and B.
bool bruteIntersect(const BoxPair& p, double delta = 0.0) {
  const P3 half_a{p.half_a[0] + delta, p.half_a[1] + delta, p.half_a[2] + delta};
  const P3 half_b{p.half_b[0], p.half_b[1], p.half_b[2]};
  const P3 t{p.translation[0], p.translation[1], p.translation[2]};
  const P3 zero{0.0, 0.0, 0.0};
  // B's corners in A's frame: R w + t, w = +-half_b (t added after the product: shift by R^T t
  // would round differently, so compute R w first and add t).
  std::array<P3, 8> b_in_a = mappedCorners(p.rotation, false, half_b, zero);
  for (P3& c : b_in_a) {
    for (std::size_t k = 0; k < 3; ++k)
      c[k] += t[k];
  }
  if (edgesMeetBox(b_in_a, half_a)) return true;
  // A's corners in B's frame: R^T (u - t), u = +-half_a.
  const P3 minus_t{-t[0], -t[1], -t[2]};
  const std::array<P3, 8> a_in_b = mappedCorners(p.rotation, true, half_a, minus_t);
  if (edgesMeetBox(a_in_b, half_b)) return true;
  // No edge meets the other box: disjoint, or one inside the other (then it holds the centre).
  P3 a_center_in_b{};
  for (std::size_t r = 0; r < 3; ++r) {
    for (std::size_t k = 0; k < 3; ++k) {
      a_center_in_b[r] -=
          p.rotation(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(r)) * t[k];
    }
  }
  return segmentMeetsBox(a_center_in_b, a_center_in_b, half_b) || segmentMeetsBox(t, t, half_a);
}

std::array<Vector3d, 8> corners(const Matrix3d& axes, const Vector3d& center,
                                const Vector3d& half) {
  std::array<Vector3d, 8> c;
  for (int i = 0; i < 8; ++i) {
    const Vector3d s((i & 1) ? 1.0 : -1.0, (i & 2) ? 1.0 : -1.0, (i & 4) ? 1.0 : -1.0);
    c[static_cast<std::size_t>(i)] = center + axes * s.cwiseProduct(half);
  }
  return c;
}

// Exact referee: whether some w with |w_k| <= half_b[k] has |translation + rotation w|_i <=
// half_a[i], in rational arithmetic (Fourier-Motzkin elimination of w0, w1, w2; the system is
// feasible iff every constraint left, 0 <= d, holds). Slow (thousands of rational constraints),
// so it only settles disagreements.
bool exactIntersect(const BoxPair& p) {
  using Rational = CGAL::Exact_rational;
  struct Constraint {
    std::array<Rational, 3> c;  // c . w <= d
    Rational d;
  };
  std::vector<Constraint> constraints;
  for (int k = 0; k < 3; ++k) {
    Constraint up{{Rational(0), Rational(0), Rational(0)}, Rational(p.half_b[k])};
    up.c[static_cast<std::size_t>(k)] = Rational(1);
    Constraint down = up;
    down.c[static_cast<std::size_t>(k)] = Rational(-1);
    constraints.push_back(up);
    constraints.push_back(down);
  }
  for (int i = 0; i < 3; ++i) {
    const Rational row[3] = {Rational(p.rotation(i, 0)), Rational(p.rotation(i, 1)),
                             Rational(p.rotation(i, 2))};
    const Rational a(p.half_a[i]);
    const Rational t(p.translation[i]);
    constraints.push_back(Constraint{{row[0], row[1], row[2]}, a - t});
    constraints.push_back(Constraint{{-row[0], -row[1], -row[2]}, a + t});
  }
  for (std::size_t var = 0; var < 3; ++var) {
    std::vector<Constraint> next;
    std::vector<const Constraint*> positive;
    std::vector<const Constraint*> negative;
    for (const Constraint& k : constraints) {
      if (CGAL::is_zero(k.c[var])) {
        next.push_back(k);
      } else {
        (CGAL::is_positive(k.c[var]) ? positive : negative).push_back(&k);
      }
    }
    for (const Constraint* pos : positive) {
      for (const Constraint* neg : negative) {
        const Rational wp = -neg->c[var];  // > 0
        const Rational wn = pos->c[var];   // > 0
        Constraint sum;
        for (std::size_t k = 0; k < 3; ++k)
          sum.c[k] = wp * pos->c[k] + wn * neg->c[k];
        sum.c[var] = Rational(0);
        sum.d = wp * pos->d + wn * neg->d;
        next.push_back(sum);
      }
    }
    constraints = std::move(next);
  }
  for (const Constraint& k : constraints) {
    if (CGAL::is_negative(k.d)) return false;
  }
  return true;
}

Matrix3d randomRotation(std::mt19937_64& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  return Eigen::Quaterniond(n(rng), n(rng), n(rng), n(rng)).normalized().toRotationMatrix();
}

Vector3d randomHalf(std::mt19937_64& rng, double scale) {
  // Include flat and needle-like boxes (one or two tiny extents) now and then.
  std::uniform_real_distribution<double> u(0.05, 1.0);
  Vector3d h(u(rng), u(rng), u(rng));
  std::uniform_int_distribution<int> pick(0, 9);
  if (pick(rng) == 0) h[pick(rng) % 3] = 0.0;
  if (pick(rng) == 0) h[pick(rng) % 3] *= 1e-6;
  return scale * h;
}

Vector3d randomDirection(std::mt19937_64& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  return Vector3d(n(rng), n(rng), n(rng)).normalized();
}

// Relative gap below which the SAT may still report an overlap: its margin is 1e-12 relative,
// the brute force's own rounding is far smaller; 1e-9 leaves a wide safety factor.
double gapFor(const BoxPair& p) {
  return 1e-9 * (p.half_a.sum() + p.half_b.sum() + p.translation.cwiseAbs().maxCoeff());
}

// How one pair was judged.
enum class Verdict { kOverlap, kSeparated, kBoundary, kRefereed };

// Compares the SAT with the brute force (and the exact referee where they disagree on an
// intersection); adds a failure naming the pair when the SAT is wrong.
Verdict checkPair(const BoxPair& p, const std::string& label) {
  const bool overlap = sat(p);
  if (bruteIntersect(p)) {
    if (overlap) return Verdict::kOverlap;
    // Within the brute force's rounding of touching: let exact arithmetic decide.
    EXPECT_FALSE(exactIntersect(p))
        << "SAT separates intersecting boxes (exact LP feasible); " << label << ": " << describe(p);
    return Verdict::kRefereed;
  }
  if (!bruteIntersect(p, gapFor(p))) {
    EXPECT_FALSE(overlap) << "SAT reports overlap for clearly separated boxes; " << label << ": "
                          << describe(p);
    return Verdict::kSeparated;
  }
  return Verdict::kBoundary;
}

TEST(SeparatingAxis, ExactRefereeOnKnownCases) {
  BoxPair p;
  p.half_a = Vector3d(1, 0.5, 0.25);
  p.half_b = Vector3d(0.75, 2, 0.125);
  p.translation = Vector3d(1.75, 2.5, 0.375);  // corner to corner, exactly
  EXPECT_TRUE(exactIntersect(p));
  p.translation.z() = 0.375 + 0x1p-40;
  EXPECT_FALSE(exactIntersect(p));
  p.translation = Vector3d(0.1, 0.2, 0.3);
  EXPECT_TRUE(exactIntersect(p));
  p.rotation = Eigen::AngleAxisd(0.4, Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  EXPECT_TRUE(exactIntersect(p));
  p.translation = Vector3d(0, 5, 0);
  EXPECT_FALSE(exactIntersect(p));
}

TEST(SeparatingAxis, AgreesWithBruteForceOnRandomPairs) {
  std::mt19937_64 rng(20240611);
  int overlapping = 0;
  int separated = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const double scale = std::pow(10.0, trial % 7 - 3);  // 1e-3 .. 1e3
    BoxPair p;
    p.half_a = randomHalf(rng, scale);
    p.half_b = randomHalf(rng, scale);
    p.rotation = randomRotation(rng);
    // Centre distances from deep overlap to clearly apart.
    std::uniform_real_distribution<double> reach(0.0, 1.3);
    p.translation = randomDirection(rng) * reach(rng) * (p.half_a.norm() + p.half_b.norm());
    if (trial % 5 == 0) p.translation += Vector3d(1e6, -2e5, 3e4) * scale;  // far off: separated
    switch (checkPair(p, "trial " + std::to_string(trial))) {
      case Verdict::kOverlap:
        ++overlapping;
        break;
      case Verdict::kSeparated:
        ++separated;
        break;
      case Verdict::kBoundary:
      case Verdict::kRefereed:
        break;
    }
    if (HasFailure()) return;
  }
  // Both outcomes were exercised in quantity (the test is not vacuous).
  EXPECT_GT(overlapping, 5000);
  EXPECT_GT(separated, 5000);
}

// Along random directions, find by bisection (on the brute force) the centre offset at which B
// just touches A; just inside must overlap, 1e-6 of their size further out must be separated. This
// puts every pair at the boundary, where the edge-edge axes matter most.
TEST(SeparatingAxis, AgreesWithBruteForceAtTheContactDistance) {
  std::mt19937_64 rng(99);
  int refereed = 0;
  int separated = 0;
  for (int trial = 0; trial < 1500; ++trial) {
    BoxPair p;
    p.half_a = randomHalf(rng, 1.0);
    p.half_b = randomHalf(rng, 1.0);
    p.rotation = randomRotation(rng);
    const Vector3d direction = randomDirection(rng);
    double inside = 0.0;
    double outside = 2.0 * (p.half_a.norm() + p.half_b.norm());
    for (int step = 0; step < 60; ++step) {
      const double middle = 0.5 * (inside + outside);
      p.translation = middle * direction;
      (bruteIntersect(p) ? inside : outside) = middle;
    }
    p.translation = inside * direction;
    ASSERT_TRUE(bruteIntersect(p));
    const Verdict touching = checkPair(p, "touching, trial " + std::to_string(trial));
    refereed += touching == Verdict::kRefereed ? 1 : 0;
    // A step of 1e-6 of the boxes' size outwards. The gap it opens is the step times the cosine
    // between the direction and the contact normal, which can be small for needle-like boxes: a
    // pair still within the brute force's 1e-9 band is not judged (kBoundary).
    p.translation = (inside + 1e-6 * (p.half_a.norm() + p.half_b.norm())) * direction;
    const Verdict apart = checkPair(p, "1e-6 apart, trial " + std::to_string(trial));
    ASSERT_NE(apart, Verdict::kOverlap) << "trial " << trial << ": " << describe(p);
    separated += apart == Verdict::kSeparated ? 1 : 0;
    if (HasFailure()) return;
  }
  // The referee settles the rare pairs whose contact is below the brute force's rounding (e.g.
  // two flat boxes crossing); the SAT itself must have decided almost all of them, and almost
  // every pair moved apart must have been judged (and found separated).
  EXPECT_LT(refereed, 30);
  EXPECT_GT(separated, 1400);
}

// Signed permutation matrices: every rotation by multiples of 90 degrees about the axes.
std::vector<Matrix3d> quarterTurnRotations() {
  std::vector<Matrix3d> out;
  const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (const auto& perm : perms) {
    for (int signs = 0; signs < 8; ++signs) {
      Matrix3d r = Matrix3d::Zero();
      for (int j = 0; j < 3; ++j)
        r(perm[j], j) = (signs >> j & 1) ? -1.0 : 1.0;
      if (r.determinant() > 0.0) out.push_back(r);
    }
  }
  return out;
}

// B's exact extent along A's axes for an axis-aligned B (dyadic numbers: every sum is exact).
Vector3d alignedExtent(const Matrix3d& r, const Vector3d& half_b) {
  return r.cwiseAbs() * half_b;
}

TEST(SeparatingAxis, QuarterAndHalfTurnsTouchingExactly) {
  const std::vector<Matrix3d> rotations = quarterTurnRotations();
  ASSERT_EQ(rotations.size(), 24u);
  const Vector3d half_a(1.0, 0.5, 0.25);
  const Vector3d half_b(0.75, 2.0, 0.125);
  for (const Matrix3d& r : rotations) {
    const Vector3d reach = half_a + alignedExtent(r, half_b);  // exact sums of dyadics
    // Offsets: face-face on each axis (others centred or sheared), edge-edge, corner-corner.
    const Vector3d offsets[] = {{reach.x(), 0.0, 0.0},
                                {0.0, -reach.y(), 0.0},
                                {0.0, 0.0, reach.z()},
                                {reach.x(), 0.5 * reach.y(), -0.25 * reach.z()},
                                {reach.x(), reach.y(), 0.0},
                                {0.0, -reach.y(), reach.z()},
                                {-reach.x(), 0.0, -reach.z()},
                                {reach.x(), reach.y(), reach.z()},
                                {-reach.x(), reach.y(), -reach.z()}};
    for (const Vector3d& offset : offsets) {
      BoxPair p;
      p.rotation = r;
      p.half_a = half_a;
      p.half_b = half_b;
      p.translation = offset;
      EXPECT_TRUE(sat(p)) << "touching exactly: " << describe(p);
      EXPECT_TRUE(bruteIntersect(p)) << describe(p);
      // Pushed apart along the touching direction by a small gap: separated.
      p.translation = offset + 1e-7 * offset.cwiseSign();
      EXPECT_FALSE(sat(p)) << "1e-7 apart: " << describe(p);
      // Pushed into each other: overlapping.
      p.translation = offset - 1e-7 * offset.cwiseSign();
      EXPECT_TRUE(sat(p)) << "1e-7 into each other: " << describe(p);
    }
  }
}

TEST(SeparatingAxis, IdenticalAndNestedBoxesOverlap) {
  BoxPair p;
  p.half_a = Vector3d(1, 2, 3);
  p.half_b = Vector3d(1, 2, 3);
  EXPECT_TRUE(sat(p));
  p.half_b = Vector3d(0.01, 0.02, 0.03);  // deep inside A, any orientation
  std::mt19937_64 rng(3);
  for (int i = 0; i < 50; ++i) {
    p.rotation = randomRotation(rng);
    EXPECT_TRUE(sat(p)) << describe(p);
    std::swap(p.half_a, p.half_b);  // A deep inside B
    EXPECT_TRUE(sat(p)) << describe(p);
    std::swap(p.half_a, p.half_b);
  }
  // Degenerate boxes: a point at A's corner, a flat square crossing A's face.
  p.rotation = Matrix3d::Identity();
  p.half_b = Vector3d::Zero();
  p.translation = Vector3d(1, 2, 3);
  EXPECT_TRUE(sat(p));
  p.translation = Vector3d(1, 2, 3.0000001);
  EXPECT_FALSE(sat(p));
}

// Edge-edge contact that only a cross-product axis can decide: A's vertical edge at (ax, ay) and
// an edge of B along (1, -1, 0) touching it, B on the far side of the plane x + y = ax + ay and
// tilted so that none of its faces lies in that plane.
TEST(SeparatingAxis, EdgeEdgeContactNeedsTheCrossAxis) {
  const Vector3d half_a(1.0, 0.5, 2.0);
  const Vector3d half_b(0.8, 0.3, 0.6);
  const Vector3d edge = Vector3d(1, -1, 0).normalized();
  const Vector3d normal = Vector3d(1, 1, 0).normalized();  // out of A at its (+x, +y) edge
  const Vector3d up = Vector3d::UnitZ();
  for (double tilt : {0.3, 0.7, 1.1}) {
    // B's axis 0 along the edge; axes 1, 2 turned by `tilt` in the (normal, up) plane.
    Matrix3d r;
    r.col(0) = edge;
    r.col(1) = std::cos(tilt) * normal + std::sin(tilt) * up;
    r.col(2) = r.col(0).cross(r.col(1));
    // Along the normal, axis 1 rises (cos tilt > 0) and axis 2 falls (-sin tilt < 0), so B's
    // edge along axis 0 at its corner (-1, +1) in axes 1, 2 is the only part of B in the plane.
    const Vector3d contact(half_a.x(), half_a.y(), 0.1);
    const Vector3d to_center = half_b.y() * r.col(1) - half_b.z() * r.col(2);
    BoxPair p;
    p.rotation = r;
    p.half_a = half_a;
    p.half_b = half_b;
    p.translation = contact + to_center;
    // The edges cross at `contact` (exactly up to the rounding of cos, sin and the sums).
    EXPECT_TRUE(sat(p)) << "tilt " << tilt << ": " << describe(p);
    EXPECT_TRUE(bruteIntersect(p, gapFor(p)));
    BoxPair apart = p;
    apart.translation += 1e-6 * normal;
    EXPECT_FALSE(bruteIntersect(apart, gapFor(apart)));
    EXPECT_FALSE(sat(apart)) << "tilt " << tilt << ", 1e-6 apart: " << describe(apart);
    // The face axes alone do not separate `apart`: the cross axis did the work.
    bool face_separates = false;
    for (int i = 0; i < 3; ++i) {
      face_separates |=
          std::abs(apart.translation[i]) > half_a[i] + r.cwiseAbs().row(i).dot(half_b);
      face_separates |=
          std::abs(apart.translation.dot(r.col(i))) > r.cwiseAbs().col(i).dot(half_a) + half_b[i];
    }
    EXPECT_FALSE(face_separates) << "tilt " << tilt;
  }
}

// A corner of a tilted B resting on A's top face.
TEST(SeparatingAxis, VertexOnFaceTouching) {
  std::mt19937_64 rng(5);
  for (int trial = 0; trial < 200; ++trial) {
    BoxPair p;
    p.half_a = randomHalf(rng, 1.0).cwiseMax(0.1);
    p.half_b = randomHalf(rng, 1.0).cwiseMax(0.1);
    p.rotation = randomRotation(rng);
    // B's lowest corner along z, placed on A's top face at a point inside it.
    const std::array<Vector3d, 8> c = corners(p.rotation, Vector3d::Zero(), p.half_b);
    Vector3d lowest = c[0];
    for (const Vector3d& v : c) {
      if (v.z() < lowest.z()) lowest = v;
    }
    std::uniform_real_distribution<double> u(-0.9, 0.9);
    const Vector3d on_face(u(rng) * p.half_a.x(), u(rng) * p.half_a.y(), p.half_a.z());
    p.translation = on_face - lowest;
    EXPECT_TRUE(sat(p)) << "trial " << trial << ": " << describe(p);
    p.translation.z() += 1e-6;
    EXPECT_FALSE(sat(p)) << "trial " << trial << ", 1e-6 above: " << describe(p);
  }
}

TEST(SeparatingAxis, ClearlySeparatedPairsAreSeparated) {
  std::mt19937_64 rng(11);
  for (int trial = 0; trial < 500; ++trial) {
    BoxPair p;
    p.half_a = randomHalf(rng, 1.0);
    p.half_b = randomHalf(rng, 1.0);
    p.rotation = randomRotation(rng);
    // Bounding spheres apart by 1 %.
    p.translation = randomDirection(rng) * 1.01 * (p.half_a.norm() + p.half_b.norm());
    EXPECT_FALSE(sat(p)) << "trial " << trial << ": " << describe(p);
    EXPECT_FALSE(bruteIntersect(p));
  }
}

// The same pairs far from the origin and at extreme scales: the relative margin keeps the
// answer (B's centre in A's frame is what matters, so scale everything together).
TEST(SeparatingAxis, ScaleInvariant) {
  std::mt19937_64 rng(13);
  for (int trial = 0; trial < 300; ++trial) {
    BoxPair p;
    p.half_a = randomHalf(rng, 1.0);
    p.half_b = randomHalf(rng, 1.0);
    p.rotation = randomRotation(rng);
    std::uniform_real_distribution<double> reach(0.0, 1.3);
    p.translation = randomDirection(rng) * reach(rng) * (p.half_a.norm() + p.half_b.norm());
    const Verdict verdict = checkPair(p, "trial " + std::to_string(trial));
    if (verdict != Verdict::kOverlap && verdict != Verdict::kSeparated) continue;  // boundary
    const bool brute = verdict == Verdict::kOverlap;
    for (double scale : {0x1p-30, 0x1p-10, 0x1p10, 0x1p30}) {  // exact scalings
      BoxPair s = p;
      s.half_a *= scale;
      s.half_b *= scale;
      s.translation *= scale;
      EXPECT_EQ(sat(s), brute) << "scale " << scale << ": " << describe(s);
    }
  }
}

}  // namespace
}  // namespace collido::obbtree
