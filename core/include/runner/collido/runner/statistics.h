#pragma once

#include <vector>

namespace collido {

/// The q-quantile (0 <= q <= 1) of `samples` by linear interpolation between closest ranks
/// (Hyndman & Fan type 7, the default of R and NumPy); 0 for no samples.
double quantile(std::vector<double> samples, double q);

}  // namespace collido
