// The registered checks: each is a file of checks/, listed here once.
#include <algorithm>

#include "check.h"

namespace collido {
namespace detail {

std::unique_ptr<Check> makeWitnessGapCheck();

const std::vector<std::unique_ptr<Check>>& registeredChecks() {
  static const std::vector<std::unique_ptr<Check>> checks = [] {
    std::vector<std::unique_ptr<Check>> all;
    all.push_back(makeWitnessGapCheck());
    return all;
  }();
  return checks;
}

std::optional<double> largestFrameValue(const QueryMeasurement& m, const std::string& name) {
  std::optional<double> largest;
  for (const FrameRecord& f : m.frames) {
    const auto found = f.values.find(name);
    if (found != f.values.end()) largest = std::max(largest.value_or(found->second), found->second);
  }
  return largest;
}

}  // namespace detail

const std::vector<std::string>& checkFrameValues() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> all;
    for (const auto& check : detail::registeredChecks()) {
      for (std::string& name : check->frameValues())
        all.push_back(std::move(name));
    }
    return all;
  }();
  return names;
}

const std::vector<CheckFigure>& checkFigures() {
  static const std::vector<CheckFigure> figures = [] {
    std::vector<CheckFigure> all;
    for (const auto& check : detail::registeredChecks()) {
      for (CheckFigure& figure : check->figures())
        all.push_back(std::move(figure));
    }
    return all;
  }();
  return figures;
}

}  // namespace collido
