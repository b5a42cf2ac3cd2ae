// The runner's public part: comparing an answer with the oracle's, summarising a measurement,
// the timing protocols' names, and running scenes on backends (one backend on one scene is
// backend_run.cpp; the frames' figures are its observers, frame_observers.cpp).
#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <tuple>

#include <collido/motion.h>
#include <collido/oracle/distance_oracle.h>
#include <collido/oracle/exact_oracle.h>
#include <collido/oracle/proximity.h>
#include <collido/oracle/triangle_distance.h>
#include <collido/runner/runner.h>
#include <collido/runner/statistics.h>
#include <collido/scene/broad_phase.h>

#include "backend_run.h"
#include "frame_observers.h"

namespace collido {

void summariseMeasurement(QueryMeasurement& m) {
  m.median_us = quantile(m.times_us, 0.5);
  m.p90_us = quantile(m.times_us, 0.9);
  m.p99_us = quantile(m.times_us, 0.99);
  m.max_us = m.times_us.empty() ? 0.0 : *std::max_element(m.times_us.begin(), m.times_us.end());
  m.false_negatives = 0;
  m.false_positives = 0;
  m.disagreements = 0;
  m.finest_disagreements.reset();
  m.tracking_false_contacts.reset();
  m.tracking_missed_contacts.reset();
  m.tracking_possible_contacts.reset();
  m.tracking_missed_within_margin.reset();
  std::size_t oracle_pairs = 0;
  std::size_t reported_pairs = 0;
  std::size_t matched_pairs = 0;
  double timed_with_floor_us = 0.0;
  double floor_us = 0.0;
  std::vector<double> updates_us;
  m.update_rebuilds.reset();
  m.max_distance_error.reset();
  m.max_relative_distance_error.reset();
  m.contact.reset();
  m.reused_pairs = 0;
  m.unasked_frames = 0;
  m.skipped_pairs = 0;
  for (const FrameRecord& f : m.frames) {
    m.reused_pairs += f.reused_pairs;
    m.skipped_pairs += f.skipped_pairs;
    // Nothing asked, yet answered: every pair reused or culled by the broad phase.
    if (f.reused_pairs == f.object_pairs && f.reused_pairs + f.skipped_pairs > 0)
      ++m.unasked_frames;
    if (f.contact) {
      if (!m.contact) m.contact.emplace();
      m.contact->add(*f.contact);
    }
    if (f.oracle_distance && f.reported_distance) {
      const double error = std::abs(*f.reported_distance - *f.oracle_distance);
      m.max_distance_error = std::max(m.max_distance_error.value_or(0.0), error);
      if (*f.oracle_distance > 0.0) {
        m.max_relative_distance_error =
            std::max(m.max_relative_distance_error.value_or(0.0), error / *f.oracle_distance);
      }
    }
    if (f.update_us) updates_us.push_back(*f.update_us);
    if (f.update_work.counted)
      m.update_rebuilds = m.update_rebuilds.value_or(0) + f.update_work.rebuilds;
    // A frame with reused pairs timed only the others, so it is held to no floor.
    if (f.floor_us && f.reused_pairs == 0) {
      timed_with_floor_us += f.median_us;
      floor_us += *f.floor_us;
    }
    if (f.oracle_intersecting && !f.reported_intersecting) ++m.false_negatives;
    if (!f.oracle_intersecting && f.reported_intersecting) ++m.false_positives;
    if (f.disagrees(m.kind)) ++m.disagreements;
    if (f.truth_intersecting) {
      m.tracking_false_contacts = m.tracking_false_contacts.value_or(0) +
                                  (f.oracle_intersecting && !*f.truth_intersecting ? 1 : 0);
      m.tracking_missed_contacts = m.tracking_missed_contacts.value_or(0) +
                                   (!f.oracle_intersecting && *f.truth_intersecting ? 1 : 0);
    }
    if (f.possible_contact) {
      m.tracking_possible_contacts =
          m.tracking_possible_contacts.value_or(0) + (*f.possible_contact ? 1 : 0);
      m.tracking_missed_within_margin =
          m.tracking_missed_within_margin.value_or(0) +
          (f.truth_intersecting.value_or(false) && !*f.possible_contact ? 1 : 0);
    }
    if (f.finest_intersecting) {
      m.finest_disagreements = m.finest_disagreements.value_or(0) +
                               (*f.finest_intersecting != f.reported_intersecting ? 1 : 0);
    }
    oracle_pairs += f.oracle_pairs;
    reported_pairs += f.reported_pairs;
    matched_pairs += f.matched_pairs;
  }
  if (queryKindInfo(m.kind).has(AnswerPart::kPairSet)) {
    m.recall = oracle_pairs == 0 ? 1.0 : static_cast<double>(matched_pairs) / oracle_pairs;
    m.precision = reported_pairs == 0 ? 1.0 : static_cast<double>(matched_pairs) / reported_pairs;
  }
  m.max_first_contact_error.reset();
  for (const FrameRecord& f : m.frames) {
    if (f.first_contact_error) {
      m.max_first_contact_error =
          std::max(m.max_first_contact_error.value_or(0.0), *f.first_contact_error);
    }
  }
  m.floor_ratio.reset();
  if (floor_us > 0.0) m.floor_ratio = timed_with_floor_us / floor_us;
  m.update_median_us.reset();
  if (!updates_us.empty()) m.update_median_us = quantile(updates_us, 0.5);
}

namespace {

// The distance answer against the exact one: within rounding below, within tolerance and
// rounding above; points the reported distance apart and on their triangles; a certified
// interval that holds the exact distance.
void compareDistance(const TriangleMesh& a, const Pose& pose_a, const TriangleMesh& b,
                     const Pose& pose_b, const QueryRequest& request, const DistanceResult& d,
                     const MeshDistance& truth, FrameRecord& record) {
  const double magnitude = std::max((pose_a * a.vertices).cwiseAbs().maxCoeff(),
                                    (pose_b * b.vertices).cwiseAbs().maxCoeff());
  const double rounding = 1e-10 * magnitude;
  record.oracle_distance = truth.distance;
  record.reported_distance = d.distance;
  record.distance_below = rounding;
  record.distance_above =
      rounding + std::max(request.abs_tolerance, request.rel_tolerance * truth.distance);
  record.oracle_intersecting = truth.distance == 0.0;
  // Contact is a distance of exactly 0 (or a negative, penetration-signed one): a tiny positive
  // distance says the meshes are apart, however close to rounding it is.
  record.reported_intersecting = d.distance <= 0.0;
  bool invalid = std::abs((d.point_b - d.point_a).norm() - d.distance) > rounding;
  // Decided exactly (the point as a zero-area triangle against the posed one): a double
  // closest point on a sliver can be off by far more than the rounding allowed here.
  const auto off_triangle = [&](const TriangleMesh& mesh, const Pose& pose, std::int32_t t,
                                const Eigen::Vector3d& p) {
    if (t < 0) return false;
    if (static_cast<std::size_t>(t) >= mesh.triangleCount()) return true;
    std::array<Eigen::Vector3d, 3> corners;
    for (int k = 0; k < 3; ++k)
      corners[static_cast<std::size_t>(k)] = mesh.corner(static_cast<std::size_t>(t), k);
    const double squared =
        exactPosedClosestPoints({p, p, p}, Pose::Identity(), corners, pose).squared_distance.lower;
    return std::sqrt(squared) > rounding;
  };
  invalid = invalid || off_triangle(a, pose_a, d.triangle_a, d.point_a) ||
            off_triangle(b, pose_b, d.triangle_b, d.point_b);
  if (d.lower && d.upper) {
    invalid =
        invalid || *d.lower > truth.distance + rounding || *d.upper < truth.distance - rounding;
  }
  record.invalid_distance_witness = invalid;
}

// The reported first contact against the oracle's certified bracket: the verdicts, the brackets
// (each proves its free part and its contact, so a right bracket meets the oracle's), and the
// witness at the reported t_hi.
void compareFirstContact(const TriangleMesh& a, const Pose& pose_a, const TriangleMesh& b,
                         const Pose& pose_b, const QueryRequest& request,
                         const FirstContactResult& reported, const ExactFirstContact& truth,
                         FrameRecord& record) {
  // A claim contradicted by less than the width asked for is an error of the time (measured
  // below), not a wrong answer: a backend whose time is within its accuracy of the contact.
  const double slack = request.step->bracket_width + 1e-12;
  using Outcome = ExactFirstContact::Outcome;
  record.reported_intersecting = reported.touches;
  record.bracket_width = request.step->bracket_width;
  record.oracle_t_lo = truth.t_lo;
  if (truth.outcome != Outcome::kUndecided) {
    record.oracle_touches = truth.outcome == Outcome::kTouch;
    record.oracle_intersecting = *record.oracle_touches;
  } else {
    record.oracle_intersecting = reported.touches;
  }
  if (truth.outcome == Outcome::kTouch) record.oracle_t_hi = truth.t_hi;
  // Every answer claims its free part: a free part past the oracle's proven contact is wrong.
  const bool free_too_long = truth.outcome == Outcome::kTouch && reported.t_lo > truth.t_hi + slack;
  record.invalid_first_contact = free_too_long;
  if (!reported.touches) return;
  record.reported_t_lo = reported.t_lo;
  record.reported_t_hi = reported.t_hi;
  bool invalid = free_too_long || reported.t_hi < truth.t_lo - slack;
  if (truth.outcome == Outcome::kTouch) {
    record.first_contact_error =
        std::max({reported.t_hi - truth.t_lo, truth.t_hi - reported.t_lo, 0.0});
  }
  if (reported.triangle_a >= 0 && reported.triangle_b >= 0) {
    const TrianglePair pair{reported.triangle_a, reported.triangle_b};
    if (static_cast<std::size_t>(pair.a) >= a.triangleCount() ||
        static_cast<std::size_t>(pair.b) >= b.triangleCount()) {
      invalid = true;
    } else {
      const auto at_t_hi = [&](const Pose& start, const Pose& end) {
        return StepMotion::between(start, end, "").value().at(reported.t_hi);
      };
      invalid = invalid || !exactPairIntersects(a, at_t_hi(pose_a, request.step->pose_a), b,
                                                at_t_hi(pose_b, request.step->pose_b), pair);
    }
  }
  record.invalid_first_contact = invalid;
}

}  // namespace

void compareWithOracle(const TriangleMesh& a, const Pose& pose_a, const TriangleMesh& b,
                       const Pose& pose_b, const QueryRequest& request, const QueryResult& result,
                       const OracleAnswer& truth, FrameRecord& record) {
  const QueryKindInfo& kind = queryKindInfo(request.kind);
  record.oracle_intersecting = truth.intersecting;
  record.reported_intersecting = result.intersecting;
  record.truncated = result.truncated;
  const auto in_range = [&](const TrianglePair& p) {
    return p.a >= 0 && static_cast<std::size_t>(p.a) < a.triangleCount() && p.b >= 0 &&
           static_cast<std::size_t>(p.b) < b.triangleCount();
  };
  std::vector<TrianglePair> reported;
  for (const TrianglePair& p : result.pairs) {
    if (in_range(p)) {
      reported.push_back(p);
    } else {
      ++record.invalid_pairs;
    }
  }
  if (kind.has(AnswerPart::kFirstContact)) {
    if (truth.first_contact) {
      compareFirstContact(a, pose_a, b, pose_b, request, result.first_contact, *truth.first_contact,
                          record);
    }
    return;
  }
  if (kind.has(AnswerPart::kDistance)) {
    if (truth.distance) {
      compareDistance(a, pose_a, b, pose_b, request, result.distance, *truth.distance, record);
    }
    return;
  }
  std::sort(reported.begin(), reported.end());
  const std::size_t before_dedupe = reported.size();
  reported.erase(std::unique(reported.begin(), reported.end()), reported.end());
  record.invalid_pairs += before_dedupe - reported.size();

  if (kind.has(AnswerPart::kContacts)) {
    record.oracle_pairs = truth.pairs.size();
    record.contact = scoreContacts(a, pose_a, b, pose_b, truth.pairs, result.contacts);
  }
  if (kind.has(AnswerPart::kWitnessPairs)) {
    // A witness, when given, must really intersect.
    for (const TrianglePair& p : reported) {
      if (!exactPairIntersects(a, pose_a, b, pose_b, p)) {
        ++record.invalid_pairs;
      }
    }
  }
  if (!kind.has(AnswerPart::kPairSet)) return;
  record.oracle_pairs = truth.pairs.size();
  record.reported_pairs = reported.size();
  std::vector<TrianglePair> matched;
  std::set_intersection(reported.begin(), reported.end(), truth.pairs.begin(), truth.pairs.end(),
                        std::back_inserter(matched));
  record.matched_pairs = matched.size();
}

bool FrameRecord::coarserThanAsked() const {
  // Two brackets of the asked width around the same time are at most two widths apart.
  return first_contact_error && bracket_width &&
         *first_contact_error > 2.0 * *bracket_width + 1e-12;
}

bool FrameRecord::disagrees(QueryKind query_kind) const {
  const QueryKindInfo& kind = queryKindInfo(query_kind);
  if (kind.has(AnswerPart::kDistance)) {
    if (!oracle_distance || !reported_distance) return true;
    if (invalid_distance_witness || *reported_distance < *oracle_distance - distance_below ||
        *reported_distance > *oracle_distance + distance_above)
      return true;
  }
  if (kind.has(AnswerPart::kIntersecting) &&
      (oracle_intersecting != reported_intersecting || invalid_pairs != 0))
    return true;
  if (kind.has(AnswerPart::kFirstContact) &&
      (invalid_first_contact || oracle_intersecting != reported_intersecting || coarserThanAsked()))
    return true;
  if (kind.has(AnswerPart::kContacts) && contact && contact->anyWrong()) return true;
  if (!kind.has(AnswerPart::kPairSet)) return false;
  // A truncated answer is right when every pair it gives is real and some were left out.
  if (truncated) return matched_pairs != reported_pairs || reported_pairs >= oracle_pairs;
  return matched_pairs != oracle_pairs || matched_pairs != reported_pairs;
}

const char* timingProtocolName(TimingProtocol protocol) {
  return protocol == TimingProtocol::kCycled ? "cycled" : "repeated";
}

std::optional<TimingProtocol> parseTimingProtocol(const std::string& name) {
  if (name == "repeated") return TimingProtocol::kRepeated;
  if (name == "cycled") return TimingProtocol::kCycled;
  return std::nullopt;
}

void precomputeOracleAnswers(OracleCache& oracle, bool distances) {
  const Scene& scene = oracle.scene();
  for (const SceneQuery& query : scene.queries) {
    std::optional<BroadPhase> broad_phase;
    if (query.isGroup()) broad_phase.emplace(scene, query);
    for (std::size_t frame = 0; frame < scene.frames; ++frame) {
      if (!query.asked.contains(frame)) continue;
      const std::vector<std::pair<std::size_t, std::size_t>> candidates =
          detail::objectPairsAt(broad_phase, query, frame);
      for (const auto& [ia, ib] : candidates)
        (void)oracle.answerFor(query, ia, ib, frame, distances);
    }
  }
}

RunReport runScenes(const std::vector<Scene>& scenes, const std::vector<BackendSpec>& backends,
                    const RunOptions& options) {
  RunReport report;
  for (const Scene& scene : scenes) {
    OracleCache oracle(scene);
    runSceneOnBackends(scene, backends, options, oracle, report);
  }
  return report;
}

void runSceneOnBackends(const Scene& scene, const std::vector<BackendSpec>& backends,
                        const RunOptions& options, OracleCache& oracle, RunReport& report) {
  for (const BackendSpec& spec : backends) {
    detail::runSceneOnBackend(scene, spec, oracle, nullptr, options, report);
  }
}

RunReport runScene(const Scene& scene, const BackendSpec& backend, const RunOptions& options,
                   OracleCache& oracle, OracleCache* finest_oracle) {
  RunReport report;
  detail::runSceneOnBackend(scene, backend, oracle, finest_oracle, options, report);
  return report;
}

RunReport runScene(const Scene& scene, const BackendSpec& backend, const RunOptions& options,
                   const Scene* finest) {
  RunReport report;
  OracleCache oracle(scene);
  std::optional<OracleCache> finest_oracle;
  if (finest != nullptr) finest_oracle.emplace(*finest, /*witness_only=*/true);
  detail::runSceneOnBackend(scene, backend, oracle, finest_oracle ? &*finest_oracle : nullptr,
                            options, report);
  return report;
}

}  // namespace collido
