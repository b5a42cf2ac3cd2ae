#include <collido/runner/surface_run.h>

#include <chrono>
#include <cmath>

#include <collido/host/backend_instance.h>
#include <collido/nurbs/tessellate.h>
#include <collido/runner/statistics.h>
#include <collido/runner/text_table.h>
#include <collido/runner/timed_calls.h>
#include <collido/scene/surface_file.h>

namespace collido {
namespace {

using Json = nlohmann::json;

const NamedSurface* find(const std::vector<NamedSurface>& surfaces, const std::string& name,
                         std::size_t fallback) {
  if (name.empty()) return fallback < surfaces.size() ? &surfaces[fallback] : nullptr;
  for (const NamedSurface& s : surfaces) {
    if (s.name == name) return &s;
  }
  return nullptr;
}

double modelSize(const nurbs::NurbsSurface& a, const nurbs::NurbsSurface& b) {
  Eigen::Matrix3Xd all(3, static_cast<Eigen::Index>(a.control.size() + b.control.size()));
  all << a.controlPoints(), b.controlPoints();
  return (all.rowwise().maxCoeff() - all.rowwise().minCoeff()).norm();
}

// The seed method, per bound, as published (corners only) and with the descent.
std::vector<SeedDistanceRow> seedRows(const SurfaceRunRequest& request, const NamedSurface& a,
                                      const NamedSurface& b, double tolerance) {
  std::vector<SeedDistanceRow> rows;
  if (!request.seed_rows) return rows;
  for (const nurbs::PatchBound bound : request.bounds) {
    for (const bool descent : {false, true}) {
      if (descent && request.seed_only) continue;
      nurbs::SurfaceDistanceOptions options;
      options.bound = bound;
      options.refine = descent;
      options.tolerance = tolerance;
      options.max_pairs = request.max_pairs;
      SeedDistanceRow row{bound, descent, {}, 0.0};
      const Result<std::vector<double>> timed = timeRepeated(request.repetitions, [&] {
        row.distance = nurbs::minimumDistance(a.surface, b.surface, options);
        return Status();
      });
      row.median_ms = quantile(timed.value(), 0.5) * 1e-3;
      rows.push_back(std::move(row));
    }
  }
  return rows;
}

// One backend on the surfaces (segments 0) or on tessellations of `segments` per parameter.
SurfaceBackendRow backendRow(BackendInstance& backend, const std::string& label,
                             const NamedSurface& a, const NamedSurface& b, int segments,
                             double tolerance, double truth, int repetitions) {
  SurfaceBackendRow row;
  row.backend = label;
  row.segments = segments;
  const BuildNeeds needs{QueryKindSet(QueryKind::kDistance)};
  const Status not_built{StatusCode::kInternal, "not built"};
  Result<ModelHandle> ma = not_built;
  Result<ModelHandle> mb = not_built;
  const std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
  if (segments == 0) {
    ma = backend.build(nurbs::viewOf(a.surface), needs);
    mb = backend.build(nurbs::viewOf(b.surface), needs);
  } else {
    const TriangleMesh mesh_a = nurbs::tessellate(a.surface, segments, segments);
    const TriangleMesh mesh_b = nurbs::tessellate(b.surface, segments, segments);
    row.triangles = mesh_a.triangleCount() + mesh_b.triangleCount();
    ma = backend.build(mesh_a.view(), needs);
    mb = backend.build(mesh_b.view(), needs);
  }
  row.build_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  if (!ma.ok() || !mb.ok()) {
    row.end = SurfaceRowEnd::kFailed;
    row.failure = (ma.ok() ? mb.status() : ma.status()).message();
    return row;
  }
  QueryRequest request;
  request.kind = QueryKind::kDistance;
  // Surface backends are asked for the seed's tolerance; mesh backends for their best.
  if (segments == 0) request.abs_tolerance = tolerance;
  QueryResult result;
  const Result<std::vector<double>> timed = timeRepeated(repetitions, [&] {
    return backend.query(ma.value(), Pose::Identity(), mb.value(), Pose::Identity(), request,
                         result);
  });
  if (!timed.ok()) {
    row.end = SurfaceRowEnd::kFailed;
    row.failure = timed.status().message();
    return row;
  }
  // An answer with no finite distance is a failure, not a row with an infinite error.
  if (!std::isfinite(result.distance.distance)) {
    row.end = SurfaceRowEnd::kFailed;
    row.failure = "no finite distance reported";
    return row;
  }
  row.distance = result.distance.distance;
  row.error = row.distance - truth;
  row.median_us = quantile(timed.value(), 0.5);
  if (result.counters.counts_bv_tests) row.bv_tests = result.counters.bv_tests;
  if (result.counters.counts_primitive_tests) row.primitive_tests = result.counters.primitive_tests;
  return row;
}

// A row for a backend that measured nothing, and why.
SurfaceBackendRow unmeasuredRow(const std::string& backend, SurfaceRowEnd end,
                                const std::string& why) {
  SurfaceBackendRow row;
  row.backend = backend;
  row.end = end;
  row.failure = why;
  return row;
}

// Every backend's rows: surface backends on the surfaces, mesh backends on each tessellation.
std::vector<SurfaceBackendRow> backendRows(const SurfaceRunRequest& request, const NamedSurface& a,
                                           const NamedSurface& b, double tolerance, double truth) {
  std::vector<SurfaceBackendRow> rows;
  for (const BackendSpec& spec : request.backends) {
    Result<std::unique_ptr<BackendInstance>> created =
        BackendInstance::create(spec.library, spec.variant, spec.pluginOptions());
    if (!created.ok()) {
      rows.push_back(
          unmeasuredRow(spec.label(), SurfaceRowEnd::kNotCreated, created.status().message()));
      continue;
    }
    BackendInstance& backend = *created.value();
    const Capabilities& caps = backend.capabilities();
    if (!caps.queries.contains(QueryKind::kDistance)) {
      rows.push_back(unmeasuredRow(spec.label(), SurfaceRowEnd::kNoDistance,
                                   "does not answer distance queries"));
      continue;
    }
    const bool on_surfaces = caps.buildsShape(ShapeKind::kNurbsSurface);
    for (const int segments : on_surfaces ? std::vector<int>{0} : request.tessellations) {
      rows.push_back(
          backendRow(backend, spec.label(), a, b, segments, tolerance, truth, request.repetitions));
    }
  }
  return rows;
}

std::string shapeText(const SurfaceBackendRow& row) {
  if (row.end == SurfaceRowEnd::kNotCreated) return "-";
  return row.segments == 0 ? "surfaces" : std::to_string(row.segments);
}

std::string countText(const std::optional<std::uint64_t>& count) {
  return count ? std::to_string(*count) : "-";
}

}  // namespace

const char* patchBoundName(nurbs::PatchBound bound) {
  return bound == nurbs::PatchBound::kConvexHull ? "hull" : "box";
}

std::optional<nurbs::PatchBound> parsePatchBound(const std::string& name) {
  for (const nurbs::PatchBound bound : {nurbs::PatchBound::kConvexHull, nurbs::PatchBound::kBox}) {
    if (name == patchBoundName(bound)) return bound;
  }
  return std::nullopt;
}

std::string SeedDistanceRow::label() const {
  return std::string(patchBoundName(bound)) + (descent ? " + descent" : " (seed)");
}

Result<SurfaceRun> runSurfaces(const SurfaceRunRequest& request) {
  Result<std::vector<NamedSurface>> surfaces = loadSurfaces(request.file);
  if (!surfaces.ok()) return surfaces.status();
  const NamedSurface* a = find(surfaces.value(), request.a, 0);
  const NamedSurface* b = find(surfaces.value(), request.b, 1);
  if (a == nullptr || b == nullptr) {
    return Status(StatusCode::kInvalidArgument, request.file + ": no surface named '" +
                                                    (a == nullptr ? request.a : request.b) +
                                                    "' (or fewer than two surfaces)");
  }
  SurfaceRun run;
  run.file = request.file;
  run.a = a->name;
  run.b = b->name;
  run.model_size = modelSize(a->surface, b->surface);
  run.tolerance = request.tolerance > 0.0 ? request.tolerance : 1e-6 * run.model_size;
  run.seed = seedRows(request, *a, *b, run.tolerance);
  for (const SeedDistanceRow& row : run.seed) {
    const nurbs::SurfaceDistance& d = row.distance;
    if (d.converged &&
        (!run.reference || d.upper - d.lower < run.reference->upper - run.reference->lower))
      run.reference = d;
  }
  if (request.backends.empty()) return run;

  // The backends are judged against a tighter certified distance than the seed rows ask for.
  run.backends_asked = true;
  nurbs::SurfaceDistanceOptions reference_options;
  reference_options.tolerance = 1e-10 * run.model_size;
  reference_options.max_pairs = 5'000'000;
  const nurbs::SurfaceDistance tight =
      nurbs::minimumDistance(a->surface, b->surface, reference_options);
  if (tight.converged) run.reference = tight;
  if (!run.reference) {
    return Status(StatusCode::kUnsupported,
                  "no bound converged: no certified distance to measure errors against");
  }
  const double truth = 0.5 * (run.reference->lower + run.reference->upper);
  run.backends = backendRows(request, *a, *b, run.tolerance, truth);
  return run;
}

std::string surfaceRunText(const SurfaceRun& run, bool levels) {
  std::string text = run.a + " against " + run.b + " (" + run.file + "): model size " +
                     formatNumber("%.4g", run.model_size) + ", tolerance " +
                     formatNumber("%.3g", run.tolerance) + "\n";
  std::vector<std::vector<std::string>> rows;
  std::vector<std::vector<std::string>> level_rows;
  for (const SeedDistanceRow& row : run.seed) {
    const nurbs::SurfaceDistance& d = row.distance;
    rows.push_back({row.label(), formatNumber("%.12g", d.lower), formatNumber("%.12g", d.upper),
                    formatNumber("%.3g", d.upper - d.lower), d.converged ? "yes" : "no",
                    std::to_string(d.pairs_bounded), std::to_string(d.pairs_opened),
                    std::to_string(d.levels.size()), formatNumber("%.3f", row.median_ms)});
    for (std::size_t level = 0; level < d.levels.size(); ++level) {
      const nurbs::LevelWork& w = d.levels[level];
      level_rows.push_back({row.label(), std::to_string(level), std::to_string(w.pairs_bounded),
                            std::to_string(w.pairs_opened), formatNumber("%.3f", w.seconds * 1e3)});
    }
  }
  if (!run.seed.empty()) {
    text += formatTextTable({"bound", "lower", "upper", "gap", "converged", "pairs bounded",
                             "pairs opened", "levels", "median ms"},
                            rows, 1);
  }
  if (levels) {
    text +=
        "\nWork per subdivision level:\n" +
        formatTextTable({"bound", "level", "pairs bounded", "pairs opened", "ms"}, level_rows, 2);
  }
  if (!run.backends_asked || !run.reference) return text;

  std::vector<std::vector<std::string>> backend_rows;
  std::string failures;
  for (const SurfaceBackendRow& row : run.backends) {
    if (row.end != SurfaceRowEnd::kOk) {
      backend_rows.push_back({row.backend, shapeText(row), "-", "-", "-", "-", "-", "-", "-", "-",
                              row.end == SurfaceRowEnd::kNoDistance ? "skipped" : "failed"});
      failures += "  " + row.backend;
      if (row.end == SurfaceRowEnd::kFailed) failures += " (" + shapeText(row) + ")";
      failures += ": " + row.failure + "\n";
      continue;
    }
    backend_rows.push_back(
        {row.backend, shapeText(row), row.segments == 0 ? "-" : std::to_string(row.triangles),
         formatNumber("%.12g", row.distance), formatNumber("%.3g", row.error),
         formatNumber("%.3g", std::abs(row.error) / run.model_size),
         formatNumber("%.1f", row.median_us), countText(row.bv_tests),
         countText(row.primitive_tests), formatNumber("%.2f", row.build_ms), "ok"});
  }
  const nurbs::SurfaceDistance& reference = *run.reference;
  text +=
      "\nBackends (surfaces, or tessellations of segments x segments per surface), error "
      "against the certified distance " +
      formatNumber("%.15g", 0.5 * (reference.lower + reference.upper)) + " (+- " +
      formatNumber("%.2g", 0.5 * (reference.upper - reference.lower)) + "):\n" +
      formatTextTable({"backend", "shape", "triangles", "distance", "error", "error / size",
                       "median us", "bv tests", "prim tests", "build ms", "status"},
                      backend_rows, 2) +
      failures;
  return text;
}

}  // namespace collido
