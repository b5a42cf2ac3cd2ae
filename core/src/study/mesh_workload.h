// `collido study a.obj b.obj`: mesh files given where scenes go become scenes of their own,
// built the way bunny_vs_bunny is, and written into the study folder for the user to edit and
// run again.
#pragma once

#include <string>
#include <vector>

#include <collido/status.h>

namespace collido::study {

/// Whether a study input names a mesh file rather than a scene (anything but .json).
bool isMeshInput(const std::string& path);

/// Writes two scenes of the meshes into `folder`: the first mesh fixed and every other one (a
/// copy of it, when only one is given) at seeded random poses whose bounding spheres overlap by
/// 30 to 90 percent ("<name>_overlap"), and in a close approach along an axis through first
/// contact, found by the exact oracle ("<name>_approach"); each asks boolean, all pairs and
/// distance of the first against every other. A scene file already there with other content
/// (the user's edit of an earlier run's) is kept, not overwritten. Fails naming a mesh that does
/// not load.
struct MeshWorkloadScene {
  std::string path;
  bool kept = false;  ///< an edited file was found and kept
};
Result<std::vector<MeshWorkloadScene>> writeMeshWorkload(const std::vector<std::string>& meshes,
                                                         const std::string& folder);

}  // namespace collido::study
