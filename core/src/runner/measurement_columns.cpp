#include <collido/runner/measurement_columns.h>

#include <optional>

#include <collido/runner/checks.h>
#include <collido/runner/text_table.h>
#include <collido/runner/time_statistic.h>

namespace collido {
namespace {

std::string meanTime(const QueryMeasurement& m) {
  const TimeBootstrap time(m);
  return withInterval(time.estimate(), time.ci95());
}

// "3 1.12x unstable": the rounds, and the slowest round's figure over the fastest's.
std::string rounds(const QueryMeasurement& m) {
  const std::optional<double> spread = roundSpread(m);
  if (!spread) return std::to_string(m.rounds);
  return std::to_string(m.rounds) + " " + formatNumber("%.2f", *spread) + "x" +
         (unstable(m) ? " unstable" : "");
}

// The repeated protocol's figure over the headline's, "0.81x", or "-" where not measured.
std::string repeated(const QueryMeasurement& m) {
  const double headline = meanFrameTimeUs(m);
  if (!m.repeated_us || headline <= 0.0) return "-";
  return formatNumber("%.2f", *m.repeated_us / headline) + "x";
}

std::string pairFigure(const QueryMeasurement& m, double value) {
  return queryKindInfo(m.kind).has(AnswerPart::kPairSet) ? formatNumber("%.4f", value) : "-";
}

// The registered checks' figures that declare a column (runner/checks.h), after the runner's.
std::vector<MeasurementColumn> withCheckColumns(std::vector<MeasurementColumn> columns) {
  for (const CheckFigure& figure : checkFigures()) {
    if (figure.column.empty()) continue;
    columns.push_back({figure.column, [figure](const QueryMeasurement& m) {
                         const std::optional<double> value = figure.value(m);
                         return value ? formatNumber(figure.format, *value) : std::string("-");
                       }});
  }
  return columns;
}

// The registered checks' columns explained, each after a space.
std::string checkLegends() {
  std::string text;
  for (const CheckFigure& figure : checkFigures()) {
    if (!figure.column.empty()) text += " " + figure.column + ": " + figure.legend;
  }
  return text;
}

}  // namespace

const std::vector<MeasurementColumn>& measurementColumns() {
  using M = const QueryMeasurement&;
  static const std::vector<MeasurementColumn> columns = withCheckColumns({
      {"frames", [](M m) { return std::to_string(m.frames.size()); }},
      {"mean us [95% CI]", &meanTime},
      {"rounds", &rounds},
      {"repeated", &repeated},
      {"FN", [](M m) { return std::to_string(m.false_negatives); }},
      {"FP", [](M m) { return std::to_string(m.false_positives); }},
      {"recall", [](M m) { return pairFigure(m, m.recall); }},
      {"precision", [](M m) { return pairFigure(m, m.precision); }},
      {"disagree", [](M m) { return std::to_string(m.disagreements); }},
      {"coarse err",
       [](M m) {
         return m.finest_disagreements ? std::to_string(*m.finest_disagreements) : std::string("-");
       }},
      {"build ms", [](M m) { return formatNumber("%.2f", m.build_ms); }},
      {"B/tri", [](M m) { return bytesPerTriangleText(m.memory_bytes, m.triangles); }},
      {"B/tri heap",
       [](M m) {
         return m.heap_bytes ? bytesPerTriangleText(*m.heap_bytes, m.triangles)
                             : std::string("n/a");
       }},
  });
  return columns;
}

std::vector<std::string> measurementHeaders() {
  std::vector<std::string> headers;
  for (const MeasurementColumn& column : measurementColumns())
    headers.emplace_back(column.header);
  return headers;
}

std::vector<std::string> measurementCells(const QueryMeasurement& m) {
  std::vector<std::string> cells;
  for (const MeasurementColumn& column : measurementColumns())
    cells.push_back(column.cell(m));
  return cells;
}

std::string measurementColumnsLegend(const std::string& percentiles) {
  return std::string("mean us: the ") + kTimeStatisticText +
         "; the single calls' percentiles are in " + percentiles +
         " (p90_us, p99_us, max_us). rounds: "
         "the worker processes the calls came from, and the slowest round's figure over the "
         "fastest's; 'unstable' where the rounds cannot pin the figure down to within " +
         formatNumber("%g", kEquivalenceBand * 100.0) +
         "% (the 95% interval of their mean is wider), even after the extra rounds the study "
         "gave it. repeated: the secondary figure, the repeated protocol's (each frame's calls "
         "back to back, its data in cache: one pose checked again and again; measured in the "
         "first round), over the mean." +
         checkLegends() + "\n";
}

}  // namespace collido
