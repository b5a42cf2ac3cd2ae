#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include <collido/scene/scene.h>

namespace collido {

/// The broad phase shared by every backend on a group query (a pile of objects): each frame,
/// the object pairs whose world boxes touch or overlap, found by sort and sweep. It is the same
/// for every backend, so a group query compares narrow phases only, on the same candidates.
///
/// Conservative by construction: an object's world box is its model-frame bounding box mapped
/// by the pose's matrix as written (centre R c + t, half extents |R| h, exact for any linear map,
/// so a rotation that is orthonormal only to 1e-9 is still covered), enlarged by 1e-12 of its
/// magnitude — a thousand times the rounding of those few operations — so a pair the exact
/// oracle finds intersecting is never culled.
class BroadPhase {
 public:
  /// `query` is a query of `scene` (a group query, or a two-object one: its one pair); both must
  /// outlive this object.
  BroadPhase(const Scene& scene, const SceneQuery& query);

  /// Candidate pairs in `frame` of objects that exist in it (those the query asks: across its
  /// two sets, for a query of two subtrees): object indices (into Scene::objects) with first <
  /// second, in ascending order.
  std::vector<std::pair<std::size_t, std::size_t>> pairsAt(std::size_t frame) const;

 private:
  struct LocalBox {
    std::size_t object = 0;
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    Eigen::Vector3d half = Eigen::Vector3d::Zero();
  };
  const Scene& scene_;
  const SceneQuery& query_;
  std::vector<LocalBox> boxes_;
};

}  // namespace collido
