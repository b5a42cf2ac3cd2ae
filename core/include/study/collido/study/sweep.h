#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <collido/status.h>

namespace collido::study {

/// What each object is built for and what each frame asks: the scene's own queries; those, and
/// only the pairs that changed since the frame before (RunOptions::reuse_unchanged); or every
/// query kind the backend answers, every pair every frame (the cold figure that shows what the
/// other two save).
enum class NeedsMode { kDeclared, kChanged, kEvery };

/// "declared", "changed" or "every".
const char* needsModeName(NeedsMode mode);
std::optional<NeedsMode> parseNeedsMode(const std::string& name);

/// One backend variant of a sweep and the option values to try; every combination of the
/// listed values is one setting.
struct SweepBackend {
  std::string variant;
  std::vector<std::pair<std::string, std::vector<std::string>>> options;  ///< name, values
  /// Only these scenes (by name); empty: every scene. For settings that matter only to some
  /// scenes (a rebuild-on-update option on the deforming ones).
  std::vector<std::string> scenes;
  /// A backend that only some builds have (a licence opt-in, an optional library): a study
  /// without its plugin leaves it out with a warning instead of refusing the sweep.
  bool optional = false;

  /// Every setting as backend text: "variant" or "variant[a=1;b=x]", options in file order.
  std::vector<std::string> settings() const;
};

/// The backend settings and grid sizes for a study's NURBS surface files (grid: tessellations,
/// segments per side) or FRep files (grid: polygonization cells along the longest side).
struct SweepComparison {
  std::vector<std::string> backends;  ///< backend texts; empty: the study's mesh settings
  std::vector<int> grid;
};

/// The settings a study sweeps (format: docs/STUDY.md). Every list has at least one entry.
/// Which backends the field table ("ours against the field", field_table.h) compares: the
/// family whose fastest exact setting each row shows, and the setting it meets first, its
/// method's direct peer. A study setting: the sweep's "field", kept in plan.json.
struct FieldSides {
  std::string ours = "obbtree";  ///< a backend family (a variant's name before ':')
  std::string peer = "fcl:obb";  ///< a variant
};

struct Sweep {
  std::vector<SweepBackend> backends;    ///< empty: every variant found (or --backends)
  std::vector<double> resolutions{1.0};  ///< for scenes with no entry below
  /// Per scene name: its own resolutions (a sweep may size one scene family for scaling).
  std::map<std::string, std::vector<double>> scene_resolutions;
  std::vector<NeedsMode> needs{NeedsMode::kDeclared};  ///< for scenes with no entry below
  /// Per scene name: its own needs modes (a sweep may compare them on a few scenes only).
  std::map<std::string, std::vector<NeedsMode>> scene_needs;
  /// Caps on all-pairs and contacts answers (max_pairs / max_contacts); 0 keeps the scene's.
  std::vector<std::uint64_t> limits{0};
  std::optional<int> repetitions;  ///< timed calls per frame and query in each round
  /// Timing rounds: each mesh combination runs this many times, each in a worker process of its
  /// own, in a seeded random order across the study (rounds.h); unset: --rounds, else 1.
  std::optional<int> rounds;
  /// Seconds the study may spend on extra rounds for combinations with unstable rows, after the
  /// planned ones; unset: --adaptive-seconds, else 0 (none).
  std::optional<double> adaptive_s;
  std::optional<double> timeout_s;
  /// "repeated" or "cycled" (TimingProtocol); unset: --protocol, else repeated.
  std::optional<std::string> protocol;
  /// "surfaces" and "frep": how the study's surface and FRep files are compared.
  SweepComparison surfaces{{}, {8, 32, 128}};
  SweepComparison frep{{}, {16, 32, 64}};
  FieldSides field;  ///< "field": {"ours": family, "peer": variant}

  /// The resolutions to run `scene` at.
  const std::vector<double>& resolutionsOf(const std::string& scene) const;
  /// The needs modes to run `scene` with.
  const std::vector<NeedsMode>& needsOf(const std::string& scene) const;
};

/// Reads a sweep; every error names `label`, the JSON path and the problem.
Result<Sweep> parseSweep(const std::string& text, const std::string& label);
Result<Sweep> loadSweep(const std::string& path);

}  // namespace collido::study
