#pragma once

// Building blocks of the stress generators: a portable seeded sampler, small meshes built from
// exact coordinates, exact and generic rotations, and the ways a configuration is posed.
//
// Every configuration is first built in one common frame (the "contact frame"): object A below
// the plane z = 1, object B above it, the contact (when aimed at) on that plane. Placing it then
// gives each object its model coordinates and pose.
#include <cmath>
#include <cstdint>
#include <vector>

#include <Eigen/Geometry>

#include <collido/geometry.h>
#include <collido/mesh/triangle_mesh.h>
#include <collido/random/portable_random.h>

namespace collido::stress::detail {

/// PortableRandom with the draws the generators need besides it.
class Rng : public PortableRandom {
 public:
  explicit Rng(std::uint64_t seed) : PortableRandom(seed) {}

  /// An integer in [low, high].
  int integer(int low, int high) {
    return low + static_cast<int>(bits() % static_cast<std::uint64_t>(high - low + 1));
  }
  bool coin() { return (bits() >> 63) != 0; }
  /// A multiple of 1 / denominator in [low, high]: exact in double, and sums of a few of them
  /// stay exact.
  double dyadic(double low, double high, int denominator) {
    const int first = static_cast<int>(std::ceil(low * denominator));
    const int last = static_cast<int>(std::floor(high * denominator));
    return static_cast<double>(integer(first, last)) / denominator;
  }
  /// Three draws of dyadic(-bound, bound, denominator), x first.
  Eigen::Vector3d dyadicVector(double bound, int denominator);
  /// Three draws of uniform(low, high), x first.
  Eigen::Vector3d uniformVector(double low, double high);
};

/// Two meshes a generator built for one case, and whether it aimed at contact.
struct GeneratedPair {
  const char* kind = "";
  TriangleMesh a;
  TriangleMesh b;
  bool contact = true;
};

/// Collects vertices and triangles.
class MeshBuilder {
 public:
  int vertex(const Eigen::Vector3d& p);
  void triangle(int i, int j, int k);
  /// Appends a whole mesh (its indices shifted).
  void append(const TriangleMesh& mesh);
  TriangleMesh build() const;

 private:
  std::vector<Eigen::Vector3d> vertices_;
  std::vector<Eigen::Vector3i> triangles_;
};

/// Turns every triangle of a convex closed mesh to face away from the centre of its vertices,
/// so the meshes keep the counter-clockwise-from-outside convention whatever way they were built.
void orientOutward(TriangleMesh& mesh);

/// The axis-aligned box [lo, hi]: 8 vertices, 12 triangles.
TriangleMesh boxMesh(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi);

/// A triangular prism (a wedge) whose ridge runs from centre - half_length * d to centre +
/// half_length * d at height centre.z(); its base (at base_z, above or below the ridge) is that
/// segment widened by ±half_width * n, n = (-d.y, d.x, 0). `d` is horizontal, not necessarily of
/// unit length, so dyadic inputs give dyadic vertices. 6 vertices, 8 triangles.
TriangleMesh ridgePrism(const Eigen::Vector3d& centre, const Eigen::Vector2d& d, double half_length,
                        double half_width, double base_z);

/// A pyramid with its apex at `apex` and a square base of half-width `half_width` centred below
/// (or above) it at height base_z. 5 vertices, 6 triangles.
TriangleMesh pyramid(const Eigen::Vector3d& apex, double half_width, double base_z);

/// A flat grid [x0, x1] × [y0, y1] at height z, cells_x × cells_y cells of two triangles each;
/// an open sheet facing +z.
TriangleMesh gridPlate(double x0, double x1, double y0, double y1, double z, int cells_x,
                       int cells_y);

/// One triangle (possibly degenerate, as given).
TriangleMesh singleTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& q,
                            const Eigen::Vector3d& r);

/// The 24 rotations whose matrices are signed permutations (entries 0 and ±1, so they rotate
/// exactly in double); index 0 is the identity.
Eigen::Matrix3d signedPermutation(int index);

/// The rotation by `angle` about coordinate axis `axis` (0 = x, 1 = y, 2 = z) with that axis's
/// row and column exactly the unit vector: the coordinate along the axis is kept exactly whatever
/// the angle, so a contact across a plane normal to it stays exact.
Eigen::Matrix3d rotationAbout(int axis, double angle);

/// How a configuration built in the contact frame is posed.
enum class Placement {
  kIdentity,        ///< both poses identity: model = contact-frame coordinates
  kExactShared,     ///< one signed-permutation rotation and dyadic translation for both
  kExactDistinct,   ///< a different signed permutation for each object, no translation, and
                    ///< model coordinates rotated back exactly
  kGenericShared,   ///< one generic rotation and translation for both: the exact relation of the
                    ///< two objects is kept (the oracle applies the same map to both), but every
                    ///< world coordinate a backend computes is rounded
  kGenericDistinct  ///< A at a generic pose, B at that pose times an exact motion, the product
                    ///< rounded: the relation is kept only up to that rounding
};

/// Two meshes with their poses.
struct Placed {
  TriangleMesh a;
  TriangleMesh b;
  Pose pose_a = Pose::Identity();
  Pose pose_b = Pose::Identity();
  bool exact = true;  ///< the contact-frame relation of A and B holds exactly in the oracle's world
};

/// Poses the contact-frame meshes `a` and `b` as `placement` says.
Placed place(Placement placement, TriangleMesh a, TriangleMesh b, Rng& rng);

/// Both meshes at one pose (kept exactly: the oracle applies the same map to both).
Placed placeShared(TriangleMesh a, TriangleMesh b, const Pose& pose);

/// A at `pose_a`, B at pose_a · M for a seeded exact motion M (a signed permutation and a dyadic
/// translation), B's model being its contact-frame coordinates undone by M: the product pose_a · M
/// is rounded, so the relation holds only up to that rounding (Placed::exact is false).
Placed placeDistinct(TriangleMesh a, TriangleMesh b, const Pose& pose_a, Rng& rng);

/// A pose from a rotation and a translation.
Pose makePose(const Eigen::Matrix3d& rotation, const Eigen::Vector3d& translation);

/// Applies an affine map to every vertex (rounded to double as computed).
void transformVertices(TriangleMesh& mesh, const Eigen::Matrix3d& linear,
                       const Eigen::Vector3d& translation);

}  // namespace collido::stress::detail
