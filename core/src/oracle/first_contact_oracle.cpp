#include <collido/oracle/first_contact_oracle.h>

#include <algorithm>
#include <cmath>

#include <collido/assert.h>
#include <collido/oracle/distance_oracle.h>
#include <collido/oracle/exact_oracle.h>

namespace collido {
namespace {

// The largest distance of a vertex from the mesh's origin: every point of the mesh lies within.
double radiusAboutOrigin(const TriangleMesh& mesh) {
  return mesh.vertices.cols() == 0 ? 0.0 : mesh.vertices.colwise().norm().maxCoeff();
}

// The largest world coordinate any point of the mesh reaches over the step, for the rounding
// allowance: the exact distance is of the poses as evaluated in double, within 256 units in the
// last place of the largest coordinate, and each evaluated pose is within a few of the path.
double reach(const StepMotion& motion, double radius) {
  return std::max(motion.start().translation().norm(), motion.end().translation().norm()) + radius;
}

// Trial ends tried within one advance: down to 2^-24 of the width.
constexpr int kMaxHalvings = 24;

struct Trial {
  bool touching = false;
  TrianglePair witness;
};

Trial touchingAt(const TriangleMesh& a, const StepMotion& motion_a, const TriangleMesh& b,
                 const StepMotion& motion_b, double t) {
  const OracleAnswer answer =
      exactIntersectingPairs(a, motion_a.at(t), b, motion_b.at(t), OracleMode::kFirstPair);
  Trial trial;
  trial.touching = answer.intersecting;
  if (answer.intersecting && !answer.pairs.empty()) trial.witness = answer.pairs.front();
  return trial;
}

}  // namespace

ExactFirstContact exactFirstContact(const TriangleMesh& a, const StepMotion& motion_a,
                                    const TriangleMesh& b, const StepMotion& motion_b, double width,
                                    std::size_t max_evaluations) {
  COLLIDO_ASSERT(width > 0.0 && std::isfinite(width), "a bracket width must be finite and > 0");
  const double radius_a = radiusAboutOrigin(a);
  const double radius_b = radiusAboutOrigin(b);
  const double speed = motion_a.speedBound(radius_a) + motion_b.speedBound(radius_b);
  const double allowance = 1e-12 * std::max(reach(motion_a, radius_a), reach(motion_b, radius_b));
  ExactFirstContact answer;
  double t = 0.0;
  for (;;) {
    if (answer.distance_evaluations == max_evaluations) {
      answer.outcome = ExactFirstContact::Outcome::kUndecided;
      return answer;
    }
    const MeshDistance d = exactMeshDistance(a, motion_a.at(t), b, motion_b.at(t));
    ++answer.distance_evaluations;
    answer.t_lo = t;
    if (d.distance == 0.0) {
      answer.outcome = ExactFirstContact::Outcome::kTouch;
      answer.t_hi = t;
      answer.witness = d.pair;
      return answer;
    }
    // Nothing moves relative to anything: apart now is apart over the whole step.
    if (speed == 0.0) break;
    const double free_distance = d.distance * (1.0 - 1e-12) - allowance;
    if (free_distance <= 0.0) {
      answer.outcome = ExactFirstContact::Outcome::kUndecided;
      return answer;
    }
    const double advance = free_distance / speed;
    if (t + advance > 1.0) break;
    if (advance < width) {
      // Close: look for a shared point within the width, nearest the far end first (a head-on
      // approach is still touching there), then halving towards the advance (a thin part that
      // has already passed through at the far end).
      int halvings = 0;
      for (double reach_out = width; reach_out > advance && halvings <= kMaxHalvings;
           reach_out /= 2.0, ++halvings) {
        double t_hi = std::min(t + reach_out, 1.0);
        // The bracket's width is a promise: t + width may round above it.
        while (t_hi - t > width)
          t_hi = std::nextafter(t_hi, t);
        const Trial trial = touchingAt(a, motion_a, b, motion_b, t_hi);
        ++answer.intersection_tests;
        if (trial.touching) {
          answer.outcome = ExactFirstContact::Outcome::kTouch;
          answer.t_hi = t_hi;
          answer.witness = trial.witness;
          return answer;
        }
      }
    }
    t += advance;
  }
  answer.outcome = ExactFirstContact::Outcome::kApart;
  answer.t_lo = answer.t_hi = 1.0;
  return answer;
}

}  // namespace collido
