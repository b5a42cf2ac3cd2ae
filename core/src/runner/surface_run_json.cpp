// A surface run as JSON: the document collido surface-distance --json writes, the dashboard
// reads and a study stores per combination.
#include <filesystem>
#include <stdexcept>

#include <collido/runner/surface_run.h>

#include "run_json.h"

namespace collido {
namespace {

using Json = nlohmann::json;

nurbs::SurfaceDistance distanceFromJson(const Json& row) {
  nurbs::SurfaceDistance d;
  d.lower = detail::numberAt(row, "lower");
  d.upper = detail::numberAt(row, "upper");
  d.converged = row.at("converged").get<bool>();
  d.pairs_bounded = row.at("pairs_bounded").get<std::size_t>();
  d.pairs_opened = row.at("pairs_opened").get<std::size_t>();
  for (const Json& level : row.at("levels")) {
    d.levels.push_back({level.at("pairs_bounded").get<std::size_t>(),
                        level.at("pairs_opened").get<std::size_t>(),
                        detail::numberAt(level, "ms") * 1e-3});
  }
  return d;
}

SurfaceBackendRow backendRowFromJson(const Json& json) {
  SurfaceBackendRow row;
  row.backend = json.at("backend").get<std::string>();
  row.segments = json.at("segments").get<int>();
  row.failure = detail::rowFailure(json);
  if (!row.failure.empty()) {
    row.end = SurfaceRowEnd::kFailed;
    return row;
  }
  row.triangles = json.at("triangles").get<std::size_t>();
  row.distance = detail::numberAt(json, "distance");
  row.error = detail::numberAt(json, "error");
  row.median_us = detail::numberAt(json, "median_us");
  row.build_ms = detail::numberAt(json, "build_ms");
  // Absent where the backend does not count (and in runs written before the counts were).
  if (json.contains("bv_tests")) row.bv_tests = json.at("bv_tests").get<std::uint64_t>();
  if (json.contains("primitive_tests"))
    row.primitive_tests = json.at("primitive_tests").get<std::uint64_t>();
  return row;
}

}  // namespace

Json surfaceRunJson(const SurfaceRun& run) {
  Json json = {{"collidoscope_surface_distance", 1},
               {"file", run.file},
               {"name", std::filesystem::path(run.file).stem().string()},
               {"a", run.a},
               {"b", run.b},
               {"model_size", run.model_size},
               {"tolerance", run.tolerance},
               {"seed", Json::array()},
               {"backends", Json::array()}};
  for (const SeedDistanceRow& row : run.seed) {
    const nurbs::SurfaceDistance& d = row.distance;
    Json levels = Json::array();
    for (const nurbs::LevelWork& w : d.levels)
      levels.push_back({{"pairs_bounded", w.pairs_bounded},
                        {"pairs_opened", w.pairs_opened},
                        {"ms", w.seconds * 1e3}});
    json["seed"].push_back({{"bound", patchBoundName(row.bound)},
                            {"descent", row.descent},
                            {"lower", d.lower},
                            {"upper", d.upper},
                            {"converged", d.converged},
                            {"pairs_bounded", d.pairs_bounded},
                            {"pairs_opened", d.pairs_opened},
                            {"median_ms", row.median_ms},
                            {"levels", levels}});
  }
  if (run.backends_asked && run.reference)
    json["reference"] = {{"lower", run.reference->lower}, {"upper", run.reference->upper}};
  for (const SurfaceBackendRow& row : run.backends) {
    if (row.end != SurfaceRowEnd::kOk) {
      json["backends"].push_back(
          {{"backend", row.backend},
           {"segments", row.end == SurfaceRowEnd::kFailed ? row.segments : 0},
           {"status", row.failure}});
      continue;
    }
    Json backend = {{"backend", row.backend},     {"segments", row.segments},
                    {"triangles", row.triangles}, {"distance", row.distance},
                    {"error", row.error},         {"median_us", row.median_us},
                    {"build_ms", row.build_ms},   {"status", detail::rowStatus({})}};
    if (row.bv_tests) backend["bv_tests"] = *row.bv_tests;
    if (row.primitive_tests) backend["primitive_tests"] = *row.primitive_tests;
    json["backends"].push_back(std::move(backend));
  }
  return json;
}

Result<SurfaceRun> surfaceRunFromJson(const Json& json) {
  try {
    if (json.value("collidoscope_surface_distance", 0) != 1)
      return Status(StatusCode::kInvalidArgument,
                    "not a surface run (collidoscope_surface_distance != 1)");
    SurfaceRun run;
    run.file = json.at("file").get<std::string>();
    run.a = json.at("a").get<std::string>();
    run.b = json.at("b").get<std::string>();
    run.model_size = detail::numberAt(json, "model_size");
    run.tolerance = detail::numberAt(json, "tolerance");
    for (const Json& row : json.at("seed")) {
      const std::string bound = row.at("bound").get<std::string>();
      const std::optional<nurbs::PatchBound> parsed = parsePatchBound(bound);
      if (!parsed) throw std::invalid_argument("unknown bound '" + bound + "'");
      SeedDistanceRow seed;
      seed.bound = *parsed;
      seed.descent = row.at("descent").get<bool>();
      seed.distance = distanceFromJson(row);
      seed.median_ms = detail::numberAt(row, "median_ms");
      run.seed.push_back(std::move(seed));
    }
    if (json.contains("reference")) {
      nurbs::SurfaceDistance reference;
      reference.lower = json.at("reference").at("lower").get<double>();
      reference.upper = json.at("reference").at("upper").get<double>();
      reference.converged = true;
      run.reference = reference;
    }
    for (const Json& row : json.at("backends"))
      run.backends.push_back(backendRowFromJson(row));
    run.backends_asked = !run.backends.empty();
    return run;
  } catch (const Json::exception& e) {
    return Status(StatusCode::kInvalidArgument, std::string("surface run: ") + e.what());
  } catch (const std::invalid_argument& e) {
    return Status(StatusCode::kInvalidArgument, std::string("surface run: ") + e.what());
  }
}

}  // namespace collido
