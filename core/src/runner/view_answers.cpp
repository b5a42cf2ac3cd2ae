#include <collido/runner/view_answers.h>

#include <algorithm>
#include <memory>
#include <vector>

#include <nlohmann/json.hpp>

#include <collido/oracle/exact_oracle.h>

namespace collido {
namespace {

using Json = nlohmann::json;

// Triangle pairs flattened as [a0, b0, a1, b1, ...]: a fifth of the size of objects per pair.
Json flatPairs(const std::vector<TrianglePair>& pairs) {
  Json flat = Json::array();
  for (const TrianglePair& p : pairs) {
    flat.push_back(p.a);
    flat.push_back(p.b);
  }
  return flat;
}

Json point(const Eigen::Vector3d& p) {
  return Json::array({p.x(), p.y(), p.z()});
}

Json distanceJson(const DistanceResult& d) {
  if (!std::isfinite(d.distance)) return nullptr;
  return {{"value", d.distance},
          {"a", point(d.point_a)},
          {"b", point(d.point_b)},
          {"triangle_a", d.triangle_a},
          {"triangle_b", d.triangle_b}};
}

// The triangle pairs a backend names in its answer: all-pairs and witness pairs, and for
// contact queries the pairs its contacts name (engines that say which triangles touch).
std::vector<TrianglePair> namedPairs(const QueryResult& result, const QueryKindInfo& kind) {
  std::vector<TrianglePair> pairs = result.pairs;
  if (kind.has(AnswerPart::kContacts)) {
    for (const Contact& c : result.contacts) {
      if (c.triangle_a >= 0 && c.triangle_b >= 0) pairs.push_back({c.triangle_a, c.triangle_b});
    }
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

Json pairJson(const Scene& scene, std::size_t frame, const PairAnswers& answers,
              const QueryKindInfo& kind) {
  const std::vector<TrianglePair> reported =
      kind.has(AnswerPart::kPairSet) ? answers.reported.pairs : namedPairs(answers.reported, kind);
  Json out = {{"a", answers.a},
              {"b", answers.b},
              {"intersecting", answers.reported.intersecting},
              {"oracle_intersecting", answers.oracle_intersecting},
              {"reported", flatPairs(reported)},
              {"oracle", flatPairs(answers.oracle_pairs)}};
  if (kind.has(AnswerPart::kWitnessPairs) || kind.has(AnswerPart::kContacts)) {
    // The oracle keeps one witness where no all-pairs query asks the same pair, so whether a
    // backend's witness really intersects is decided here, pair by pair.
    const SceneObject& a = scene.objects[answers.a];
    const SceneObject& b = scene.objects[answers.b];
    const std::shared_ptr<const TriangleMesh> shape_a = a.shapeAt(frame);
    const std::shared_ptr<const TriangleMesh> shape_b = b.shapeAt(frame);
    Json exact = Json::array();
    for (const TrianglePair& p : reported) {
      const bool in_range = p.a >= 0 && static_cast<std::size_t>(p.a) < shape_a->triangleCount() &&
                            p.b >= 0 && static_cast<std::size_t>(p.b) < shape_b->triangleCount();
      exact.push_back(in_range &&
                      exactPairIntersects(*shape_a, a.poseAt(frame), *shape_b, b.poseAt(frame), p));
    }
    out["reported_exact"] = std::move(exact);
  }
  if (kind.has(AnswerPart::kDistance)) {
    out["distance"] = distanceJson(answers.reported.distance);
    out["oracle_distance"] =
        answers.oracle_distance ? distanceJson(*answers.oracle_distance) : Json(nullptr);
  }
  return out;
}

}  // namespace

std::string viewAnswersJson(const Scene& scene, const RunReport& report,
                            const std::string& backend_label) {
  Json queries = Json::array();
  for (const QueryMeasurement& m : report.measurements) {
    if (m.scene != scene.name) continue;
    Json frames = Json::array();
    for (const FrameRecord& f : m.frames) {
      Json pairs = Json::array();
      for (const PairAnswers& answers : f.answers)
        pairs.push_back(pairJson(scene, f.frame, answers, queryKindInfo(m.kind)));
      frames.push_back({{"frame", f.frame},
                        {"disagrees", f.disagrees(m.kind)},
                        {"object_pairs", f.object_pairs},
                        {"oracle_pairs", f.oracle_pairs},
                        {"reported_pairs", f.reported_pairs},
                        {"matched_pairs", f.matched_pairs},
                        {"pairs", std::move(pairs)}});
    }
    queries.push_back({{"name", m.query},
                       {"kind", queryKindName(m.kind)},
                       {"status", m.status.text()},
                       {"disagreements", m.disagreements},
                       {"frames", std::move(frames)}});
  }
  Json problems = Json::array();
  for (const std::string& problem : report.problems)
    problems.push_back(problem);
  return Json{{"backend", backend_label}, {"queries", std::move(queries)}, {"problems", problems}}
      .dump(-1, ' ', false, Json::error_handler_t::replace);
}

}  // namespace collido
