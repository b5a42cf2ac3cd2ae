#pragma once

// Reading the study's plain-text tables back in tests: a row's cells, split on runs of two or
// more spaces (cells themselves hold at most single spaces).
#include <string>
#include <vector>

namespace collido::study::testdata {

/// The cells of line `line` (0: the header, 1: the rule, 2: the first row) of `table`; empty
/// when the table has no such line.
inline std::vector<std::string> cellsOfLine(const std::string& table, std::size_t line) {
  std::size_t start = 0;
  for (std::size_t k = 0; k < line; ++k) {
    start = table.find('\n', start);
    if (start == std::string::npos) return {};
    ++start;
  }
  const std::string row = table.substr(start, table.find('\n', start) - start);
  std::vector<std::string> cells;
  std::size_t i = 0;
  while (i < row.size()) {
    while (i < row.size() && row[i] == ' ')
      ++i;
    std::size_t j = i;
    while (j < row.size() && !(row[j] == ' ' && j + 1 < row.size() && row[j + 1] == ' '))
      ++j;
    if (j > i) cells.push_back(row.substr(i, j - i));
    i = j;
  }
  return cells;
}

}  // namespace collido::study::testdata
