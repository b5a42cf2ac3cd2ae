#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace collido::obbtree {

/// The triangles of a subtree: positions [first, first + count) of the tree's triangle order.
struct TriangleRange {
  std::int32_t first = 0;
  std::int32_t count = 0;
};

/// Triangles as vertex-index triples in the tree's order, with 16-bit indices when the mesh has
/// at most 65,536 vertices (6 bytes a triangle instead of 12: most meshes a collision query
/// meets), else 32-bit ones. Read like an Eigen::Matrix3Xi: (corner, k) and col(k).
class TriangleList {
 public:
  TriangleList() = default;
  /// Column order[k] of `triangles` stored as triangle k, for every k; indices below
  /// `vertex_count`.
  TriangleList(const Eigen::Ref<const Eigen::Matrix3Xi>& triangles,
               const std::vector<std::int32_t>& order, Eigen::Index vertex_count);

  std::int32_t operator()(int corner, std::int32_t k) const {
    const auto at = 3 * static_cast<std::size_t>(k) + static_cast<std::size_t>(corner);
    return narrow_ ? static_cast<std::int32_t>(short_indices_[at]) : wide_indices_[at];
  }
  Eigen::Vector3i col(std::int32_t k) const {
    return Eigen::Vector3i((*this)(0, k), (*this)(1, k), (*this)(2, k));
  }
  Eigen::Index cols() const { return count_; }
  /// Replaces triangle k (its indices must fit the list's width: a vertex of the same mesh).
  void set(std::int32_t k, const Eigen::Vector3i& triangle);
  /// Triangles [first, first + count) as a matrix (a copy).
  Eigen::Matrix3Xi middleCols(std::int32_t first, std::int32_t count) const;
  /// Every triangle as a matrix (a copy).
  Eigen::Matrix3Xi matrix() const { return middleCols(0, static_cast<std::int32_t>(count_)); }
  /// Whether the indices are stored in 16 bits.
  bool narrow() const { return narrow_; }
  /// The storage, for telling whether two trees share it.
  const void* data() const {
    return narrow_ ? static_cast<const void*>(short_indices_.data())
                   : static_cast<const void*>(wide_indices_.data());
  }
  std::size_t memoryBytes() const {
    return short_indices_.capacity() * sizeof(std::uint16_t) +
           wide_indices_.capacity() * sizeof(std::int32_t);
  }

 private:
  std::vector<std::uint16_t> short_indices_;
  std::vector<std::int32_t> wide_indices_;
  Eigen::Index count_ = 0;
  bool narrow_ = false;
};

}  // namespace collido::obbtree
