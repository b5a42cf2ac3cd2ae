#include <collido/runner/frep_run.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <tuple>

#include <collido/frep_mesh/polygonize.h>
#include <collido/frep_preview/preview.h>
#include <collido/host/backend_instance.h>
#include <collido/runner/statistics.h>
#include <collido/runner/text_table.h>
#include <collido/runner/timed_calls.h>

namespace collido {
namespace {

using Clock = std::chrono::steady_clock;
using Json = nlohmann::json;

double millisecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

std::string pairName(const FrepFile& file, std::size_t pair) {
  return file.solids[file.pairs[pair].first].name + " / " +
         file.solids[file.pairs[pair].second].name;
}

// How a mesh backend's boolean answer compares with the guaranteed one.
MeshAnswerOutcome outcomeOf(frep::CollisionVerdict truth, bool intersecting) {
  switch (truth) {
    case frep::CollisionVerdict::kColliding:
      return intersecting ? MeshAnswerOutcome::kAgrees : MeshAnswerOutcome::kMissedOverlap;
    case frep::CollisionVerdict::kSeparated:
      return intersecting ? MeshAnswerOutcome::kFalseContact : MeshAnswerOutcome::kAgrees;
    case frep::CollisionVerdict::kTouching:
      return MeshAnswerOutcome::kWithinPrecision;
    case frep::CollisionVerdict::kUndecided:
      break;
  }
  return MeshAnswerOutcome::kNoReference;
}

// A polygonized solid: its mesh (or why there is none) and what it cost.
struct Polygonized {
  std::optional<TriangleMesh> mesh;
  std::string error;
  double ms = 0.0;
};

// Meshes per resolution, frame and solid, made when first asked: static solids once.
class MeshCache {
 public:
  explicit MeshCache(const FrepFile& file) : file_(file) {}

  const Polygonized& at(int resolution, std::size_t frame, std::size_t solid) {
    const std::size_t key_frame = file_.solids[solid].animated ? frame : 0;
    const auto key = std::make_tuple(resolution, key_frame, solid);
    const auto found = meshes_.find(key);
    if (found != meshes_.end()) return found->second;
    Polygonized& out = meshes_[key];
    const frep::SolidPtr shape = file_.solids[solid].at(file_.times[key_frame]);
    const Clock::time_point start = Clock::now();
    Result<TriangleMesh> mesh = frep::polygonize(*shape, shape->bounds(), resolution);
    out.ms = millisecondsSince(start);
    if (mesh.ok())
      out.mesh = std::move(mesh).value();
    else
      out.error = file_.solids[solid].name + ": " + mesh.status().message();
    return out;
  }

