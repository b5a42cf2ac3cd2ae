#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <collido/nurbs/surface_distance.h>
#include <collido/runner/runner.h>
#include <collido/status.h>

namespace collido {

/// What one run on a surface file asks: the two surfaces, the seed method's settings, and the
/// backends to measure against its certified distance.
struct SurfaceRunRequest {
  std::string file;
  std::string a;  ///< empty: the file's first surface
  std::string b;  ///< empty: the file's second surface
  std::vector<nurbs::PatchBound> bounds{nurbs::PatchBound::kConvexHull, nurbs::PatchBound::kBox};
  double tolerance = 0.0;  ///< 0: 1e-6 of the model's size
  bool seed_rows = true;   ///< false: the backends only, against the certified reference
  bool seed_only = false;  ///< the seed method as published only (no descent)
  int repetitions = 5;     ///< timed calls after one untimed call, per row
  std::size_t max_pairs = 200'000;
  /// Surface backends answer on the surfaces; mesh backends on each tessellation.
  std::vector<BackendSpec> backends;
  std::vector<int> tessellations{8, 32, 128};  ///< segments per parameter
};

/// "hull" or "box".
const char* patchBoundName(nurbs::PatchBound bound);
std::optional<nurbs::PatchBound> parsePatchBound(const std::string& name);

/// One setting of the seed method: its certified interval, its work and its median time.
struct SeedDistanceRow {
  nurbs::PatchBound bound = nurbs::PatchBound::kConvexHull;
  bool descent = false;
  nurbs::SurfaceDistance distance;
  double median_ms = 0.0;

  std::string label() const;  ///< "hull (seed)", "box + descent", ...
};

/// How a backend's row ended.
enum class SurfaceRowEnd {
  kOk,
  kNotCreated,  ///< the backend could not be created
  kNoDistance,  ///< it does not answer distance queries
  kFailed,      ///< a build or a query failed
};

/// One backend on the surfaces (segments 0) or on one tessellation.
struct SurfaceBackendRow {
  std::string backend;
  int segments = 0;
  SurfaceRowEnd end = SurfaceRowEnd::kOk;
  std::string failure;        ///< why, unless kOk
  std::size_t triangles = 0;  ///< both tessellations
  double distance = 0.0;
  double error = 0.0;  ///< distance - the certified midpoint
  double median_us = 0.0;
  double build_ms = 0.0;  ///< both models, tessellation included
  /// Bounding-volume and primitive tests of one query, where the backend counts them.
  std::optional<std::uint64_t> bv_tests;
  std::optional<std::uint64_t> primitive_tests;
};

/// A surface run: the seed method's rows, the certified reference and the backends' rows.
struct SurfaceRun {
  std::string file;
  std::string a;
  std::string b;
  double model_size = 0.0;  ///< the diagonal of both control nets' bounds
  double tolerance = 0.0;
  std::vector<SeedDistanceRow> seed;
  /// The tightest converged interval: the backends' reference. Absent when nothing converged.
  std::optional<nurbs::SurfaceDistance> reference;
  std::vector<SurfaceBackendRow> backends;
  bool backends_asked = false;
};

/// Runs the seed method and the backends on a surface file, each timed by timeRepeated. Fails
/// with kInvalidArgument on an unreadable file or an unknown surface name, and with kUnsupported
/// when backends are asked and no bound converged: no certified distance to judge them by.
Result<SurfaceRun> runSurfaces(const SurfaceRunRequest& request);

/// The run as `collido surface-distance --json` writes it (what the dashboard reads).
nlohmann::json surfaceRunJson(const SurfaceRun& run);

/// Reads what surfaceRunJson wrote (a backend row that is not "ok" reads as kFailed); errors
/// name the field.
Result<SurfaceRun> surfaceRunFromJson(const nlohmann::json& json);

/// The run's text tables: the seed rows (unless none), the work per level when asked, and the
/// backends' rows with their failures.
std::string surfaceRunText(const SurfaceRun& run, bool levels);

}  // namespace collido
