#pragma once

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <collido/frep/solid.h>
#include <collido/status.h>

namespace collido {

/// A named FRep solid from a file; `at(time)` builds it with its animated parameters at that
/// time (checked at load for every frame time, so it does not fail for those).
struct FrepSolidEntry {
  std::string name;
  bool animated = false;
  /// About how many node evaluations one evaluation of the solid costs (its nodes; sweeps and
  /// projections once per piece): what an octree cell or a grid sample costs, relatively.
  double evaluation_cost = 0.0;
  std::function<frep::SolidPtr(double time)> at;
};

/// An FRep case file: solids, the pairs to test, the frame times and the precision.
struct FrepFile {
  std::string name;
  std::vector<FrepSolidEntry> solids;
  std::vector<std::pair<std::size_t, std::size_t>> pairs;  ///< indices into solids
  std::vector<double> times;                               ///< frame times (seconds)
  double precision = 1e-3;                                 ///< the collision test's ε
  /// The answer every frame of every pair is expected to give ("colliding", "separated",
  /// "touching"), per pair, when the file states it; empty otherwise.
  std::vector<std::string> expected;
};

/// Reads an FRep file:
///   {"name": "...", "precision": 1e-3,
///    "frames": {"count": 12, "duration": 2.0},          (optional: one frame at time 0)
///    "solids": [{"name": "a", "solid": SOLID}, ...],
///    "pairs": [["a", "b", "colliding"?], ...]}          (optional: every pair)
/// SOLID is {"type": ..., ...} (see docs/frep.md). Errors name the file, the JSON path and the
/// problem.
Result<FrepFile> parseFrepFile(const std::string& text, const std::string& label);

/// parseFrepFile on a file's contents; a missing or unreadable file is an error naming it.
Result<FrepFile> loadFrepFile(const std::string& path);

}  // namespace collido
