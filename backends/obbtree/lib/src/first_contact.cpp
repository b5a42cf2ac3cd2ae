#include <collido/obbtree/first_contact.h>

#include <algorithm>
#include <cmath>

#include <collido/assert.h>
#include <collido/obbtree/collide.h>
#include <collido/obbtree/distance.h>

#include "step_advance.h"

namespace collido::obbtree {
namespace {

// The distance search needs to be no closer than this share of the distance: a lower bound
// within 10% moves the step forward by 90% of what the exact distance would, for a search that
// stops far sooner.
constexpr double kDistanceShare = 0.1;
// Trial ends tried within one advance: down to 2^-24 of the width, as the reference does.
constexpr int kMaxHalvings = 24;
// A bound on the advances of one step, as the reference's.
constexpr std::uint64_t kMaxAdvances = 4096;

double reach(const MovingTree& m) {
  return std::max(m.motion.start().translation().norm(), m.motion.end().translation().norm()) +
         m.radius;
}

}  // namespace

double radiusAboutOrigin(const ObbTree& tree) {
  return tree.vertices().cols() == 0 ? 0.0 : tree.vertices().colwise().norm().maxCoeff();
}

void firstContact(const MovingTree& a, const MovingTree& b, double width,
                  FirstContactAnswer& answer) {
  COLLIDO_ASSERT(width > 0.0 && std::isfinite(width), "a bracket width must be finite and > 0");
  answer = FirstContactAnswer{};
  const double speed = a.motion.speedBound(a.radius) + b.motion.speedBound(b.radius);
  const double allowance = 1e-12 * std::max(reach(a), reach(b));
  DistanceAnswer distance_answer;
  CollideResult hits;
  CollideRequest first_hit;
  first_hit.mode = CollideMode::kFirstHit;
  const auto touching = [&](double t) {
    collide(a.tree, a.motion.at(t), b.tree, b.motion.at(t), first_hit, hits);
    ++answer.trial_tests;
    answer.box_tests += hits.box_tests;
    answer.triangle_tests += hits.triangle_tests;
    return !hits.pairs.empty();
  };
  const auto touch = [&](double t_lo, double t_hi, std::int32_t ta, std::int32_t tb) {
    answer.touches = true;
    answer.t_lo = t_lo;
    answer.t_hi = t_hi;
    answer.triangle_a = ta;
    answer.triangle_b = tb;
  };
  detail::StepRates rates;
  rates.closing_velocity = (a.motion.end().translation() - a.motion.start().translation()) -
                           (b.motion.end().translation() - b.motion.start().translation());
  rates.turn_a = a.motion.angle();
  rates.turn_b = b.motion.angle();
  rates.allowance = allowance;
  double t = 0.0;
  for (;;) {
    if (answer.advances == kMaxAdvances) return;  // undecided past t_lo
    const Eigen::Isometry3d pose_a = a.motion.at(t);
    const Eigen::Isometry3d pose_b = b.motion.at(t);
    detail::AdvanceCounters counters;
    double advance =
        detail::certifiedAdvance(a.tree, pose_a, b.tree, pose_b, rates, 1.0 - t, counters);
    ++answer.advances;
    answer.box_tests += counters.box_tests;
    answer.triangle_tests += counters.triangle_tests;
    answer.t_lo = t;
    if (advance >= 1.0 - t) break;
    if (advance == 0.0) {
      // A pair within rounding of contact: decided by the exact distance search, which also
      // gives a certified advance (with the whole trees' motion bound) when they do not touch.
      distance(a.tree, pose_a, b.tree, pose_b,
               DistanceRequest{0.0, kDistanceShare, /*bound_only=*/true}, distance_answer);
      answer.box_tests += distance_answer.box_tests;
      answer.triangle_tests += distance_answer.triangle_tests;
      if (distance_answer.distance == 0.0) {
        touch(t, t, distance_answer.triangle_a, distance_answer.triangle_b);
        return;
      }
      if (speed == 0.0) break;
      const double free_distance = distance_answer.lower_bound * (1.0 - 1e-12) - allowance;
      if (free_distance <= 0.0) return;  // a grazing pass: nothing claimed past t
      advance = free_distance / speed;
      if (t + advance > 1.0) break;
    }
    if (advance < width) {
      int halvings = 0;
      for (double reach_out = width; reach_out > advance && halvings <= kMaxHalvings;
           reach_out /= 2.0, ++halvings) {
        double t_hi = std::min(t + reach_out, 1.0);
        while (t_hi - t > width)
          t_hi = std::nextafter(t_hi, t);
        if (touching(t_hi)) {
          touch(t, t_hi, hits.pairs.front().a, hits.pairs.front().b);
          return;
        }
      }
    }
    t += advance;
  }
  answer.t_lo = answer.t_hi = 1.0;
}

}  // namespace collido::obbtree
