// Solved constraint blocks kept on disk, so the processes of one study (its workers, the views'
// backends, the conformance kit's plugins) solve a scene's placement once instead of once each:
// the solve calls the exact distance oracle many times and took 2 to 6 s per load of the
// bundled constraint scenes.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <collido/geometry.h>
#include <collido/mesh/triangle_mesh.h>

namespace collido::scene_reading {

/// What a solve produced, in the problem's orders (bodies, variables, clearance constraints).
struct StoredSolve {
  std::vector<Pose> body_poses;
  std::vector<double> variables;
  std::vector<double> clearances;  ///< the exact oracle's distances after the solve
  int equations = 0;
  int parameters = 0;
  int iterations = 0;
  double change = 0.0;
};

/// Everything a solve depends on: the constraint block as written, the length scale's default,
/// and each body's pose and frame-0 mesh before the solve. Equal keys: the same solve.
class PlacementKey {
 public:
  PlacementKey(const std::string& block_text, double largest_radius);
  void addBody(const Pose& pose, const TriangleMesh& mesh);
  /// The file of this solve in `directory`: "<directory>/<32 hex digits>.json".
  std::string path(const std::string& directory) const;

 private:
  std::string bytes_;
};

/// The solve stored at `path`, when there is one of these sizes; anything missing, unreadable
/// or of other sizes gives none (the caller solves afresh and stores the result).
std::optional<StoredSolve> readStoredSolve(const std::string& path, std::size_t bodies,
                                           std::size_t variables, std::size_t clearances);

/// Stores `solve` at `path` (through a temporary file and a rename, so a concurrent reader sees
/// a whole file or none); a store that cannot be written costs time only, so failures are
/// ignored.
void writeStoredSolve(const std::string& path, const StoredSolve& solve);

}  // namespace collido::scene_reading