 private:
  const FrepFile& file_;
  std::map<std::tuple<int, std::size_t, std::size_t>, Polygonized> meshes_;
};

// One backend at one resolution over every frame and pair; stops at the first failure.
FrepBackendRow backendRow(BackendInstance& backend, const std::string& label, int resolution,
                          const FrepFile& file, MeshCache& meshes,
                          const std::vector<std::vector<frep::CollisionVerdict>>& truth,
                          int repetitions) {
  FrepBackendRow row;
  row.backend = label;
  row.resolution = resolution;
  double charged_ms = 0.0;  // polygonization and build, each mesh once
  for (std::size_t f = 0; f < file.times.size() && row.failure.empty(); ++f) {
    for (std::size_t p = 0; p < file.pairs.size() && row.failure.empty(); ++p) {
      const std::size_t ids[2] = {file.pairs[p].first, file.pairs[p].second};
      ModelHandle models[2] = {0, 0};
      double frame_ms = 0.0;
      for (int k = 0; k < 2; ++k) {
        const Polygonized& shape = meshes.at(resolution, f, ids[k]);
        if (!shape.mesh) {
          row.failure = shape.error;
          break;
        }
        const bool fresh = f == 0 || file.solids[ids[k]].animated;
        if (fresh) frame_ms += shape.ms;
        const Clock::time_point start = Clock::now();
        Result<ModelHandle> built =
            backend.build(shape.mesh->view(), BuildNeeds{QueryKindSet(QueryKind::kBoolean)});
        if (fresh) frame_ms += millisecondsSince(start);
        if (!built.ok()) {
          row.failure = built.status().message();
          break;
        }
        models[k] = built.value();
        if (f == 0 && p == 0) row.triangles_first_pair += shape.mesh->triangleCount();
      }
      if (row.failure.empty()) {
        QueryRequest request;
        request.kind = QueryKind::kBoolean;
        QueryResult answer;
        const Result<std::vector<double>> timed = timeRepeated(repetitions, [&] {
          return backend.query(models[0], Pose::Identity(), models[1], Pose::Identity(), request,
                               answer);
        });
        if (timed.ok()) {
          const double us = quantile(timed.value(), 0.5);
          charged_ms += frame_ms + us * 1e-3;
          row.answers.push_back({file.times[f], pairName(file, p), answer.intersecting,
                                 outcomeOf(truth[f][p], answer.intersecting), us,
                                 frame_ms + us * 1e-3});
        } else {
          row.failure = timed.status().message();
        }
      }
      for (const ModelHandle model : models)
        if (model != 0) (void)backend.release(model);
    }
  }
  row.ms_per_query_with_meshing =
      charged_ms / static_cast<double>(file.times.size() * file.pairs.size());
  return row;
}

}  // namespace

bool FrepSeedAnswer::asExpected() const {
  return expected.empty() || expected == frep::verdictName(result.verdict);
}

const char* meshAnswerOutcomeName(MeshAnswerOutcome outcome) {
  switch (outcome) {
    case MeshAnswerOutcome::kAgrees:
      return "agrees";
    case MeshAnswerOutcome::kMissedOverlap:
      return "missed overlap";
    case MeshAnswerOutcome::kFalseContact:
      return "false contact";
    case MeshAnswerOutcome::kWithinPrecision:
      return "within precision";
    case MeshAnswerOutcome::kNoReference:
      break;
  }
  return "no reference";
}

std::optional<MeshAnswerOutcome> parseMeshAnswerOutcome(const std::string& name) {
  for (const MeshAnswerOutcome outcome :
       {MeshAnswerOutcome::kAgrees, MeshAnswerOutcome::kMissedOverlap,
        MeshAnswerOutcome::kFalseContact, MeshAnswerOutcome::kWithinPrecision,
        MeshAnswerOutcome::kNoReference}) {
    if (name == meshAnswerOutcomeName(outcome)) return outcome;
  }
  return std::nullopt;
}

std::size_t FrepBackendRow::count(MeshAnswerOutcome outcome) const {
  return static_cast<std::size_t>(
      std::count_if(answers.begin(), answers.end(),
                    [outcome](const FrepMeshAnswer& a) { return a.outcome == outcome; }));
}

Result<FrepRun> runFrep(const FrepFile& file, const std::string& path,
                        const FrepRunRequest& request) {
  FrepRun run;
  run.file = path;
  run.name = file.name;
  frep::CollisionOptions options;
  options.precision = request.precision > 0 ? request.precision : file.precision;
  run.precision = options.precision;

  // The seed method per frame and pair: the guaranteed answers every backend is judged by.
  std::vector<std::vector<frep::CollisionVerdict>> truth(file.times.size());
  for (std::size_t f = 0; f < file.times.size(); ++f) {
    for (std::size_t p = 0; p < file.pairs.size(); ++p) {
      const frep::SolidPtr a = file.solids[file.pairs[p].first].at(file.times[f]);
      const frep::SolidPtr b = file.solids[file.pairs[p].second].at(file.times[f]);
      FrepSeedAnswer answer{file.times[f], pairName(file, p), file.expected[p], {}, 0.0};
      try {
        const Result<std::vector<double>> timed =
            timeRepeated(request.seed_rows ? request.repetitions : 0, [&] {
              answer.result = frep::collide(*a, *b, options);
              return Status();
            });
        answer.median_ms = quantile(timed.value(), 0.5) * 1e-3;
      } catch (const std::invalid_argument& error) {
        return Status(StatusCode::kInvalidArgument,
                      path + ": " + answer.pair + ": " + error.what());
      } catch (const std::exception& error) {
        // Boost.Interval refuses some degenerate operations (an empty interval) by throwing.
        return Status(
            StatusCode::kInternal,
            path + ": " + answer.pair + ": the interval evaluation failed: " + error.what());
      }
      truth[f].push_back(answer.result.verdict);
      if (!request.seed_rows) continue;
      if (!answer.asExpected()) ++run.unexpected;
      run.seed.push_back(std::move(answer));
    }
  }

  MeshCache meshes(file);
  for (const BackendSpec& spec : request.backends) {
    Result<std::unique_ptr<BackendInstance>> created =
        BackendInstance::create(spec.library, spec.variant, spec.pluginOptions());
    for (const int resolution : request.resolutions) {
      if (!created.ok()) {
        FrepBackendRow row;
        row.backend = spec.label();
        row.resolution = resolution;
        row.created = false;
        row.failure = created.status().message();
        run.comparators.push_back(std::move(row));
        continue;
      }
      run.comparators.push_back(backendRow(*created.value(), spec.label(), resolution, file, meshes,
                                           truth, request.repetitions));
    }
  }
  return run;
}

std::string frepRunText(const FrepRun& run) {
  std::string text;
  if (!run.seed.empty()) {
    std::vector<std::vector<std::string>> rows;
    for (const FrepSeedAnswer& answer : run.seed) {
      std::string shown = frep::verdictName(answer.result.verdict);
      if (!answer.asExpected()) shown += " (expected " + answer.expected + ")";
      rows.push_back({formatNumber("%.3g", answer.time), answer.pair, shown,
                      std::to_string(answer.result.cells), std::to_string(answer.result.max_depth),
                      std::to_string(answer.result.undecided_cells),
                      formatNumber("%.3f", answer.median_ms)});
    }
    text +=
        run.name + " (" + run.file + "): guaranteed collision at precision " +
        formatNumber("%.3g", run.precision) + "\n" +
        formatTextTable(
            {"time", "pair", "verdict", "cells", "depth", "undecided cells", "median ms"}, rows, 2);
  }
  if (run.comparators.empty()) return text;
  std::vector<std::vector<std::string>> summary;
  for (const FrepBackendRow& row : run.comparators) {
    if (!row.created) {
      summary.push_back({row.backend, "-", "-", "-", "-", "-", "-", "-", row.failure});
      continue;
    }
    summary.push_back(
        {row.backend, std::to_string(row.resolution), std::to_string(row.triangles_first_pair),
         std::to_string(row.count(MeshAnswerOutcome::kAgrees)),
         std::to_string(row.count(MeshAnswerOutcome::kMissedOverlap)),
         std::to_string(row.count(MeshAnswerOutcome::kFalseContact)),
         std::to_string(row.count(MeshAnswerOutcome::kWithinPrecision)),
         row.failure.empty() ? formatNumber("%.3f", row.ms_per_query_with_meshing) : "-",
         row.failure.empty() ? "ok" : "failed: " + row.failure});
  }
  return text +
         "\nMesh backends on polygonizations (OpenVDB, cells along the longest side), against "
         "the guaranteed answers:\n" +
         formatTextTable({"backend", "resolution", "triangles", "agree", "missed", "false contact",
                          "within precision", "ms / query", "status"},
                         summary, 2) +
         "  ms / query: polygonization and build where a mesh changed, plus the query\n";
}

Result<std::string> frepPreviewPng(const FrepFile& file, const FrepRun& run,
                                   std::optional<double> time, int width, int height) {
  static const Eigen::Vector3d kPalette[] = {
      {0.35, 0.55, 0.85}, {0.95, 0.65, 0.25}, {0.45, 0.75, 0.45}, {0.7, 0.5, 0.8}, {0.6, 0.6, 0.6}};
  double shown = file.times[file.times.size() / 2];
  std::optional<Eigen::Vector3d> witness;
  for (const FrepSeedAnswer& answer : run.seed) {
    if (time && answer.time != *time) continue;
    if (answer.result.verdict == frep::CollisionVerdict::kColliding) {
      shown = answer.time;
      witness = answer.result.witness;
      break;
    }
  }
  if (time) shown = *time;
  std::vector<frep::SolidPtr> keep;
  std::vector<frep::PreviewSolid> solids;
  for (std::size_t i = 0; i < file.solids.size(); ++i) {
    keep.push_back(file.solids[i].at(shown));
    solids.push_back({keep.back().get(), kPalette[i % std::size(kPalette)]});
  }
  frep::PreviewOptions options;
  options.width = width;
  options.height = height;
  Result<frep::Image> image = frep::renderPreview(solids, witness, options);
  if (!image.ok()) return image.status();
  return frep::encodePng(image.value());
}

}  // namespace collido
