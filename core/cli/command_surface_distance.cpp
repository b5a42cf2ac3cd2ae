// collido surface-distance: the minimum distance between two NURBS surfaces of a surface file by
// the seed method (certified interval, hull or box bounds, work per subdivision level), and the
// same question answered by surface backends (OpenCASCADE, the seed as a plugin) and by mesh
// backends on tessellations of the surfaces: run time against error.
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iostream>

#include <nlohmann/json.hpp>

#include <collido/host/backend_instance.h>
#include <collido/io/files.h>
#include <collido/nurbs/surface_distance.h>
#include <collido/nurbs/tessellate.h>
#include <collido/runner/runner.h>
#include <collido/runner/statistics.h>
#include <collido/runner/text_table.h>
#include <collido/runner/timed_calls.h>
#include <collido/scene/surface_file.h>

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
  bool backends_only = false;  // no seed rows: the backends against the certified reference
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
                         {"name", std::filesystem::path(args.file).stem().string()},
                         {"a", a->name},
                         {"b", b->name},
                         {"model_size", size},
                         {"tolerance", tolerance},
                         {"seed", nlohmann::json::array()},
                         {"backends", nlohmann::json::array()}};

  // The seed method, per bound, as published (corners only) and with the descent.
  std::vector<std::vector<std::string>> rows;
  std::vector<std::vector<std::string>> level_rows;
  std::optional<nurbs::SurfaceDistance> reference;
  const std::vector<std::string> no_bounds;
  for (const std::string& bound_name : args.backends_only ? no_bounds : args.bounds) {
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
      // The runner's repeated protocol: one untimed call (the answer shown), then the timed ones.
      nurbs::SurfaceDistance d;
      const Result<std::vector<double>> timed = timeRepeated(args.repetitions, [&] {
        d = nurbs::minimumDistance(a->surface, b->surface, options);
        return Status();
      });
      std::vector<double> times;
      for (const double us : timed.value())
        times.push_back(us * 1e-3);
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
            << "\n";
  if (!args.backends_only) {
    std::cout << formatTextTable({"bound", "lower", "upper", "gap", "converged", "pairs bounded",
                                  "pairs opened", "levels", "median ms"},
                                 rows, 1);
  }
  if (args.levels) {
    std::cout << "\nWork per subdivision level:\n"
              << formatTextTable({"bound", "level", "pairs bounded", "pairs opened", "ms"},
                                 level_rows, 2);
  }

  // Backends, against a tighter certified reference: surface backends on the surfaces
  // themselves, mesh backends on tessellations.
  if (!args.backends.empty()) {
    nurbs::SurfaceDistanceOptions reference_options;
    reference_options.tolerance = 1e-10 * size;
    reference_options.max_pairs = 5'000'000;
    const nurbs::SurfaceDistance tight =
        nurbs::minimumDistance(a->surface, b->surface, reference_options);
    if (tight.converged) reference = tight;
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
    json["reference"] = {{"lower", reference->lower}, {"upper", reference->upper}};
    std::vector<std::vector<std::string>> backend_rows;
    std::vector<std::string> failures;
    for (const BackendSpec& spec : specs.value()) {
      Result<std::unique_ptr<BackendInstance>> created =
          BackendInstance::create(spec.library, spec.variant, spec.options);
      if (!created.ok()) {
        backend_rows.push_back({spec.label(), "-", "-", "-", "-", "-", "-", "-", "failed"});
        failures.push_back(spec.label() + ": " + created.status().message());
        json["backends"].push_back(
            {{"backend", spec.label()}, {"segments", 0}, {"status", created.status().message()}});
        continue;
      }
      BackendInstance& backend = *created.value();
      const Capabilities& caps = backend.capabilities();
      const bool on_surfaces = caps.buildsShape(ShapeKind::kNurbsSurface);
      std::vector<int> resolutions = on_surfaces ? std::vector<int>{0} : args.tessellations;
      for (const int segments : resolutions) {
        const std::string shape = segments == 0 ? "surfaces" : std::to_string(segments);
        if (!caps.queries.contains(QueryKind::kDistance)) {
          backend_rows.push_back({spec.label(), shape, "-", "-", "-", "-", "-", "-", "skipped"});
          failures.push_back(spec.label() + ": does not answer distance queries");
          json["backends"].push_back({{"backend", spec.label()},
                                      {"segments", 0},
                                      {"status", "does not answer distance queries"}});
          break;
        }
        const BuildNeeds needs{QueryKindSet(QueryKind::kDistance)};
        std::size_t triangles = 0;
        const Clock::time_point start = Clock::now();
        const Status not_built{StatusCode::kInternal, "not built"};
        Result<ModelHandle> ma = not_built;
        Result<ModelHandle> mb = not_built;
        if (segments == 0) {
          ma = backend.build(nurbs::viewOf(a->surface), needs);
          mb = backend.build(nurbs::viewOf(b->surface), needs);
        } else {
          const TriangleMesh mesh_a = nurbs::tessellate(a->surface, segments, segments);
          const TriangleMesh mesh_b = nurbs::tessellate(b->surface, segments, segments);
          triangles = mesh_a.triangleCount() + mesh_b.triangleCount();
          ma = backend.build(mesh_a.view(), needs);
          mb = backend.build(mesh_b.view(), needs);
        }
        const double build_ms = seconds(Clock::now() - start) * 1e3;
        std::string status;
        if (!ma.ok() || !mb.ok()) status = (ma.ok() ? mb.status() : ma.status()).message();
        QueryRequest request;
        request.kind = QueryKind::kDistance;
        // Surface backends are asked for the seed's tolerance; mesh backends for their best.
        if (segments == 0) request.abs_tolerance = tolerance;
        QueryResult result;
        std::vector<double> times;
        if (status.empty()) {
          Result<std::vector<double>> timed = timeRepeated(args.repetitions, [&] {
            return backend.query(ma.value(), Pose::Identity(), mb.value(), Pose::Identity(),
                                 request, result);
          });
          if (timed.ok()) {
            times = std::move(timed).value();
          } else {
            status = timed.status().message();
          }
        }
        if (!status.empty()) {
          backend_rows.push_back({spec.label(), shape, "-", "-", "-", "-", "-", "-", "failed"});
          failures.push_back(spec.label() + " (" + shape);
          failures.back() += "): " + status;
          json["backends"].push_back(
              {{"backend", spec.label()}, {"segments", segments}, {"status", status}});
          continue;
        }
        const double distance = result.distance.distance;
        const double error = distance - truth;
        backend_rows.push_back(
            {spec.label(), shape, segments == 0 ? "-" : std::to_string(triangles),
             formatNumber("%.12g", distance), formatNumber("%.3g", error),
             formatNumber("%.3g", std::abs(error) / size),
             formatNumber("%.1f", quantile(times, 0.5)), formatNumber("%.2f", build_ms), "ok"});
        json["backends"].push_back({{"backend", spec.label()},
                                    {"segments", segments},
                                    {"triangles", triangles},
                                    {"distance", distance},
                                    {"error", error},
                                    {"median_us", quantile(times, 0.5)},
                                    {"build_ms", build_ms},
                                    {"status", "ok"}});
      }
    }
    std::cout << "\nBackends (surfaces, or tessellations of segments x segments per surface), "
                 "error against the certified distance "
              << formatNumber("%.15g", truth) << " (+- "
              << formatNumber("%.2g", 0.5 * (reference->upper - reference->lower)) << "):\n"
              << formatTextTable({"backend", "shape", "triangles", "distance", "error",
                                  "error / size", "median us", "build ms", "status"},
                                 backend_rows, 2);
    for (const std::string& failure : failures)
      std::cout << "  " << failure << "\n";
  }
  if (!args.json_path.empty()) {
    if (Status s = io::writeFileAtomically(args.json_path, json.dump(1) + "\n"); !s.ok()) {
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
      ->check(nonNegativeNumber());
  command->add_flag("--seed-only", args->seed_only, "only the seed method as published");
  command->add_flag("--backends-only", args->backends_only,
                    "only the backends against the certified reference, not the seed's rows (how "
                    "collido study runs each backend in a worker of its own)");
  command->add_flag("--levels", args->levels, "print the work per subdivision level");
  command->add_option("--max-pairs", args->max_pairs, "patch pairs bounded before giving up");
  command
      ->add_option("--repetitions", args->repetitions,
                   "timed calls, after one untimed call (median reported)")
      ->check(CLI::Range(1, 100000));
  command
      ->add_option("--backends", args->backends,
                   "backends to compare: surface backends (nurbs:hull, occt:brep_extrema, ...) "
                   "on the surfaces, mesh backends on tessellations")
      ->delimiter(',');
  command->add_option("--tessellations", args->tessellations, "segments per parameter")
      ->delimiter(',')
      ->check(CLI::Range(1, 4096));
  command->add_option("--json", args->json_path, "also write the results as JSON");
  command->callback([args, &plugins, &exit_code] { exit_code = surfaceDistance(*args, plugins); });
}

}  // namespace collido::cli
