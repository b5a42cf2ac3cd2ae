#include "frame_observers.h"

#include <algorithm>
#include <cmath>

#include <collido/oracle/proximity.h>

namespace collido::detail {
namespace {

// Adds one object pair's answer to a frame's record (a group query's frame sums its pairs).
void addAnswer(const FrameRecord& one, FrameRecord& frame) {
  frame.oracle_intersecting = frame.oracle_intersecting || one.oracle_intersecting;
  frame.reported_intersecting = frame.reported_intersecting || one.reported_intersecting;
  frame.oracle_pairs += one.oracle_pairs;
  frame.reported_pairs += one.reported_pairs;
  frame.matched_pairs += one.matched_pairs;
  frame.invalid_pairs += one.invalid_pairs;
  frame.truncated = frame.truncated || one.truncated;
  // Distance queries name two objects, never a group: one answer per frame.
  frame.oracle_distance = one.oracle_distance;
  frame.reported_distance = one.reported_distance;
  frame.distance_below = one.distance_below;
  frame.distance_above = one.distance_above;
  frame.invalid_distance_witness = one.invalid_distance_witness;
  // So are queries over a step.
  frame.oracle_touches = one.oracle_touches;
  frame.oracle_t_lo = one.oracle_t_lo;
  frame.oracle_t_hi = one.oracle_t_hi;
  frame.reported_t_lo = one.reported_t_lo;
  frame.reported_t_hi = one.reported_t_hi;
  frame.first_contact_error = one.first_contact_error;
  frame.bracket_width = one.bracket_width;
  frame.invalid_first_contact = one.invalid_first_contact;
  if (one.contact) {
    if (!frame.contact) frame.contact.emplace();
    frame.contact->add(*one.contact);
  }
}

// Whether another version of the scene (the finest meshes, the true poses) intersects in
// `frame`: for a group query, whether any pair does (that scene's own broad phase picks the
// candidates).
bool otherIntersecting(OracleCache& other, const SceneQuery& query,
                       const std::optional<BroadPhase>& other_broad_phase, std::size_t frame) {
  if (!other_broad_phase) return other.get(query.a, query.b, frame).intersecting;
  for (const auto& [ia, ib] : other_broad_phase->pairsAt(frame)) {
    if (other.get(ia, ib, frame).intersecting) return true;
  }
  return false;
}

std::optional<BroadPhase> groupBroadPhase(const Scene& scene, const SceneQuery& query) {
  std::optional<BroadPhase> broad_phase;
  if (query.isGroup()) broad_phase.emplace(scene, query);
  return broad_phase;
}

}  // namespace

ObjectPairs objectPairsAt(const std::optional<BroadPhase>& broad_phase, const SceneQuery& query,
                          std::size_t frame) {
  if (!broad_phase) return {{query.a, query.b}};
  // A two-object query keeps its own order of the pair (the broad phase sorts it).
  if (!query.isGroup()) {
    if (broad_phase->pairsAt(frame).empty()) return {};
    return {{query.a, query.b}};
  }
  return broad_phase->pairsAt(frame);
}

void FrameObserver::pair(const AskedPair& /*asked*/, FrameRecord& /*record*/) {}
void FrameObserver::frame(const SteppedFrame& /*stepped*/, FrameRecord& /*record*/) {}

void OracleComparison::pair(const AskedPair& asked, FrameRecord& record) {
  FrameRecord one;
  compareWithOracle(asked.shape_a, asked.pose_a, asked.shape_b, asked.pose_b, asked.request,
                    asked.reported, asked.truth, one);
  addAnswer(one, record);
}

void AnswerKeeper::pair(const AskedPair& asked, FrameRecord& record) {
  PairAnswers kept{asked.a,           asked.b,     asked.reported, asked.truth.intersecting,
                   asked.truth.pairs, std::nullopt};
  if (asked.truth.distance) {
    DistanceResult exact;
    exact.distance = asked.truth.distance->distance;
    exact.point_a = asked.truth.distance->point_a;
    exact.point_b = asked.truth.distance->point_b;
    exact.triangle_a = asked.truth.distance->pair.a;
    exact.triangle_b = asked.truth.distance->pair.b;
    kept.oracle_distance = exact;
  }
  record.answers.push_back(std::move(kept));
}

void FloorTimer::pair(const AskedPair& asked, FrameRecord& /*record*/) {
  appendWorldPairs(asked.shape_a, asked.pose_a, asked.shape_b, asked.pose_b, asked.truth.pairs,
                   true_pairs_);
}

void FloorTimer::frame(const SteppedFrame& /*stepped*/, FrameRecord& record) {
  record.floor_us = floorMicroseconds(true_pairs_, repetitions_);
  true_pairs_.clear();
}

FinestComparison::FinestComparison(OracleCache& finest, const SceneQuery& query)
    : finest_(finest), query_(query), broad_phase_(groupBroadPhase(finest.scene(), query)) {}

void FinestComparison::frame(const SteppedFrame& stepped, FrameRecord& record) {
  record.finest_intersecting = otherIntersecting(finest_, query_, broad_phase_, stepped.frame);
}

TrackingComparison::TrackingComparison(const Scene& scene, OracleCache& truth,
                                       const SceneQuery& query, double sigmas)
    : scene_(scene),
      truth_(truth),
      query_(query),
      sigmas_(sigmas),
      broad_phase_(groupBroadPhase(truth.scene(), query)) {}

// The possible-contact answer: whether some candidate object pair comes within `sigmas` times
// the sum of its objects' predicted spreads (tracked objects and those mounted on them). Left
// unset when a spread is unknown (no redundant marker, or a lost frame).
void TrackingComparison::frame(const SteppedFrame& stepped, FrameRecord& record) {
  record.truth_intersecting = otherIntersecting(truth_, query_, broad_phase_, stepped.frame);
  bool possible = false;
  double widest = 0.0;
  for (const auto& [ia, ib] : stepped.candidates) {
    double margin = 0.0;
    for (std::size_t i : {ia, ib}) {
      const double sigma = scene_.trackingSpreadAt(i, *stepped.shapes.at(i), stepped.frame);
      if (std::isnan(sigma)) return;
      margin += sigmas_ * sigma;
    }
    widest = std::max(widest, margin);
    if (!possible) {
      possible = meshesWithinDistance(
                     *stepped.shapes.at(ia), scene_.objects[ia].poseAt(stepped.frame),
                     *stepped.shapes.at(ib), scene_.objects[ib].poseAt(stepped.frame), margin)
                     .within;
    }
  }
  record.possible_contact = possible;
  record.tracking_margin = widest;
}

}  // namespace collido::detail
