#pragma once

#include <string>
#include <vector>

namespace collido::study {

/// One check of the conformance kit as `collido conformance` shows it.
struct ConformanceRow {
  std::string check;              ///< "Suite.Test", without the parameterised suite's prefix
  std::string result;             ///< "pass", "skip" or "FAIL"
  std::string detail;             ///< the first line of the first failure, or the test's detail
  std::vector<std::string> more;  ///< the lines of every further failure message
};

/// The checks of the kit's GoogleTest JSON report (--gtest_output=json); none when the file is
/// missing or broken (the kit crashed while writing it).
std::vector<ConformanceRow> readConformanceReport(const std::string& path);

/// The pass/skip/fail table (the runner's text table: check, result, detail; a failure's further
/// lines under its detail), then "N passed, N skipped, N failed".
std::string conformanceTable(const std::vector<ConformanceRow>& rows);

}  // namespace collido::study
