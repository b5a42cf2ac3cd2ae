// The scalar kernel of a batched box test, lane by lane through boxesOverlap, and the choice of
// kernel for this CPU.
#include "box_batch.h"

#include <collido/obbtree/separating_axis.h>

#include <Eigen/Core>

namespace collido::obbtree::detail {

std::uint32_t overlappingLanesAvx2(const BoxBatch& batch);  // box_batch_avx2.cpp

namespace {

struct BoxView {
  Eigen::Matrix3d axes;
  Eigen::Vector3d center;
  Eigen::Vector3d half;
};

BoxView boxAt(const double* axes, const double* center, const double* half) {
  BoxView box;
  box.axes = Eigen::Map<const Eigen::Matrix3d>(axes);
  box.center = Eigen::Map<const Eigen::Vector3d>(center);
  box.half = Eigen::Map<const Eigen::Vector3d>(half);
  return box;
}

std::uint32_t overlappingLanesScalar(const BoxBatch& batch) {
  const BoxView fixed = boxAt(batch.fixed_axes, batch.fixed_center, batch.fixed_half);
  std::uint32_t overlapping = 0;
  for (int lane = 0; lane < batch.count; ++lane) {
    const BoxView other = boxAt(batch.axes[lane], batch.center[lane], batch.half[lane]);
    const BoxView& a = batch.lanes_are_a ? other : fixed;
    const BoxView& b = batch.lanes_are_a ? fixed : other;
    const Eigen::Matrix3d relative = a.axes.transpose() * b.axes;
    const Eigen::Vector3d offset = a.axes.transpose() * (b.center - a.center);
    const SeparationTolerance tolerance{batch.axis_error, batch.inflation[lane]};
    const bool face_axes_only = (batch.full_test_lanes >> lane & 1U) == 0;
    if (boxesOverlap(relative, offset, a.half, b.half, tolerance, face_axes_only))
      overlapping |= 1U << lane;
  }
  return overlapping;
}

bool cpuHasAvx2AndFma() {
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
  return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
#else
  return false;
#endif
}

}  // namespace

BoxKernel bestBoxKernel() {
  static const BoxKernel best = cpuHasAvx2AndFma() ? BoxKernel::kAvx2 : BoxKernel::kScalar;
  return best;
}

std::uint32_t overlappingLanes(const BoxBatch& batch, BoxKernel kernel) {
  if (kernel == BoxKernel::kAvx2 && bestBoxKernel() == BoxKernel::kAvx2)
    return overlappingLanesAvx2(batch);
  return overlappingLanesScalar(batch);
}

}  // namespace collido::obbtree::detail
