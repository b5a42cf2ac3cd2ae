#pragma once

#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include <Eigen/Core>

#include <collido/obbtree/triangle_list.h>

namespace collido::obbtree {
/// An oriented box: the points center + axes * u with |u_k| <= half_extents[k].
struct OrientedBox {
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();  ///< orthonormal, right-handed columns,
                                                       ///< sorted by decreasing spread
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  Eigen::Vector3d half_extents = Eigen::Vector3d::Zero();
};

/// Fits boxes to sets of triangles of one mesh, as in the dissertation: m = the centre of mass
/// of the triangles (area-weighted centroid; the mean of the centroids when the area is zero);
/// C = the covariance of their vertices about m, each distinct vertex counted once (counting a
/// vertex once per triangle would weight it by its valence and tilt the axes of even a cuboid);
/// axes = the normalised eigenvectors of C, by decreasing extent; extents = the extreme vertices
/// along each axis, widened by a few units of rounding so the box contains every vertex as
/// computed. Holds scratch space for the distinct-vertex pass, reused across calls.
class BoxFitter {
 public:
  explicit BoxFitter(std::size_t vertex_count) : stamp_(vertex_count, 0) {}

  /// The box of triangles order[0 .. count).
  OrientedBox fit(const Eigen::Ref<const Eigen::Matrix3Xd>& vertices,
                  const Eigen::Ref<const Eigen::Matrix3Xi>& triangles, const std::int32_t* order,
                  std::int32_t count);

  /// `box`, the last fit() of these triangles, or where one of their triangles' frames gives a
  /// clearly smaller box (surface), that box; a single triangle's box flush with its longest
  /// edge unless that is larger (box_frame_search.h).
  OrientedBox tighten(const OrientedBox& box, const Eigen::Ref<const Eigen::Matrix3Xd>& vertices,
                      const Eigen::Ref<const Eigen::Matrix3Xi>& triangles,
                      const std::int32_t* order, std::int32_t count);

