#pragma once

#include <memory>
#include <string>
#include <vector>

#include <collido/runner/checks.h>
#include <collido/scene/scene.h>

#include "frame_observers.h"

namespace collido::detail {

/// A check that owns its data (runner/checks.h): the observer that measures it, the per-frame
/// values that observer records in FrameRecord::values, and the summary figures folded from them.
class Check {
 public:
  virtual ~Check() = default;
  /// The names its observer records in FrameRecord::values.
  virtual std::vector<std::string> frameValues() const = 0;
  virtual std::vector<CheckFigure> figures() const = 0;
  /// The observer for one query's frames; null when the check does not apply to the query.
  virtual std::unique_ptr<FrameObserver> observe(const SceneQuery& query) const = 0;
};

/// Every registered check (checks.cpp), in output order.
const std::vector<std::unique_ptr<Check>>& registeredChecks();

/// The largest of a per-frame value over a measurement's frames; absent when no frame has it.
std::optional<double> largestFrameValue(const QueryMeasurement& m, const std::string& name);

}  // namespace collido::detail
