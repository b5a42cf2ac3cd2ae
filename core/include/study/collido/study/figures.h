#pragma once

#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <collido/study/result_store.h>

namespace collido::study {

/// Where a figure is shown.
enum FigureUse : unsigned {
  kInSummary = 1u,    ///< a counter of summary.json (Google Benchmark's format)
  kInDashboard = 2u,  ///< a key of the dashboard's rows (collido report)
};

/// One figure of a (combination, measurement) as the outputs show it, listed once for all of
/// them: its name, where it is shown, and its value — null where the backend, the scene or the
/// query gives none (summary.json then leaves it out; the dashboard shows a gap).
struct Figure {
  std::string name;
  unsigned uses;
  std::function<nlohmann::json(const CombinationResult& result, const QueryMeasurement& m)> value;
};

/// The fields that name a measurement's setting, scene and query: the start of every
/// records.jsonl line and of every dashboard row (JsonT: nlohmann::json or ordered_json).
template <typename JsonT>
JsonT measurementIdentity(const Combination& c, const QueryMeasurement& m) {
  return {{"backend", c.backend},       {"scene", c.scene_name},           {"category", c.category},
          {"resolution", c.resolution}, {"needs", needsModeName(c.needs)}, {"limit", c.limit},
          {"query", m.query},           {"kind", queryKindName(m.kind)}};
}

/// Every figure, in output order. A new figure is one entry here (and its computation in the
/// runner's summary, summariseMeasurement), and it reaches summary.json and the dashboard.
const std::vector<Figure>& measurementFigures();

}  // namespace collido::study
