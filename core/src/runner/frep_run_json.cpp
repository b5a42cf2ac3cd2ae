// An FRep run as JSON: the document collido frep --json writes, the dashboard reads and a study
// stores per combination.
#include <stdexcept>

#include <collido/runner/frep_run.h>
#include <collido/runner/statistics.h>

#include "run_json.h"

namespace collido {
namespace {

using Json = nlohmann::json;

FrepSeedAnswer seedAnswerFromJson(const Json& json) {
  FrepSeedAnswer answer;
  answer.time = detail::numberAt(json, "time");
  answer.pair = json.at("pair").get<std::string>();
  answer.expected = json.at("expected").get<std::string>();
  const std::string verdict = json.at("verdict").get<std::string>();
  const std::optional<frep::CollisionVerdict> parsed = frep::parseVerdict(verdict);
  if (!parsed) throw std::invalid_argument("unknown verdict '" + verdict + "'");
  frep::CollisionResult& result = answer.result;
  result.verdict = *parsed;
  result.cells = json.at("cells").get<std::size_t>();
  result.max_depth = json.at("max_depth").get<int>();
  result.undecided_cells = json.at("undecided_cells").get<std::size_t>();
  for (const Json& level : json.at("levels")) {
    result.levels.push_back({level.at("cells").get<std::size_t>(),
                             level.at("discarded").get<std::size_t>(),
                             level.at("split").get<std::size_t>()});
  }
  if (json.contains("witness")) {
    const Json& w = json.at("witness");
    result.witness = {w.at(0).get<double>(), w.at(1).get<double>(), w.at(2).get<double>()};
  }
  answer.median_ms = detail::numberAt(json, "median_ms");
  return answer;
}

FrepBackendRow backendRowFromJson(const Json& json) {
  FrepBackendRow row;
  row.backend = json.at("backend").get<std::string>();
  row.resolution = json.at("resolution").get<int>();
  row.failure = detail::rowFailure(json);
  row.triangles_first_pair = json.at("triangles_first_pair").get<std::size_t>();
  row.ms_per_query_with_meshing = detail::numberAt(json, "ms_per_query_with_meshing");
  for (const Json& frame : json.at("frames")) {
    const std::string outcome = frame.at("outcome").get<std::string>();
    const std::optional<MeshAnswerOutcome> parsed = parseMeshAnswerOutcome(outcome);
    if (!parsed) throw std::invalid_argument("unknown outcome '" + outcome + "'");
    row.answers.push_back({detail::numberAt(frame, "time"), frame.at("pair").get<std::string>(),
                           frame.at("intersecting").get<bool>(), *parsed,
                           detail::numberAt(frame, "query_us"),
                           detail::numberAt(frame, "ms_with_meshing")});
  }
  return row;
}

}  // namespace

Json frepRunJson(const FrepRun& run) {
  Json json = {{"collidoscope_frep", 1}, {"file", run.file},
               {"name", run.name},       {"precision", run.precision},
               {"seed", Json::array()},  {"comparators", Json::array()}};
  for (const FrepSeedAnswer& answer : run.seed) {
    const frep::CollisionResult& result = answer.result;
    Json levels = Json::array();
    for (const frep::CollisionLevel& level : result.levels)
      levels.push_back(
          {{"cells", level.cells}, {"discarded", level.discarded}, {"split", level.split}});
    Json entry = {{"time", answer.time},
                  {"pair", answer.pair},
                  {"verdict", frep::verdictName(result.verdict)},
                  {"expected", answer.expected},
                  {"cells", result.cells},
                  {"max_depth", result.max_depth},
                  {"undecided_cells", result.undecided_cells},
                  {"median_ms", answer.median_ms},
                  {"levels", levels}};
    if (result.verdict == frep::CollisionVerdict::kColliding)
      entry["witness"] = {result.witness.x(), result.witness.y(), result.witness.z()};
    json["seed"].push_back(entry);
  }
  for (const FrepBackendRow& row : run.comparators) {
    Json frames = Json::array();
    std::vector<double> query_us;
    for (const FrepMeshAnswer& a : row.answers) {
      query_us.push_back(a.query_us);
      frames.push_back({{"time", a.time},
                        {"pair", a.pair},
                        {"intersecting", a.intersecting},
                        {"outcome", meshAnswerOutcomeName(a.outcome)},
                        {"query_us", a.query_us},
                        {"ms_with_meshing", a.ms_with_meshing}});
    }
    const std::size_t missed = row.count(MeshAnswerOutcome::kMissedOverlap);
    const std::size_t false_contacts = row.count(MeshAnswerOutcome::kFalseContact);
    json["comparators"].push_back(
        {{"backend", row.backend},
         {"resolution", row.resolution},
         {"triangles_first_pair", row.triangles_first_pair},
         {"agrees", row.count(MeshAnswerOutcome::kAgrees)},
         {"missed", missed},
         {"false_contacts", false_contacts},
         {"within_precision", row.count(MeshAnswerOutcome::kWithinPrecision)},
         {"wrong", missed + false_contacts},
         {"ms_per_query_with_meshing", row.ms_per_query_with_meshing},
         {"median_query_us", query_us.empty() ? 0.0 : quantile(query_us, 0.5)},
         {"status", detail::rowStatus(row.failure)},
         {"frames", frames}});
  }
  if (!run.preview_png.empty()) json["preview_png"] = run.preview_png;
  return json;
}
Result<FrepRun> frepRunFromJson(const Json& json) {
  try {
    if (json.value("collidoscope_frep", 0) != 1)
      return Status(StatusCode::kInvalidArgument, "not an FRep run (collidoscope_frep != 1)");
    FrepRun run;
    run.file = json.at("file").get<std::string>();
    run.name = json.at("name").get<std::string>();
    run.precision = detail::numberAt(json, "precision");
    for (const Json& answer : json.at("seed")) {
      run.seed.push_back(seedAnswerFromJson(answer));
      if (!run.seed.back().asExpected()) ++run.unexpected;
    }
    for (const Json& row : json.at("comparators"))
      run.comparators.push_back(backendRowFromJson(row));
    if (json.contains("preview_png")) run.preview_png = json.at("preview_png").get<std::string>();
    return run;
  } catch (const Json::exception& e) {
    return Status(StatusCode::kInvalidArgument, std::string("FRep run: ") + e.what());
  } catch (const std::invalid_argument& e) {
    return Status(StatusCode::kInvalidArgument, std::string("FRep run: ") + e.what());
  }
}

}  // namespace collido
