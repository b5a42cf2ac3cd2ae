#include <collido/runner/statistics.h>

#include <algorithm>
#include <cmath>

namespace collido {

double quantile(std::vector<double> samples, double q) {
  if (samples.empty()) return 0.0;
  const double position = std::clamp(q, 0.0, 1.0) * static_cast<double>(samples.size() - 1);
  const auto below = static_cast<std::size_t>(std::floor(position));
  const auto at = samples.begin() + static_cast<std::ptrdiff_t>(below);
  // Selection, not a sort: the study takes thousands of quantiles of bootstrap replicates.
  std::nth_element(samples.begin(), at, samples.end());
  const double low = *at;
  // Everything after the selected one is at least as large: the next order statistic is their
  // least.
  const double high = at + 1 == samples.end() ? low : *std::min_element(at + 1, samples.end());
  return low + (position - static_cast<double>(below)) * (high - low);
}

}  // namespace collido
