#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace collido {

/// A plain-text table: a header, a rule, then the rows; columns from `first_numeric` on are
/// right-aligned. Widths count UTF-8 characters, each taken as one column.
std::string formatTextTable(const std::vector<std::string>& header,
                            const std::vector<std::vector<std::string>>& rows,
                            std::size_t first_numeric);

/// printf-style formatting of one number ("%.1f").
std::string formatNumber(const char* pattern, double value);

/// bytes / triangles, rounded, or "-" without triangles.
std::string bytesPerTriangleText(std::size_t bytes, std::size_t triangles);

}  // namespace collido
