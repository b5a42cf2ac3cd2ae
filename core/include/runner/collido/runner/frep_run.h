#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <collido/frep/collision.h>
#include <collido/runner/runner.h>
#include <collido/scene/frep_file.h>
#include <collido/status.h>

namespace collido {

/// What one run on an FRep file asks: the seed method's precision and the mesh backends to
/// measure, on polygonizations, against its guaranteed answers.
struct FrepRunRequest {
  double precision = 0.0;  ///< the octree's cell size; 0: the file's
  int repetitions = 3;     ///< timed calls after one untimed call, per answer
  bool seed_rows = true;   ///< false: the seed's answers once, untimed, as the reference only
  std::vector<BackendSpec> backends;
  std::vector<int> resolutions{16, 32, 64};  ///< grid cells along each solid's longest side
};

/// The seed method's answer for one pair at one frame, with its work and median time.
struct FrepSeedAnswer {
  double time = 0.0;
  std::string pair;      ///< "a / b"
  std::string expected;  ///< the file's expected verdict, or empty
  frep::CollisionResult result;
  double median_ms = 0.0;

  bool asExpected() const;
};

/// How a mesh backend's boolean answer compares with the guaranteed one.
enum class MeshAnswerOutcome {
  kAgrees,
  kMissedOverlap,    ///< the solids collide; the meshes were reported apart
  kFalseContact,     ///< the solids are separated; the meshes were reported in contact
  kWithinPrecision,  ///< the solids touch within the precision: either answer is right
  kNoReference,      ///< the seed could not decide
};

/// "agrees", "missed overlap", "false contact", "within precision", "no reference".
const char* meshAnswerOutcomeName(MeshAnswerOutcome outcome);
std::optional<MeshAnswerOutcome> parseMeshAnswerOutcome(const std::string& name);

/// A mesh backend's answer for one pair at one frame, against the guaranteed one.
struct FrepMeshAnswer {
  double time = 0.0;
  std::string pair;
  bool intersecting = false;
  MeshAnswerOutcome outcome = MeshAnswerOutcome::kAgrees;
  double query_us = 0.0;
  double ms_with_meshing = 0.0;  ///< polygonization and build where a mesh changed, and query
};

/// A mesh backend at one polygonization resolution, over every frame and pair.
struct FrepBackendRow {
  std::string backend;
  int resolution = 0;
  bool created = true;
  std::string failure;  ///< empty: every answer came
  std::size_t triangles_first_pair = 0;
  std::vector<FrepMeshAnswer> answers;
  double ms_per_query_with_meshing = 0.0;

  std::size_t count(MeshAnswerOutcome outcome) const;
};

/// An FRep run: the seed's guaranteed answers and each backend's rows.
struct FrepRun {
  std::string file;
  std::string name;
  double precision = 0.0;
  std::vector<FrepSeedAnswer> seed;  ///< per frame, then pair; empty unless seed rows were asked
  std::vector<FrepBackendRow> comparators;
  std::size_t unexpected = 0;  ///< seed answers that differ from the file's expected ones
  /// The preview picture as a data URI ("data:image/png;base64,..."), where one was made.
  std::string preview_png;
};

/// Runs the seed method, then each backend on polygonizations of the solids, every answer timed
/// by timeRepeated. `path` names the file in the run and its errors. Fails with kInvalidArgument
/// on a solid the seed refuses, and with kInternal when the interval evaluation fails.
Result<FrepRun> runFrep(const FrepFile& file, const std::string& path,
                        const FrepRunRequest& request);

/// The run as `collido frep --json` writes it (what the dashboard reads).
nlohmann::json frepRunJson(const FrepRun& run);

/// Reads what frepRunJson wrote (a seed answer keeps its verdict, witness and work, not its
/// touching cells); errors name the field.
Result<FrepRun> frepRunFromJson(const nlohmann::json& json);

/// The run's text tables: the seed's answers (when asked) and the backends' rows.
std::string frepRunText(const FrepRun& run);

/// A PNG picture of the file's solids at one frame (the asked time; else the first frame with a
/// collision, with its witness as a red dot; else the middle frame).
Result<std::string> frepPreviewPng(const FrepFile& file, const FrepRun& run,
                                   std::optional<double> time, int width, int height);

}  // namespace collido
