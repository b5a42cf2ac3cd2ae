// 3x3 products on the distance search's hot path, written out: GCC keeps Eigen's generic
// fixed-size product loops out of line there, a call and a loop per product for about 27
// multiplications. Each entry is a three-term sum of products, as in Eigen's, so the error
// bounds that rely on these products hold alike.
#pragma once

#include <Eigen/Core>

namespace collido::obbtree::detail {

/// a^T b.
inline Eigen::Matrix3d transposedTimes(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  Eigen::Matrix3d out;
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 3; ++i)
      out(i, j) = a(0, i) * b(0, j) + a(1, i) * b(1, j) + a(2, i) * b(2, j);
  }
  return out;
}

/// a b.
inline Eigen::Matrix3d times(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  Eigen::Matrix3d out;
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 3; ++i)
      out(i, j) = a(i, 0) * b(0, j) + a(i, 1) * b(1, j) + a(i, 2) * b(2, j);
  }
  return out;
}

/// a^T v.
inline Eigen::Vector3d transposedTimesVector(const Eigen::Matrix3d& a, const Eigen::Vector3d& v) {
  return {a(0, 0) * v[0] + a(1, 0) * v[1] + a(2, 0) * v[2],
          a(0, 1) * v[0] + a(1, 1) * v[1] + a(2, 1) * v[2],
          a(0, 2) * v[0] + a(1, 2) * v[1] + a(2, 2) * v[2]};
}

/// a v.
inline Eigen::Vector3d timesVector(const Eigen::Matrix3d& a, const Eigen::Vector3d& v) {
  return {a(0, 0) * v[0] + a(0, 1) * v[1] + a(0, 2) * v[2],
          a(1, 0) * v[0] + a(1, 1) * v[1] + a(1, 2) * v[2],
          a(2, 0) * v[0] + a(2, 1) * v[1] + a(2, 2) * v[2]};
}

}  // namespace collido::obbtree::detail
