// collido surface-distance: the minimum distance between two NURBS surfaces of a surface file by
// the seed method (certified interval, hull or box bounds, work per subdivision level), and the
// same question answered by mesh backends on tessellations of the surfaces: run time against
// error.
#include <algorithm>
#include <chrono>
#include <iostream>

#include <nlohmann/json.hpp>

#include <collido/host/backend_instance.h>
#include <collido/nurbs/surface_distance.h>
#include <collido/nurbs/tessellate.h>
#include <collido/runner/runner.h>
#include <collido/runner/statistics.h>
#include <collido/runner/text_table.h>
#include <collido/scene/surface_file.h>
#include <collido/study/result_store.h>

#include "commands.h"

namespace collido::cli {
namespace {

using Clock = std::chrono::steady_clock;

struct SurfaceDistanceArguments {
  std::string file;
  std::string a;
  std::string b;
  std::vector<std::string> bounds{"hull", "box"};
  double tolerance = 0.0;  // 0: 1e-6 of the model's size
  bool seed_only = false;
  bool levels = false;
  int repetitions = 5;
  std::size_t max_pairs = 200'000;
  std::vector<std::string> backends;
  std::vector<int> tessellations{8, 32, 128};
  std::string json_path;
};

double seconds(Clock::duration d) {
  return std::chrono::duration<double>(d).count();
}

const NamedSurface* find(const std::vector<NamedSurface>& surfaces, const std::string& name,
                         std::size_t fallback) {
  if (name.empty()) return fallback < surfaces.size() ? &surfaces[fallback] : nullptr;
  for (const NamedSurface& s : surfaces) {
    if (s.name == name) return &s;
  }
  return nullptr;
}

// The size of the model: the diagonal of both control nets' bounds.
double modelSize(const nurbs::NurbsSurface& a, const nurbs::NurbsSurface& b) {
  Eigen::Matrix3Xd all(3, static_cast<Eigen::Index>(a.control.size() + b.control.size()));
  all << a.controlPoints(), b.controlPoints();
  return (all.rowwise().maxCoeff() - all.rowwise().minCoeff()).norm();
}

int surfaceDistance(const SurfaceDistanceArguments& args, const PluginOptions& plugin_options) {
  Result<std::vector<NamedSurface>> surfaces = loadSurfaces(args.file);
  if (!surfaces.ok()) {
    std::cerr << "error: " << surfaces.status().message() << "\n";
    return 2;
  }
  const NamedSurface* a = find(surfaces.value(), args.a, 0);
  const NamedSurface* b = find(surfaces.value(), args.b, 1);
  if (a == nullptr || b == nullptr) {
    std::cerr << "error: " << args.file << ": no surface named '"
              << (a == nullptr ? args.a : args.b) << "' (or fewer than two surfaces)\n";
    return 2;
  }
  const double size = modelSize(a->surface, b->surface);
  const double tolerance = args.tolerance > 0.0 ? args.tolerance : 1e-6 * size;
  nlohmann::json json = {{"collidoscope_surface_distance", 1},
                         {"file", args.file},
                         {"a", a->name},
                         {"b", b->name},
                         {"model_size", size},
                         {"tolerance", tolerance},
                         {"seed", nlohmann::json::array()},
                         {"tessellations", nlohmann::json::array()}};

  // The seed method, per bound, as published (corners only) and with the descent.
  std::vector<std::vector<std::string>> rows;
  std::vector<std::vector<std::string>> level_rows;
  std::optional<nurbs::SurfaceDistance> reference;
  for (const std::string& bound_name : args.bounds) {
    if (bound_name != "hull" && bound_name != "box") {
      std::cerr << "error: --bounds: '" << bound_name << "' is not hull or box\n";
      return 2;
    }
    for (const bool refine : {false, true}) {
      if (refine && args.seed_only) continue;
      nurbs::SurfaceDistanceOptions options;
      options.bound =
          bound_name == "hull" ? nurbs::PatchBound::kConvexHull : nurbs::PatchBound::kBox;
      options.refine = refine;
      options.tolerance = tolerance;
      options.max_pairs = args.max_pairs;
      std::vector<double> times;
      nurbs::SurfaceDistance d;
      for (int rep = 0; rep < std::max(1, args.repetitions); ++rep) {
        const Clock::time_point start = Clock::now();
        d = nurbs::minimumDistance(a->surface, b->surface, options);
        times.push_back(seconds(Clock::now() - start) * 1e3);
      }
      const std::string label = bound_name + (refine ? " + descent" : " (seed)");
      rows.push_back({label, formatNumber("%.12g", d.lower), formatNumber("%.12g", d.upper),
                      formatNumber("%.3g", d.upper - d.lower), d.converged ? "yes" : "no",
                      std::to_string(d.pairs_bounded), std::to_string(d.pairs_opened),
                      std::to_string(d.levels.size()), formatNumber("%.3f", quantile(times, 0.5))});
      for (std::size_t level = 0; level < d.levels.size(); ++level) {
        const nurbs::LevelWork& w = d.levels[level];
        level_rows.push_back({label, std::to_string(level), std::to_string(w.pairs_bounded),
                              std::to_string(w.pairs_opened),
                              formatNumber("%.3f", w.seconds * 1e3)});
      }
      nlohmann::json levels = nlohmann::json::array();
      for (const nurbs::LevelWork& w : d.levels)
        levels.push_back({{"pairs_bounded", w.pairs_bounded},
                          {"pairs_opened", w.pairs_opened},
                          {"ms", w.seconds * 1e3}});
      json["seed"].push_back({{"bound", bound_name},
                              {"descent", refine},
                              {"lower", d.lower},
                              {"upper", d.upper},
                              {"converged", d.converged},
                              {"pairs_bounded", d.pairs_bounded},
                              {"pairs_opened", d.pairs_opened},
                              {"median_ms", quantile(times, 0.5)},
                              {"levels", levels}});
      if (d.converged && (!reference || d.upper - d.lower < reference->upper - reference->lower))
        reference = d;
    }
  }
  std::cout << a->name << " against " << b->name << " (" << args.file << "): model size "
            << formatNumber("%.4g", size) << ", tolerance " << formatNumber("%.3g", tolerance)
            << "\n"
            << formatTextTable({"bound", "lower", "upper", "gap", "converged", "pairs bounded",
                                "pairs opened", "levels", "median ms"},
                               rows, 1);
  if (args.levels) {
    std::cout << "\nWork per subdivision level:\n"
              << formatTextTable({"bound", "level", "pairs bounded", "pairs opened", "ms"},
                                 level_rows, 2);
  }

  // Mesh backends on tessellations, against the certified interval.
  if (!args.backends.empty()) {
    if (!reference) {
      std::cerr << "error: no bound converged: no certified distance to measure errors against\n";
      return 1;
    }
    const PluginDiscovery found =
        discoverPlugins(plugin_options.paths, !plugin_options.no_defaults);
    Result<std::vector<BackendSpec>> specs = resolveBackends(args.backends, found.plugins);
    if (!specs.ok()) {
      std::cerr << "error: " << specs.status().message() << "\n";
      return 2;
    }
    const double truth = 0.5 * (reference->lower + reference->upper);
    std::vector<std::vector<std::string>> mesh_rows;
    for (const int segments : args.tessellations) {
      const TriangleMesh mesh_a = nurbs::tessellate(a->surface, segments, segments);
      const TriangleMesh mesh_b = nurbs::tessellate(b->surface, segments, segments);
      for (const BackendSpec& spec : specs.value()) {
        Result<std::unique_ptr<BackendInstance>> backend =
            BackendInstance::create(spec.library, spec.variant, spec.options);
        std::string status;
        double distance = 0.0;
        double build_ms = 0.0;
        std::vector<double> times;
        if (!backend.ok()) {
          status = backend.status().message();
        } else if (!backend.value()->capabilities().queries.contains(QueryKind::kDistance)) {
          status = "does not answer distance queries";
        } else {
          const BuildNeeds needs{QueryKindSet(QueryKind::kDistance)};
          const Clock::time_point start = Clock::now();
          Result<ModelHandle> ma = backend.value()->build(mesh_a.view(), needs);
          Result<ModelHandle> mb = backend.value()->build(mesh_b.view(), needs);
          build_ms = seconds(Clock::now() - start) * 1e3;
          QueryRequest request;
          request.kind = QueryKind::kDistance;
          QueryResult result;
          for (int rep = 0; rep <= args.repetitions && ma.ok() && mb.ok() && status.empty();
               ++rep) {
            const Clock::time_point q = Clock::now();
            const Status s = backend.value()->query(ma.value(), Pose::Identity(), mb.value(),
                                                    Pose::Identity(), request, result);
            if (!s.ok()) status = s.message();
            if (rep > 0) times.push_back(seconds(Clock::now() - q) * 1e6);
          }
          if (!ma.ok() || !mb.ok()) status = (ma.ok() ? mb.status() : ma.status()).message();
          distance = result.distance.distance;
        }
        if (!status.empty()) {
          mesh_rows.push_back(
              {spec.label(), std::to_string(segments), "-", "-", "-", "-", "-", status});
          continue;
        }
        const double error = distance - truth;
        mesh_rows.push_back({spec.label(), std::to_string(segments),
                             std::to_string(mesh_a.triangleCount() + mesh_b.triangleCount()),
                             formatNumber("%.9g", distance), formatNumber("%.3g", error),
                             formatNumber("%.3g", std::abs(error) / std::max(truth, 1e-300)),
                             formatNumber("%.1f", quantile(times, 0.5)),
                             formatNumber("%.2f", build_ms)});
        json["tessellations"].push_back({{"backend", spec.label()},
                                         {"segments", segments},
                                         {"distance", distance},
                                         {"error", error},
                                         {"median_us", quantile(times, 0.5)},
                                         {"build_ms", build_ms}});
      }
    }
    std::cout << "\nMesh backends on tessellations (segments x segments per surface), error "
                 "against the certified distance "
              << formatNumber("%.12g", truth) << " (+- "
              << formatNumber("%.2g", 0.5 * (reference->upper - reference->lower)) << "):\n"
              << formatTextTable({"backend", "segments", "triangles", "distance", "error",
                                  "relative", "median us", "build ms"},
                                 mesh_rows, 2);
  }
  if (!args.json_path.empty()) {
    if (Status s = study::writeFileAtomically(args.json_path, json.dump(1) + "\n"); !s.ok()) {
      std::cerr << "error: " << s.message() << "\n";
      return 2;
    }
  }
  return reference ? 0 : 1;
}

}  // namespace

void addSurfaceDistanceCommand(CLI::App& app, const PluginOptions& plugins, int& exit_code) {
  auto args = std::make_shared<SurfaceDistanceArguments>();
  CLI::App* command = app.add_subcommand(
      "surface-distance",
      "The minimum distance between two NURBS surfaces of a surface file by the seed method "
      "(certified interval; convex-hull or box bounds; work per subdivision level), and mesh "
      "backends on tessellations of the surfaces against it. Exit code 1 when no bound "
      "converged within --max-pairs.");
  command->add_option("file", args->file, "surface file (JSON, see scenes/README.md)")->required();
  command->add_option("--a", args->a, "first surface (default: the file's first)");
  command->add_option("--b", args->b, "second surface (default: the file's second)");
  command->add_option("--bounds", args->bounds, "hull, box")->delimiter(',');
  command
      ->add_option("--tolerance", args->tolerance,
                   "stop when upper - lower <= this (default 1e-6 of the model's size)")
      ->check(CLI::NonNegativeNumber);
  command->add_flag("--seed-only", args->seed_only, "only the seed method as published");
  command->add_flag("--levels", args->levels, "print the work per subdivision level");
  command->add_option("--max-pairs", args->max_pairs, "patch pairs bounded before giving up");
  command->add_option("--repetitions", args->repetitions, "timed runs (median reported)")
      ->check(CLI::Range(1, 100000));
  command->add_option("--backends", args->backends, "mesh backends to run on tessellations")
      ->delimiter(',');
  command->add_option("--tessellations", args->tessellations, "segments per parameter")
      ->delimiter(',')
      ->check(CLI::Range(1, 4096));
  command->add_option("--json", args->json_path, "also write the results as JSON");
  command->callback([args, &plugins, &exit_code] { exit_code = surfaceDistance(*args, plugins); });
}

}  // namespace collido::cli
