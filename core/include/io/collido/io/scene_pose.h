// The one way a pose is written into a scene file (scenes/README.md, "Poses"), shared by every
// writer that builds scene JSON: the URDF import, constraint placement and the study's scenes of
// mesh files. (Collidoscope::record writes the same text without a JSON library: it must drop
// into an application with the standard library and Eigen only; both are read back bit for bit
// in their tests, scene_pose_test.cpp and recorded_scene_test.cpp.)
#pragma once

#include <nlohmann/json.hpp>

#include <collido/geometry.h>

namespace collido::io {

/// {"translation": [x, y, z], "rotation": {"matrix": [[...], [...], [...]]}}, rows of the rotation
/// as written, read back to the same bits; a pose that does not turn (its rotation exactly the
/// identity) is written as its translation alone.
nlohmann::json scenePoseJson(const Pose& pose);

}  // namespace collido::io
