#pragma once

#include <cstdint>

#include <collido/motion.h>
#include <collido/obbtree/tree.h>

namespace collido::obbtree {

/// A tree moving over a step.
struct MovingTree {
  const ObbTree& tree;
  const StepMotion& motion;
  double radius;  ///< at least the largest distance of a vertex from the model origin
};

/// The largest distance of the tree's vertices from its model origin (MovingTree::radius).
double radiusAboutOrigin(const ObbTree& tree);

/// When two moving trees first touch over the step, t in [0, 1].
struct FirstContactAnswer {
  bool touches = false;
  /// No shared point on [0, t_lo), proven. Without a touch, t_lo = 1 says apart over the whole
  /// step; below 1, the trees came within rounding of each other there without a shared point
  /// found (a grazing pass), and nothing is claimed past it.
  double t_lo = 1.0;
  double t_hi = 1.0;             ///< touches: a shared point at t_hi, t_hi - t_lo <= the width
  std::int32_t triangle_a = -1;  ///< touches: a pair sharing a point at t_hi (input indices)
  std::int32_t triangle_b = -1;
  std::uint64_t advances = 0;     ///< conservative advancement steps
  std::uint64_t trial_tests = 0;  ///< collision tests at a bracket's trial end
  std::uint64_t box_tests = 0;    ///< over both
  std::uint64_t triangle_tests = 0;
};

/// The first contact of two moving trees by conservative advancement, certified as the exact
/// reference's is (docs/ORACLE.md, "First contact over a step"). Each advance is a best-first
/// search over node pairs with a motion bound per pair, as C2A does: a pair separated by a
/// certified gap g along its own direction d (the boxes' or, at the leaves, the triangles'
/// approximate closest points) cannot touch before g over its closing rate along d, the
/// origins' relative velocity along d plus each tree's turning rate times the pair's largest
/// distance from that tree's origin; the least such time over the triangle pairs (to within
/// 10%, pairs at least that far off set aside) is the advance, less a rounding allowance of
/// 1e-12 of the largest coordinate reached. A pair within rounding of contact stops the search:
/// the exact distance search then decides contact, and gives the advance (its certified lower
/// bound over the trees' whole motion bounds) when they do not touch. Once an advance is shorter
/// than `width`, the exact collision test (first hit) is tried at t + width and at halvings of it
/// down to the advance; a hit closes the bracket. `width` must be > 0.
void firstContact(const MovingTree& a, const MovingTree& b, double width,
                  FirstContactAnswer& answer);

}  // namespace collido::obbtree
