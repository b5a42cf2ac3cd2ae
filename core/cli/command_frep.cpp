// collido frep: the guaranteed collision test between FRep solids (the seed method's octree
// with interval bounds) frame by frame, and the usual alternative measured against it:
// polygonize each solid at several resolutions, then ask mesh backends.
#include <chrono>
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>

#include <nlohmann/json.hpp>

#include <collido/frep/collision.h>
#include <collido/frep_mesh/polygonize.h>
#include <collido/frep_preview/preview.h>
#include <collido/host/backend_instance.h>
#include <collido/io/files.h>
#include <collido/runner/runner.h>
#include <collido/runner/statistics.h>
#include <collido/runner/text_table.h>
#include <collido/runner/timed_calls.h>
#include <collido/scene/frep_file.h>

#include "commands.h"

namespace collido::cli {
namespace {

using Clock = std::chrono::steady_clock;
using Json = nlohmann::json;

struct FrepArguments {
  std::string file;
  double precision = 0.0;  // 0: the file's
  int repetitions = 3;
  std::vector<std::string> backends;
  std::vector<int> resolutions{16, 32, 64};
  std::string json_path;
  std::string preview_path;
  std::optional<double> preview_time;
  std::vector<int> preview_size{480, 360};
  bool backends_only = false;  // the seed's answers once, untimed, as the reference only
};

// The preview: every solid at one frame (the asked time, else the first frame with a collision,
// else the middle one), with that frame's first witness as a red dot.
Status writePreview(const FrepArguments& args, const FrepFile& file, const Json& seed) {
  static const Eigen::Vector3d kPalette[] = {
      {0.35, 0.55, 0.85}, {0.95, 0.65, 0.25}, {0.45, 0.75, 0.45}, {0.7, 0.5, 0.8}, {0.6, 0.6, 0.6}};
  double time = file.times[file.times.size() / 2];
  std::optional<Eigen::Vector3d> witness;
  for (const Json& entry : seed) {
    const double t = entry["time"].get<double>();
    if (args.preview_time && t != *args.preview_time) continue;
    if (entry.contains("witness")) {
      time = t;
      witness =
          Eigen::Vector3d(entry["witness"][0].get<double>(), entry["witness"][1].get<double>(),
                          entry["witness"][2].get<double>());
      break;
    }
  }
  if (args.preview_time) time = *args.preview_time;
  std::vector<frep::SolidPtr> keep;
  std::vector<frep::PreviewSolid> solids;
  for (std::size_t i = 0; i < file.solids.size(); ++i) {
    keep.push_back(file.solids[i].at(time));
    solids.push_back({keep.back().get(), kPalette[i % std::size(kPalette)]});
  }
  frep::PreviewOptions options;
  options.width = args.preview_size[0];
  options.height = args.preview_size[1];
  Result<frep::Image> image = frep::renderPreview(solids, witness, options);
  if (!image.ok()) return image.status();
  return frep::writePng(image.value(), args.preview_path);
}

double millisecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

std::string pairName(const FrepFile& file, std::size_t pair) {
  return file.solids[file.pairs[pair].first].name + " / " +
         file.solids[file.pairs[pair].second].name;
}

// How a mesh backend's boolean answer compares with the guaranteed one.
std::string outcomeOf(frep::CollisionVerdict truth, bool intersecting) {
  switch (truth) {
    case frep::CollisionVerdict::kColliding:
      return intersecting ? "agrees" : "missed overlap";
    case frep::CollisionVerdict::kSeparated:
      return intersecting ? "false contact" : "agrees";
    case frep::CollisionVerdict::kTouching:
      return "within precision";
    case frep::CollisionVerdict::kUndecided:
      break;
  }
  return "no reference";
}

// A polygonized solid: its mesh (or why there is none) and what it cost.
struct Polygonized {
  std::optional<TriangleMesh> mesh;
  std::string error;
  double ms = 0.0;
};

int runFrep(const FrepArguments& args, const PluginOptions& plugin_options) {
  Result<FrepFile> loaded = loadFrepFile(args.file);
  if (!loaded.ok()) {
    std::cerr << "error: " << loaded.status().message() << "\n";
    return 2;
  }
  const FrepFile& file = loaded.value();
  frep::CollisionOptions options;
  options.precision = args.precision > 0 ? args.precision : file.precision;

  Json json = {{"collidoscope_frep", 1}, {"file", args.file},
               {"name", file.name},      {"precision", options.precision},
               {"seed", Json::array()},  {"comparators", Json::array()}};

  // The seed method, per frame and pair.
  std::vector<std::vector<frep::CollisionVerdict>> truth(file.times.size());  // per frame, pair
  std::vector<std::vector<std::string>> rows;
  int unexpected = 0;
  for (std::size_t f = 0; f < file.times.size(); ++f) {
    const double time = file.times[f];
    for (std::size_t p = 0; p < file.pairs.size(); ++p) {
      const frep::SolidPtr a = file.solids[file.pairs[p].first].at(time);
      const frep::SolidPtr b = file.solids[file.pairs[p].second].at(time);
      std::vector<double> ms;
      frep::CollisionResult result;
      try {
        // The runner's repeated protocol: one untimed call (the answer shown), then timed ones.
        const int repetitions = args.backends_only ? 0 : args.repetitions;
        const Result<std::vector<double>> timed = timeRepeated(repetitions, [&] {
          result = frep::collide(*a, *b, options);
          return Status();
        });
        for (const double us : timed.value())
          ms.push_back(us * 1e-3);
      } catch (const std::invalid_argument& error) {
        std::cerr << "error: " << args.file << ": " << pairName(file, p) << ": " << error.what()
                  << "\n";
        return 2;
      } catch (const std::exception& error) {
        // Boost.Interval refuses some degenerate operations (an empty interval) by throwing.
        std::cerr << "error: " << args.file << ": " << pairName(file, p)
                  << ": the interval evaluation failed: " << error.what() << "\n";
        return 1;
      }
      truth[f].push_back(result.verdict);
      if (args.backends_only) continue;
      const std::string verdict = frep::verdictName(result.verdict);
      const std::string& expected = file.expected[p];
      const bool as_expected = expected.empty() || expected == verdict;
      std::string shown = verdict;
      if (!as_expected) {
        ++unexpected;
        shown += " (expected " + expected + ")";
      }
      rows.push_back({formatNumber("%.3g", time), pairName(file, p), shown,
                      std::to_string(result.cells), std::to_string(result.max_depth),
                      std::to_string(result.undecided_cells),
                      formatNumber("%.3f", quantile(ms, 0.5))});
      Json levels = Json::array();
      for (const frep::CollisionLevel& level : result.levels)
        levels.push_back(
            {{"cells", level.cells}, {"discarded", level.discarded}, {"split", level.split}});
      Json entry = {{"time", time},
                    {"pair", pairName(file, p)},
                    {"verdict", verdict},
                    {"expected", expected},
                    {"cells", result.cells},
                    {"max_depth", result.max_depth},
                    {"undecided_cells", result.undecided_cells},
                    {"median_ms", quantile(ms, 0.5)},
                    {"levels", levels}};
      if (result.verdict == frep::CollisionVerdict::kColliding)
        entry["witness"] = {result.witness.x(), result.witness.y(), result.witness.z()};
      json["seed"].push_back(entry);
    }
  }
  if (!args.backends_only) {
    std::cout << file.name << " (" << args.file << "): guaranteed collision at precision "
              << formatNumber("%.3g", options.precision) << "\n"
              << formatTextTable(
                     {"time", "pair", "verdict", "cells", "depth", "undecided cells", "median ms"},
                     rows, 2);
  }

  if (!args.backends.empty()) {
    const PluginDiscovery found =
        discoverPlugins(plugin_options.paths, !plugin_options.no_defaults);
    Result<std::vector<BackendSpec>> specs = resolveBackends(args.backends, found.plugins);
    if (!specs.ok()) {
      std::cerr << "error: " << specs.status().message() << "\n";
      return 2;
    }
    // Meshes per resolution, frame and solid: static solids are polygonized once.
    std::map<std::tuple<int, std::size_t, std::size_t>, Polygonized> meshes;
    const auto meshOf = [&](int resolution, std::size_t frame, std::size_t solid) -> Polygonized& {
      const std::size_t key_frame = file.solids[solid].animated ? frame : 0;
      auto key = std::make_tuple(resolution, key_frame, solid);
      auto found_mesh = meshes.find(key);
      if (found_mesh != meshes.end()) return found_mesh->second;
      Polygonized& out = meshes[key];
      const frep::SolidPtr shape = file.solids[solid].at(file.times[key_frame]);
      const Clock::time_point start = Clock::now();
      Result<TriangleMesh> mesh = frep::polygonize(*shape, shape->bounds(), resolution);
      out.ms = millisecondsSince(start);
      if (mesh.ok())
        out.mesh = std::move(mesh.value());
      else
        out.error = file.solids[solid].name + ": " + mesh.status().message();
      return out;
    };
    std::vector<std::vector<std::string>> summary;
    for (const BackendSpec& spec : specs.value()) {
      Result<std::unique_ptr<BackendInstance>> created =
          BackendInstance::create(spec.library, spec.variant, spec.options);
      if (!created.ok()) {
        summary.push_back(
            {spec.label(), "-", "-", "-", "-", "-", "-", "-", created.status().message()});
        continue;
      }
      BackendInstance& backend = *created.value();
      for (const int resolution : args.resolutions) {
        std::map<std::string, int> outcomes;
        std::vector<double> query_us;
        double charged_ms = 0.0;  // polygonization and build, each mesh once
        std::size_t triangles = 0;
        std::string failure;
        Json frames = Json::array();
        for (std::size_t f = 0; f < file.times.size() && failure.empty(); ++f) {
          for (std::size_t p = 0; p < file.pairs.size() && failure.empty(); ++p) {
            const std::size_t ids[2] = {file.pairs[p].first, file.pairs[p].second};
            ModelHandle models[2] = {0, 0};
            double frame_ms = 0.0;
            for (int k = 0; k < 2; ++k) {
              Polygonized& shape = meshOf(resolution, f, ids[k]);
              if (!shape.mesh) {
                failure = shape.error;
                break;
              }
              const bool fresh = f == 0 || file.solids[ids[k]].animated;
              if (fresh) frame_ms += shape.ms;
              const Clock::time_point start = Clock::now();
              Result<ModelHandle> built =
                  backend.build(shape.mesh->view(), BuildNeeds{QueryKindSet(QueryKind::kBoolean)});
              if (fresh) frame_ms += millisecondsSince(start);
              if (!built.ok()) {
                failure = built.status().message();
                break;
              }
              models[k] = built.value();
              if (f == 0 && p == 0) triangles += shape.mesh->triangleCount();
            }
            if (failure.empty()) {
              QueryRequest request;
              request.kind = QueryKind::kBoolean;
              QueryResult answer;
              Result<std::vector<double>> timed = timeRepeated(args.repetitions, [&] {
                return backend.query(models[0], Pose::Identity(), models[1], Pose::Identity(),
                                     request, answer);
              });
              std::vector<double> us;
              if (timed.ok()) {
                us = std::move(timed).value();
              } else {
                failure = timed.status().message();
              }
              if (failure.empty()) {
                const std::string outcome = outcomeOf(truth[f][p], answer.intersecting);
                ++outcomes[outcome];
                query_us.push_back(quantile(us, 0.5));
                charged_ms += frame_ms + quantile(us, 0.5) * 1e-3;
                frames.push_back({{"time", file.times[f]},
                                  {"pair", pairName(file, p)},
                                  {"intersecting", answer.intersecting},
                                  {"outcome", outcome},
                                  {"query_us", quantile(us, 0.5)},
                                  {"ms_with_meshing", frame_ms + quantile(us, 0.5) * 1e-3}});
              }
            }
            for (ModelHandle model : models)
              if (model != 0) (void)backend.release(model);
          }
        }
        const std::size_t queries = file.times.size() * file.pairs.size();
        const int wrong = outcomes["missed overlap"] + outcomes["false contact"];
        summary.push_back(
            {spec.label(), std::to_string(resolution), std::to_string(triangles),
             std::to_string(outcomes["agrees"]), std::to_string(outcomes["missed overlap"]),
             std::to_string(outcomes["false contact"]),
             std::to_string(outcomes["within precision"]),
             failure.empty() ? formatNumber("%.3f", charged_ms / static_cast<double>(queries))
                             : "-",
             failure.empty() ? "ok" : "failed: " + failure});
        json["comparators"].push_back(
            {{"backend", spec.label()},
             {"resolution", resolution},
             {"triangles_first_pair", triangles},
             {"agrees", outcomes["agrees"]},
             {"missed", outcomes["missed overlap"]},
             {"false_contacts", outcomes["false contact"]},
             {"within_precision", outcomes["within precision"]},
             {"wrong", wrong},
             {"ms_per_query_with_meshing", charged_ms / static_cast<double>(queries)},
             {"median_query_us", query_us.empty() ? 0.0 : quantile(query_us, 0.5)},
             {"status", failure.empty() ? "ok" : failure},
             {"frames", frames}});
      }
    }
    std::cout << "\nMesh backends on polygonizations (OpenVDB, cells along the longest side), "
                 "against the guaranteed answers:\n"
              << formatTextTable({"backend", "resolution", "triangles", "agree", "missed",
                                  "false contact", "within precision", "ms / query", "status"},
                                 summary, 2)
              << "  ms / query: polygonization and build where a mesh changed, plus the query\n";
  }
  if (!args.preview_path.empty()) {
    if (Status s = writePreview(args, file, json["seed"]); !s.ok()) {
      std::cerr << "error: " << s.message() << "\n";
      return 2;
    }
    // Relative to the JSON file when both are written (the dashboard finds it there).
    const std::filesystem::path picture = std::filesystem::absolute(args.preview_path);
    json["preview"] =
        args.json_path.empty()
            ? picture.string()
            : picture.lexically_relative(std::filesystem::absolute(args.json_path).parent_path())
                  .string();
  }
  if (!args.json_path.empty()) {
    if (Status s = io::writeFileAtomically(args.json_path, json.dump(1) + "\n"); !s.ok()) {
      std::cerr << "error: " << s.message() << "\n";
      return 2;
    }
  }
  if (unexpected > 0) {
    std::cerr << "error: " << unexpected << " answers differ from the file's expected ones\n";
    return 1;
  }
  return 0;
}

}  // namespace

void addFrepCommand(CLI::App& app, const PluginOptions& plugins, int& exit_code) {
  auto args = std::make_shared<FrepArguments>();
  CLI::App* command = app.add_subcommand(
      "frep",
      "Guaranteed collision between FRep solids of an FRep file, frame by frame (octree with "
      "interval bounds: colliding with a witness, separated with a proof, or touching within the "
      "precision), and mesh backends on polygonizations against it. Exit code 1 when an answer "
      "differs from the file's expected one.");
  command->add_option("file", args->file, "FRep file (JSON, see docs/frep.md)")->required();
  command->add_option("--precision", args->precision, "octree cell size (default: the file's)")
      ->check(CLI::PositiveNumber);
  command
      ->add_option("--repetitions", args->repetitions,
                   "timed calls, after one untimed call (median reported)")
      ->check(CLI::Range(1, 1000));
  command
      ->add_option("--backends", args->backends,
                   "mesh backends to run on polygonizations (obbtree, fcl:obb, bullet, ode, ...)")
      ->delimiter(',');
  command->add_option("--resolutions", args->resolutions, "grid cells along the longest side")
      ->delimiter(',')
      ->check(CLI::Range(2, 1024));
  command->add_option("--json", args->json_path, "also write the results as JSON");
  command->add_option("--preview", args->preview_path,
                      "write a ray-cast picture of the solids (PNG) at the first frame with a "
                      "collision (its witness as a red dot), else the middle frame, or at "
                      "--preview-time");
  command->add_flag("--backends-only", args->backends_only,
                    "only the backends: the seed's answers are computed once, untimed, as their "
                    "reference (how collido study runs each backend in a worker of its own)");
  command->add_option("--preview-time", args->preview_time, "frame time of the preview");
  command->add_option("--preview-size", args->preview_size, "width,height in pixels")
      ->delimiter(',')
      ->expected(2)
      ->check(CLI::Range(16, 4096));
  command->callback([args, &plugins, &exit_code] { exit_code = runFrep(*args, plugins); });
}

}  // namespace collido::cli