 private:
  std::vector<std::uint32_t> stamp_;  // stamp_[v] == epoch_: vertex v already counted
  std::uint32_t epoch_ = 0;
  // The last fit()'s distinct vertices about its mean, for tighten().
  std::vector<Eigen::Vector3d> frame_points_;
  Eigen::Vector3d frame_mean_ = Eigen::Vector3d::Zero();
  std::vector<Eigen::Vector3d> frame_triangles_;
  const std::int32_t* last_order_ = nullptr;  // the triangles of the last fit()
  std::int32_t last_count_ = 0;
};

/// One-off BoxFitter::fit.
OrientedBox fitBox(const Eigen::Ref<const Eigen::Matrix3Xd>& vertices,
                   const Eigen::Ref<const Eigen::Matrix3Xi>& triangles, const std::int32_t* order,
                   std::int32_t count);

/// Recomputes centre and extents of `box` over all columns of `triangles`, keeping its axes
/// (refit after the vertices moved).
void refitBoxExtents(OrientedBox& box, const Eigen::Ref<const Eigen::Matrix3Xd>& vertices,
                     const Eigen::Ref<const Eigen::Matrix3Xi>& triangles);

/// refitBoxExtents over the triangles `range` of `triangles`; `axis_defect`, when >= 0, is a
/// bound on axisDefect(box.axes) known ahead (a refit keeps the axes), else it is computed.
void refitBoxExtents(OrientedBox& box, const Eigen::Ref<const Eigen::Matrix3Xd>& vertices,
                     const TriangleList& triangles, TriangleRange range, double axis_defect = -1.0);

/// The vertices of a set of triangles, each once: indices [first, last) then [extra_first,
/// extra_last); at least one in all.
struct VertexSpan {
  const std::int32_t* first = nullptr;
  const std::int32_t* last = nullptr;
  const std::int32_t* extra_first = nullptr;
  const std::int32_t* extra_last = nullptr;
};

/// refitBoxExtents over the triangles whose vertices `span` lists: the same box (up to the
/// rounding of another reference point), each vertex projected once; `axis_defect` is a bound
/// on axisDefect(box.axes) known ahead (a refit keeps the axes), saving its computation.
void refitBoxExtents(OrientedBox& box, const Eigen::Ref<const Eigen::Matrix3Xd>& vertices,
                     const VertexSpan& span, double axis_defect);

/// An oriented box in 26 bytes instead of 120. The centre is rounded to float. The axes are a
/// unit quaternion kept to 15 bits a component (its largest component left out and recovered
/// from the unit norm), decoded in double by expandBox. The half extents were measured on the
/// decoded axes about the stored centre when the box was made (compactBox), widened as a fitted
/// box's are, and rounded up to whole units of 2^-18 of the largest (a shared binary exponent
/// and three 18-bit counts). So the box the query sees — expandBox's — contains every vertex it
/// was made for, exactly as a double box does, and is looser than the fitted box only by about
/// 1e-4 of its size (the rounded axes). Packed to 2-byte alignment so that a CompactNode holds
/// it, a leaf's triangle count and a link in 32 bytes.
#pragma pack(push, 2)
struct CompactBox {
  float center[3] = {0.0F, 0.0F, 0.0F};
  /// The half extents, packed (oriented_box.cpp, encodeExtents); read them with halfExtent().
  std::uint32_t half_extents[2] = {0, 0};
  /// The quaternion, packed (oriented_box.cpp, encodeRotation); the default is the identity.
  std::uint16_t rotation[3] = {32769, 32769, 32768};
};
#pragma pack(pop)

/// The layout of CompactBox::half_extents, as one 64-bit word (half_extents[0] its low half):
/// three 18-bit counts (bits 0-17, 18-35, 36-53) of a unit 2^e shared by the three, and
/// e + kExtentBias in bits 54-61; kExtentInfinite there stands for infinite extents.
namespace compact_box_layout {
inline constexpr int kExtentBits = 18;
inline constexpr std::uint64_t kExtentMask = (std::uint64_t{1} << kExtentBits) - 1;
inline constexpr int kExtentBias = 168;      // e from -168 (about 3e-51) ...
inline constexpr int kExtentInfinite = 255;  // ... to 86 (counts up to about 2e31)

/// 2^e for a normal exponent (-1022 <= e <= 1023), made from its bits: exact, and no library
/// call on the refit's and the query's paths.
inline double powerOfTwo(int e) {
  const std::uint64_t bits = static_cast<std::uint64_t>(e + 1023) << 52U;
  double value = 0.0;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}
}  // namespace compact_box_layout

/// Half extent k of a compact box, as the query uses it (inline: the descent reads the sizes
/// of the boxes it splits).
inline double halfExtent(const CompactBox& box, int k) {
  using namespace compact_box_layout;
  const std::uint64_t packed =
      box.half_extents[0] | (static_cast<std::uint64_t>(box.half_extents[1]) << 32U);
  const auto biased = static_cast<int>(packed >> (3 * kExtentBits));
  if (biased == kExtentInfinite) return std::numeric_limits<double>::infinity();
  return static_cast<double>((packed >> (kExtentBits * k)) & kExtentMask) *
         powerOfTwo(biased - kExtentBias);
}

/// The box a compact box stands for: axes decoded from the quaternion (normalised in double;
/// the one computation used at build, refit and query time), centre and extents as stored.
OrientedBox expandBox(const CompactBox& box);

/// `box` in single precision, containing every vertex of `triangles` (see CompactBox).
CompactBox compactBox(const OrientedBox& box, const Eigen::Ref<const Eigen::Matrix3Xd>& vertices,
                      const Eigen::Ref<const Eigen::Matrix3Xi>& triangles);

/// compactBox over the triangles `range` of `triangles`.
CompactBox compactBox(const OrientedBox& box, const Eigen::Ref<const Eigen::Matrix3Xd>& vertices,
                      const TriangleList& triangles, TriangleRange range);

/// Refit of a compact box after the vertices moved: keeps its axes (the stored quaternion),
/// recomputes centre and extents over all columns of `triangles`.
void refitCompactBox(CompactBox& box, const Eigen::Ref<const Eigen::Matrix3Xd>& vertices,
                     const Eigen::Ref<const Eigen::Matrix3Xi>& triangles);

/// refitCompactBox over the triangles `range` of `triangles`; `axis_defect` as for
/// refitBoxExtents, on the decoded axes.
void refitCompactBox(CompactBox& box, const Eigen::Ref<const Eigen::Matrix3Xd>& vertices,
                     const TriangleList& triangles, TriangleRange range, double axis_defect = -1.0);

/// refitCompactBox over the vertices `span` lists, with a known bound on the decoded axes'
/// defect (see refitBoxExtents).
void refitCompactBox(CompactBox& box, const Eigen::Ref<const Eigen::Matrix3Xd>& vertices,
                     const VertexSpan& span, double axis_defect);

/// A bound on how far `axes` is from the nearest orthonormal matrix Q (the spectral norm of
/// axes - Q): 3 max|axes^T axes - I| plus the rounding of that product. The box a query reasons
/// about has the axes Q; fitted and compact boxes are widened by this defect so that it still
/// contains every vertex. Infinite for non-finite axes.
double axisDefect(const Eigen::Matrix3d& axes);

/// Whether `point` lies in `box` as computed in double precision (no tolerance).
bool boxContains(const OrientedBox& box, const Eigen::Vector3d& point);

}  // namespace collido::obbtree
