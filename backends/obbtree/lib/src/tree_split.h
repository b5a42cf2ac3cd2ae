// Where to split a node of the OBB tree (tree_build.cpp).
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <collido/obbtree/oriented_box.h>

namespace collido::obbtree::detail {

/// Reused buffers of splitByCost, kept for a whole build.
struct SplitScratch {
  std::vector<Eigen::AlignedBox3d> bounds;  // per triangle of the node: its corners' bounds
  std::vector<Eigen::Vector3d> centre;      // and the mean of its corners, along the box's axes
};

/// Chooses the split of order[0, count), triangles inside `box`, by a cost model and partitions
/// it there (the lower part first); returns the size of the lower part, or 0 when no plane
/// separates the triangles' centres (column t of `centres`: the mean of triangle t's corners).
/// The planes lie along the box's axes or along those of plane_frames[0 .. plane_frame_count);
/// the sides are sized on the box's axes either way. See tree_split.cpp.
std::int32_t splitByCost(std::int32_t* order, std::int32_t count, const OrientedBox& box,
                         const Eigen::Matrix3d* plane_frames, int plane_frame_count,
                         const Eigen::Ref<const Eigen::Matrix3Xd>& vertices,
                         const Eigen::Ref<const Eigen::Matrix3Xi>& triangles,
                         const Eigen::Matrix3Xd& centres, SplitScratch& scratch);

}  // namespace collido::obbtree::detail
