#pragma once
// Checks that own their data. A check (core/src/runner/check.h) observes the runner's frames,
// records its per-frame values in FrameRecord::values under the names it declares, and declares
// the summary figures folded from them. The JSON writer and reader (record_fields.h),
// summary.json and the dashboard's rows (study/figures.h) and the text tables' columns
// (runner/measurement_columns.h) follow these declarations: adding a check is one file in
// core/src/runner/checks/ and its line in core/src/runner/checks.cpp.
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace collido {

struct QueryMeasurement;

/// A summary figure of a check, folded from its measurement's frames when asked (so a stored
/// result cannot contradict its own records).
struct CheckFigure {
  std::string name;    ///< its key in the results, summary.json and the dashboard's rows
  std::string column;  ///< its header in the text tables and the dashboard's table; "": none
  const char* format;  ///< the table cell's printf pattern
  std::string legend;  ///< what the column shows, a sentence for the tables' legend
  std::function<std::optional<double>(const QueryMeasurement&)> value;
};

/// The per-frame values of every registered check, in output order.
const std::vector<std::string>& checkFrameValues();

/// The summary figures of every registered check, in output order.
const std::vector<CheckFigure>& checkFigures();

}  // namespace collido
