// frep_json_fuzz: the FRep file reader (collido::parseFrepFile), then the guaranteed collision
// test and the interval evaluation on whatever solids load.
//
// Why: FRep files come from users; an expression tree of any shape reaches the interval
// arithmetic (Boost.Interval with our outward-rounding policy) and the octree directly.
// What it checks:
//  - whatever the bytes, parseFrepFile returns (an error naming the label is a fine answer)
//    without a crash, an out-of-bounds access, undefined behaviour or a leak;
//  - at random points of each loaded solid's bounds, the interval at the point holds the
//    double-precision value (with a relative 1e-9 allowance), whenever both are finite;
//  - the first pair's collision test (at most 20,000 cells) returns, and a "colliding" answer's
//    witness has both interval lower bounds >= 0.
// Resources: the file's own limits (frames up to 100,000, sweeps of 4,096 pieces) are too
// generous for one input, so inputs with more than 16 frames or a solid costing more than 200
// node evaluations per evaluation are skipped after loading.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <collido/frep/collision.h>
#include <collido/scene/frep_file.h>

namespace {

constexpr const char* kLabel = "fuzz.json";

[[noreturn]] void broken(const std::string& what) {
  std::fprintf(stderr, "frep_json_fuzz: a promise was broken: %s\n", what.c_str());
  std::abort();
}

void checkPoints(const collido::frep::Solid& solid, std::uint64_t seed) {
  const Eigen::AlignedBox3d bounds = solid.bounds();
  Eigen::AlignedBox3d region(Eigen::Vector3d::Constant(-2.0), Eigen::Vector3d::Constant(2.0));
  if (!bounds.isEmpty() && bounds.min().allFinite() && bounds.max().allFinite()) region = bounds;
  for (int k = 0; k < 8; ++k) {
    seed = seed * 6364136223846793005ull + 1442695040888963407ull;
    const Eigen::Vector3d t((seed >> 11 & 1023) / 1023.0, (seed >> 21 & 1023) / 1023.0,
                            (seed >> 31 & 1023) / 1023.0);
    const Eigen::Vector3d p = region.min() + region.sizes().cwiseProduct(t);
    if (!p.allFinite()) continue;
    const double value = solid.value(p);
    const collido::frep::Interval range = solid.range(collido::frep::IntervalBox::ofPoint(p));
    if (!std::isfinite(value) || !std::isfinite(range.lower()) || !std::isfinite(range.upper()))
      continue;
    const double slack = 1e-9 * (1.0 + std::abs(value));
    if (value < range.lower() - slack || value > range.upper() + slack)
      broken("the interval at a point does not hold the value");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const collido::Result<collido::FrepFile> file = collido::parseFrepFile(text, kLabel);
  if (!file.ok()) {
    if (file.status().message().find(kLabel) == std::string::npos)
      broken("an error that does not name the file: " + file.status().message());
    return 0;
  }
  if (file.value().times.size() > 16) return 0;
  for (const collido::FrepSolidEntry& entry : file.value().solids)
    if (entry.evaluation_cost > 200) return 0;
  try {
    std::uint64_t seed = size;
    for (const collido::FrepSolidEntry& entry : file.value().solids)
      checkPoints(*entry.at(file.value().times.front()), ++seed);
    const auto [i, j] = file.value().pairs.front();
    const collido::frep::SolidPtr a = file.value().solids[i].at(0.0);
    const collido::frep::SolidPtr b = file.value().solids[j].at(0.0);
    collido::frep::CollisionOptions options;
    options.max_cells = 20000;
    const Eigen::AlignedBox3d common = a->bounds().intersection(b->bounds());
    if (!common.isEmpty() && common.sizes().allFinite() && common.sizes().maxCoeff() > 0)
      options.precision = common.sizes().maxCoeff() / 64;
    const collido::frep::CollisionResult result = collido::frep::collide(*a, *b, options);
    if (result.verdict == collido::frep::CollisionVerdict::kColliding) {
      const auto at = collido::frep::IntervalBox::ofPoint(result.witness);
      if (!(a->range(at).lower() >= 0.0 && b->range(at).lower() >= 0.0))
        broken("a witness outside a solid");
    }
  } catch (const std::invalid_argument&) {
    // Unbounded common bounds and the like: refused with a reason.
  } catch (const std::runtime_error&) {
    // Boost.Interval refusing an empty interval: reported by `collido frep` as a failure.
  }
  return 0;
}
