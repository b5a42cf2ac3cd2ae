#include <collido/obbtree/triangle_list.h>

#include <limits>

namespace collido::obbtree {

TriangleList::TriangleList(const Eigen::Ref<const Eigen::Matrix3Xi>& triangles,
                           const std::vector<std::int32_t>& order, Eigen::Index vertex_count)
    : count_(static_cast<Eigen::Index>(order.size())),
      narrow_(vertex_count <= Eigen::Index{std::numeric_limits<std::uint16_t>::max()} + 1) {
  if (narrow_) {
    short_indices_.resize(3 * order.size());
  } else {
    wide_indices_.resize(3 * order.size());
  }
  for (std::size_t k = 0; k < order.size(); ++k)
    set(static_cast<std::int32_t>(k), triangles.col(order[k]));
}

void TriangleList::set(std::int32_t k, const Eigen::Vector3i& triangle) {
  const std::size_t at = 3 * static_cast<std::size_t>(k);
  for (std::size_t c = 0; c < 3; ++c) {
    const int index = triangle[static_cast<Eigen::Index>(c)];
    if (narrow_) {
      short_indices_[at + c] = static_cast<std::uint16_t>(index);
    } else {
      wide_indices_[at + c] = index;
    }
  }
}

Eigen::Matrix3Xi TriangleList::middleCols(std::int32_t first, std::int32_t count) const {
  Eigen::Matrix3Xi out(3, count);
  for (std::int32_t k = 0; k < count; ++k)
    out.col(k) = col(first + k);
  return out;
}

}  // namespace collido::obbtree
