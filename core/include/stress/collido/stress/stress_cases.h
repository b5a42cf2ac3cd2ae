#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <collido/geometry.h>
#include <collido/mesh/triangle_mesh.h>
#include <collido/status.h>

namespace collido::stress {

/// The robustness categories of the stress suite. Their names (categoryName) are part of the
/// contract: scenes, the study's robustness matrix and the tests label cases with them.
enum class Category {
  kCoplanar,       ///< "coplanar": coplanar overlapping and coplanar touching triangles
  kTouching,       ///< "touching": edge-edge, vertex-face, face-face ... exactly touching
  kNearTouching,   ///< "near_touching": gaps of 1e-3 down to 1e-15, on both sides of contact
  kDegenerate,     ///< "degenerate": slivers, zero-area and collinear triangles, needles
  kFarFromOrigin,  ///< "far_from_origin": contacts translated to 1e3 ... 1e8
  kScaled,         ///< "scaled": contacts scaled by 1e-6 ... 1e6
  kTinyFeatures,   ///< "tiny_features": a feature 1e-6 of a big object's size makes the contact
  kAxisRotations,  ///< "axis_rotations": rotations at and near 90° and 180°, near-parallel edges
  kMeshDefects,    ///< "mesh_defects": meshes with cracks, duplicate vertices, non-manifold edges
  kDistance,       ///< "distance": touching and nearly touching pairs asked for their distance
};

/// Every category, in the order above.
const std::vector<Category>& allCategories();

/// The category's stable lower-case name ("near_touching", ...).
const char* categoryName(Category category);

/// The category named by categoryName's text, or empty for any other text.
std::optional<Category> parseCategory(const std::string& name);

/// The severities a category accepts and what a severity means for it.
struct SeverityRange {
  int min = 0;
  int max = 0;
  const char* meaning = "";  ///< one line for people, e.g. "relative gap 10^-severity"
};

/// The accepted severities of `category`.
SeverityRange severityRange(Category category);

/// A spread of severities covering the category's interesting range, used when a scene gives
/// none (and by the tests).
std::vector<int> defaultSeverities(Category category);

/// What a generator aimed at. The truth is always the exact oracle's; when `exact` is set, the
/// construction guarantees the aim in exact arithmetic on the very doubles of the case (the
/// stress tests hold the generators to it), otherwise rounding in building the case (a generic
/// rotation, a product of poses) may have moved it across contact.
struct Aim {
  bool contact = true;  ///< touching or overlapping; false: apart
  bool exact = false;
};

/// One stress case: two small meshes, each with a rigid pose, asked whether (and where) they
/// intersect.
struct StressCase {
  /// "<category>/s<severity>/<index>/<kind>", unique within a category; scenes name their objects
  /// and queries after it.
  std::string name;
  std::string kind;  ///< the configuration aimed at, e.g. "vertex_face", "edge_edge_parallel"
  Category category = Category::kTouching;
  int severity = 0;
  std::size_t index = 0;  ///< position among the cases of its severity
  std::shared_ptr<const TriangleMesh> a;
  std::shared_ptr<const TriangleMesh> b;
  Pose pose_a = Pose::Identity();
  Pose pose_b = Pose::Identity();
  Aim aim;
};

/// A mesh given to a generator, with the name cases call it by.
struct NamedMesh {
  std::string name;  ///< e.g. "truck_nonmanifold"
  std::shared_ptr<const TriangleMesh> mesh;
};

/// Input some categories need besides the seed.
struct StressInputs {
  /// mesh_defects: the meshes with defects to pose against each other and against generated
  /// shapes (at least one). Other categories ignore it.
  std::vector<NamedMesh> defect_meshes;
};

/// The cases of `category` at `severity`: `count` cases, case i depending only on (seed,
/// category, severity, i), so asking for more cases keeps the first ones. Each category cycles
/// through its kinds of configuration and mixes cases aimed at contact with cases aimed apart.
/// Fails (naming the problem) when the severity is out of range or mesh_defects has no meshes.
Result<std::vector<StressCase>> generateStressCases(Category category, int severity,
                                                    std::size_t count, std::uint64_t seed,
                                                    const StressInputs& inputs = {});

}  // namespace collido::stress
