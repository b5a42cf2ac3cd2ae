// Distance queries: how far the reported closest points are from lying the reported distance
// apart. The oracle check (compareWithOracle) flags a frame whose points miss by more than
// rounding; this gives the size of the miss, so a backend whose points are loosely tied to its
// distance shows by how much.
#include <algorithm>
#include <cmath>

#include "../check.h"

namespace collido::detail {
namespace {

constexpr const char* kFrameValue = "witness_gap";

class WitnessGapObserver final : public FrameObserver {
 public:
  void pair(const AskedPair& asked, FrameRecord& record) override {
    const DistanceResult& d = asked.reported.distance;
    const double gap = std::abs((d.point_b - d.point_a).norm() - d.distance);
    // No finite distance or points: the oracle comparison already counts the answer wrong, and
    // a gap that is not a number would not survive the records' JSON.
    if (!std::isfinite(gap)) return;
    double& value = record.values[kFrameValue];
    value = std::max(value, gap);
  }
};

class WitnessGapCheck final : public Check {
 public:
  std::vector<std::string> frameValues() const override { return {kFrameValue}; }
  std::vector<CheckFigure> figures() const override {
    return {{"max_witness_gap", "witness gap", "%.2g",
             "distance queries, the largest difference between the reported distance and the "
             "distance of the reported closest points (model units).",
             [](const QueryMeasurement& m) { return largestFrameValue(m, kFrameValue); }}};
  }
  std::unique_ptr<FrameObserver> observe(const SceneQuery& query) const override {
    if (!queryKindInfo(query.request.kind).has(AnswerPart::kDistance)) return nullptr;
    return std::make_unique<WitnessGapObserver>();
  }
};

}  // namespace

std::unique_ptr<Check> makeWitnessGapCheck() {
  return std::make_unique<WitnessGapCheck>();
}

}  // namespace collido::detail
