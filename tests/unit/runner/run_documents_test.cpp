// Surface and FRep runs read back from their documents write the same documents: a study stores
// each combination's run and joins them from what it reads, so a field the reader drops would
// vanish from the dashboard.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include <collido/runner/frep_run.h>
#include <collido/runner/surface_run.h>

#include "support/test_paths.h"

namespace collido {
namespace {

// Whether two documents hold the same keys and values, numbers to a relative 1e-12 (a level's
// time is kept in seconds and written in milliseconds).
bool sameDocument(const nlohmann::json& a, const nlohmann::json& b) {
  if (a.is_number() && b.is_number()) {
    const double x = a.get<double>();
    const double y = b.get<double>();
    return std::abs(x - y) <= 1e-12 * std::max(std::abs(x), std::abs(y));
  }
  if (a.type() != b.type() || a.size() != b.size()) return false;
  if (a.is_object()) {
    for (auto it = a.begin(); it != a.end(); ++it) {
      if (!b.contains(it.key()) || !sameDocument(it.value(), b.at(it.key()))) return false;
    }
    return true;
  }
  if (a.is_array()) {
    for (std::size_t i = 0; i < a.size(); ++i) {
      if (!sameDocument(a[i], b[i])) return false;
    }
    return true;
  }
  return a == b;
}

TEST(RunDocuments, ASurfaceRunReadBackWritesTheSameDocument) {
  SurfaceRunRequest request;
  request.file = test::sourcePath("scenes/surfaces/saddle_cap.json");
  request.repetitions = 1;
  request.bounds = {nurbs::PatchBound::kConvexHull};
  const Result<SurfaceRun> run = runSurfaces(request);
  ASSERT_TRUE(run.ok()) << run.status().toString();
  SurfaceRun with_rows = run.value();
  with_rows.backends_asked = true;
  SurfaceBackendRow failed;
  failed.backend = "bullet";
  failed.segments = 8;
  failed.end = SurfaceRowEnd::kFailed;
  failed.failure = "build: engine failure";
  SurfaceBackendRow answered;
  answered.backend = "obbtree";
  answered.segments = 32;
  answered.triangles = 4096;
  answered.distance = 0.8;
  answered.error = 1e-3;
  answered.median_us = 12.5;
  answered.build_ms = 0.25;
  with_rows.backends = {failed, answered};

  const nlohmann::json written = surfaceRunJson(with_rows);
  const Result<SurfaceRun> read = surfaceRunFromJson(written);
  ASSERT_TRUE(read.ok()) << read.status().toString();
  EXPECT_TRUE(sameDocument(surfaceRunJson(read.value()), written)) << written.dump(1);
  EXPECT_FALSE(written.at("seed").at(0).at("levels").empty());
  // JSON writes a non-finite figure as null: such a stored run still reads, the figure NaN.
  nlohmann::json with_null = written;
  with_null["backends"][1]["median_us"] = nullptr;
  const Result<SurfaceRun> tolerant = surfaceRunFromJson(with_null);
  ASSERT_TRUE(tolerant.ok()) << tolerant.status().toString();
  EXPECT_TRUE(std::isnan(tolerant.value().backends[1].median_us));
  EXPECT_FALSE(surfaceRunFromJson(nlohmann::json::object()).ok());
  nlohmann::json unknown = written;
  unknown["seed"][0]["bound"] = "sphere";
  const Result<SurfaceRun> refused = surfaceRunFromJson(unknown);
  ASSERT_FALSE(refused.ok());
  EXPECT_NE(refused.status().message().find("unknown bound 'sphere'"), std::string::npos);
}

TEST(RunDocuments, AnFrepRunReadBackWritesTheSameDocument) {
  const std::string path = test::sourcePath("scenes/frep/seed_quadric.json");
  const Result<FrepFile> file = loadFrepFile(path);
  ASSERT_TRUE(file.ok()) << file.status().toString();
  FrepRunRequest request;
  request.repetitions = 1;
  const Result<FrepRun> run = runFrep(file.value(), path, request);
  ASSERT_TRUE(run.ok()) << run.status().toString();
  FrepRun with_rows = run.value();
  with_rows.preview_png = "data:image/png;base64,AAAA";
  FrepBackendRow row;
  row.backend = "obbtree";
  row.resolution = 16;
  row.triangles_first_pair = 900;
  row.ms_per_query_with_meshing = 2.5;
  row.answers.push_back({0.0, "a / b", true, MeshAnswerOutcome::kMissedOverlap, 3.0, 2.0});
  FrepBackendRow failed = row;
  failed.failure = "plate: empty polygonization";
  failed.answers.clear();
  with_rows.comparators = {row, failed};

  const nlohmann::json written = frepRunJson(with_rows);
  const Result<FrepRun> read = frepRunFromJson(written);
  ASSERT_TRUE(read.ok()) << read.status().toString();
  EXPECT_TRUE(sameDocument(frepRunJson(read.value()), written)) << written.dump(1);
  EXPECT_TRUE(written.at("seed").at(0).contains("witness"));  // the colliding pair's
  nlohmann::json unknown = written;
  unknown["seed"][0]["verdict"] = "maybe";
  const Result<FrepRun> refused = frepRunFromJson(unknown);
  ASSERT_FALSE(refused.ok());
  EXPECT_NE(refused.status().message().find("unknown verdict 'maybe'"), std::string::npos);
}

}  // namespace
}  // namespace collido
