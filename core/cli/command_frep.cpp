// collido frep: the guaranteed collision test between FRep solids (the seed method's octree
// with interval bounds) frame by frame, and the usual alternative measured against it:
// polygonize each solid at several resolutions, then ask mesh backends (runner/frep_run.h).
#include <filesystem>
#include <iostream>
#include <optional>

#include <collido/io/files.h>
#include <collido/runner/frep_run.h>

#include "commands.h"

namespace collido::cli {
namespace {

struct FrepArguments {
  std::string file;
  FrepRunRequest run;
  bool backends_only = false;
  std::vector<std::string> backends;
  std::string json_path;
  std::string preview_path;
  std::optional<double> preview_time;
  std::vector<int> preview_size{480, 360};
};

// Writes the preview picture; the JSON names it relative to itself when both are written (the
// dashboard finds it there).
Status writePreview(const FrepArguments& args, const FrepFile& file, const FrepRun& run,
                    nlohmann::json& json) {
  const Result<std::string> png =
      frepPreviewPng(file, run, args.preview_time, args.preview_size[0], args.preview_size[1]);
  if (!png.ok()) return png.status();
  if (Status s = io::writeFileAtomically(args.preview_path, png.value()); !s.ok()) return s;
  const std::filesystem::path picture = std::filesystem::absolute(args.preview_path);
  json["preview"] =
      args.json_path.empty()
          ? picture.string()
          : picture.lexically_relative(std::filesystem::absolute(args.json_path).parent_path())
                .string();
  return Status();
}

int frepCommand(FrepArguments& args, const PluginOptions& plugin_options) {
  const Result<FrepFile> file = loadFrepFile(args.file);
  if (!file.ok()) {
    std::cerr << "error: " << file.status().message() << "\n";
    return 2;
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
  const Result<FrepRun> run = runFrep(file.value(), args.file, args.run);
  if (!run.ok()) {
    std::cerr << "error: " << run.status().message() << "\n";
    return run.status().code() == StatusCode::kInvalidArgument ? 2 : 1;
  }
  std::cout << frepRunText(run.value());
  nlohmann::json json = frepRunJson(run.value());
  if (!args.preview_path.empty()) {
    if (Status s = writePreview(args, file.value(), run.value(), json); !s.ok()) {
      std::cerr << "error: " << s.message() << "\n";
      return 2;
    }
  }
  if (!args.json_path.empty()) {
    if (Status s = io::writeFileAtomically(args.json_path, json.dump(1) + "\n"); !s.ok()) {
      std::cerr << "error: " << s.message() << "\n";
      return 2;
    }
  }
  if (run.value().unexpected > 0) {
    std::cerr << "error: " << run.value().unexpected
              << " answers differ from the file's expected ones\n";
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
  command->add_option("--precision", args->run.precision, "octree cell size (default: the file's)")
      ->check(CLI::PositiveNumber);
  command
      ->add_option("--repetitions", args->run.repetitions,
                   "timed calls, after one untimed call (median reported)")
      ->check(CLI::Range(1, 1000));
  command
      ->add_option("--backends", args->backends,
                   "mesh backends to run on polygonizations (obbtree, fcl:obb, bullet, ode, ...)")
      ->delimiter(',');
  command->add_option("--resolutions", args->run.resolutions, "grid cells along the longest side")
      ->delimiter(',')
      ->check(CLI::Range(2, 1024));
  command->add_option("--json", args->json_path, "also write the results as JSON");
  command->add_option("--preview", args->preview_path,
                      "write a ray-cast picture of the solids (PNG) at the first frame with a "
                      "collision (its witness as a red dot), else the middle frame, or at "
                      "--preview-time");
  command->add_flag("--backends-only", args->backends_only,
                    "only the backends: the seed's answers are computed once, untimed, as their "
                    "reference");
  command->add_option("--preview-time", args->preview_time, "frame time of the preview");
  command->add_option("--preview-size", args->preview_size, "width,height in pixels")
      ->delimiter(',')
      ->expected(2)
      ->check(CLI::Range(16, 4096));
  command->callback([args, &plugins, &exit_code] { exit_code = frepCommand(*args, plugins); });
}

}  // namespace collido::cli
