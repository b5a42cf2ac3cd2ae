#pragma once

// The columns a measurement's row shows in the text tables (collido run's, the study's
// table.txt), declared once: both tables are these columns between their own identity columns
// (backend, scene, query; the study adds the setting before and the worker's memory after).
#include <functional>
#include <string>
#include <vector>

#include <collido/runner/runner.h>

namespace collido {

/// One column: its header and its cell for a measurement that answered.
struct MeasurementColumn {
  std::string header;
  std::function<std::string(const QueryMeasurement& m)> cell;
};

/// frames, mean us [95% CI], rounds, repeated, FN, FP, recall, precision, disagree, coarse err,
/// build ms, B/tri, B/tri heap, then the registered checks' columns (runner/checks.h).
const std::vector<MeasurementColumn>& measurementColumns();

/// The headers of measurementColumns(), in order.
std::vector<std::string> measurementHeaders();

/// The cells of `m`'s row, in order.
std::vector<std::string> measurementCells(const QueryMeasurement& m);

/// What the columns' figures are, for the line under a table; `percentiles` names where the
/// single calls' percentiles are written (summary.json, or collido run's --json report).
std::string measurementColumnsLegend(const std::string& percentiles);

}  // namespace collido
