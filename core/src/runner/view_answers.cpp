#include <collido/runner/view_answers.h>

#include <nlohmann/json.hpp>

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

Json pairJson(const PairAnswers& answers, QueryKind kind) {
  Json out = {{"a", answers.a},
              {"b", answers.b},
              {"intersecting", answers.reported.intersecting},
              {"oracle_intersecting", answers.oracle_intersecting},
              {"reported", flatPairs(answers.reported.pairs)},
              {"oracle", flatPairs(answers.oracle_pairs)}};
  if (kind == QueryKind::kDistance) {
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
        pairs.push_back(pairJson(answers, m.kind));
      frames.push_back({{"frame", f.frame},
                        {"object_pairs", f.object_pairs},
                        {"oracle_pairs", f.oracle_pairs},
                        {"reported_pairs", f.reported_pairs},
                        {"matched_pairs", f.matched_pairs},
                        {"pairs", std::move(pairs)}});
    }
    queries.push_back({{"name", m.query},
                       {"kind", queryKindName(m.kind)},
                       {"status", m.status},
                       {"disagreements", m.disagreements},
                       {"frames", std::move(frames)}});
  }
  Json problems = Json::array();
  for (const std::string& problem : report.problems)
    problems.push_back(problem);
  return Json{{"backend", backend_label}, {"queries", std::move(queries)}, {"problems", problems}}
      .dump();
}

}  // namespace collido
