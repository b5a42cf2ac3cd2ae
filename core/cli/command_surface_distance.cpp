// collido surface-distance: the minimum distance between two NURBS surfaces of a surface file by
// the seed method (certified interval, hull or box bounds, work per subdivision level), and the
// same question answered by surface backends (OpenCASCADE, the seed as a plugin) and by mesh
// backends on tessellations of the surfaces: run time against error (runner/surface_run.h).
#include <iostream>
#include <optional>

#include <collido/io/files.h>
#include <collido/runner/surface_run.h>

#include "commands.h"

namespace collido::cli {
namespace {

struct SurfaceDistanceArguments {
  SurfaceRunRequest run;
  std::vector<std::string> bounds{"hull", "box"};
  bool backends_only = false;
  bool levels = false;
  std::vector<std::string> backends;
  std::string json_path;
};

int surfaceDistance(SurfaceDistanceArguments& args, const PluginOptions& plugin_options) {
  args.run.bounds.clear();
  for (const std::string& bound : args.bounds) {
    const std::optional<nurbs::PatchBound> parsed = parsePatchBound(bound);
    if (!parsed) {
      std::cerr << "error: --bounds: '" << bound << "' is not hull or box\n";
      return 2;
    }
    args.run.bounds.push_back(*parsed);
  }
  args.run.seed_rows = !args.backends_only;
  if (!args.backends.empty()) {
    const PluginDiscovery found =
        discoverPlugins(plugin_options.paths, !plugin_options.no_defaults);
    Result<std::vector<BackendSpec>> specs = resolveBackends(args.backends, found.plugins);
    if (!specs.ok()) {
      std::cerr << "error: " << specs.status().message() << "\n";
      return 2;
    }
    args.run.backends = std::move(specs).value();
  }
  const Result<SurfaceRun> run = runSurfaces(args.run);
  if (!run.ok()) {
    std::cerr << "error: " << run.status().message() << "\n";
    return run.status().code() == StatusCode::kUnsupported ? 1 : 2;
  }
  std::cout << surfaceRunText(run.value(), args.levels);
  if (!args.json_path.empty()) {
    const Status written =
        io::writeFileAtomically(args.json_path, surfaceRunJson(run.value()).dump(1) + "\n");
    if (!written.ok()) {
      std::cerr << "error: " << written.message() << "\n";
      return 2;
    }
  }
  return run.value().reference ? 0 : 1;
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
  command->add_option("file", args->run.file, "surface file (JSON, see scenes/README.md)")
      ->required();
  command->add_option("--a", args->run.a, "first surface (default: the file's first)");
  command->add_option("--b", args->run.b, "second surface (default: the file's second)");
  command->add_option("--bounds", args->bounds, "hull, box")->delimiter(',');
  command
      ->add_option("--tolerance", args->run.tolerance,
                   "stop when upper - lower <= this (default 1e-6 of the model's size)")
      ->check(nonNegativeNumber());
  command->add_flag("--seed-only", args->run.seed_only, "only the seed method as published");
  command->add_flag("--backends-only", args->backends_only,
                    "only the backends against the certified reference, not the seed's rows");
  command->add_flag("--levels", args->levels, "print the work per subdivision level");
  command->add_option("--max-pairs", args->run.max_pairs, "patch pairs bounded before giving up");
  command
      ->add_option("--repetitions", args->run.repetitions,
                   "timed calls, after one untimed call (median reported)")
      ->check(CLI::Range(1, 100000));
  command
      ->add_option("--backends", args->backends,
                   "backends to compare: surface backends (nurbs:hull, occt:brep_extrema, ...) "
                   "on the surfaces, mesh backends on tessellations")
      ->delimiter(',');
  command->add_option("--tessellations", args->run.tessellations, "segments per parameter")
      ->delimiter(',')
      ->check(CLI::Range(1, 4096));
  command->add_option("--json", args->json_path, "also write the results as JSON");
  command->callback([args, &plugins, &exit_code] { exit_code = surfaceDistance(*args, plugins); });
}

}  // namespace collido::cli
