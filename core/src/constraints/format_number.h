#pragma once

#include <sstream>
#include <string>

namespace collido::constraints::detail {

/// A residual or fraction for an error message, to three significant digits (std::to_string's
/// fixed six decimals would print a 1e-9 residual as 0).
inline std::string formatNumber(double value) {
  std::ostringstream out;
  out.precision(3);
  out << value;
  return out.str();
}

}  // namespace collido::constraints::detail
