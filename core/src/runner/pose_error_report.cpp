#include <collido/runner/pose_error_report.h>

#include <cmath>

#include <collido/runner/text_table.h>

namespace collido {
namespace {

using Json = nlohmann::json;

// A figure no trial gave (NaN) is shown as "-" and written as null.
std::string cell(const char* format, double value) {
  return std::isnan(value) ? "-" : formatNumber(format, value);
}

Json number(double value) {
  return std::isnan(value) ? Json() : Json(value);
}

}  // namespace

std::string errorSweepText(const std::vector<pose::ErrorSweepRow>& rows) {
  std::vector<std::vector<std::string>> table;
  table.reserve(rows.size());
  for (const pose::ErrorSweepRow& r : rows) {
    table.push_back(
        {pose::poseSolverName(r.solver), pose::layoutKindName(r.layout), std::to_string(r.markers),
         formatNumber("%g", r.noise), formatNumber("%g", r.dropout),
         std::to_string(r.failed) + "/" + std::to_string(r.trials),
         cell("%.3f", r.rotation_deg_median), cell("%.3f", r.rotation_deg_p90),
         cell("%.2f", 1000.0 * r.translation_median), cell("%.2f", 1000.0 * r.worst_vertex_median),
         cell("%.2f", 1000.0 * r.worst_vertex_p90),
         cell("%.2f", 1000.0 * r.pose_worst_vertex_median), cell("%.1f", r.solve_us_median)});
  }
  std::string text =
      formatTextTable(
          {"solver", "layout", "markers", "noise", "dropout", "failed", "rot deg median",
           "rot deg p90", "transl median x1e-3", "worst vertex median x1e-3",
           "worst vertex p90 x1e-3", "rigid pose worst x1e-3", "solve us"},
          table, 2) +
      "Errors against the true pose; 'worst vertex' is the largest displacement of the object's "
      "mesh by the fit's own map (the affine fit's 12 coefficients), 'rigid pose worst' by the "
      "rigid pose that drives the collision query; lengths in thousandths of the scene unit; "
      "'failed' fits were refused (first reason in the JSON).\n";
  for (const pose::ErrorSweepRow& r : rows) {
    if (r.failed > 0) {
      text += "note: " + std::string(pose::poseSolverName(r.solver)) + " / " +
              pose::layoutKindName(r.layout) + " / " + std::to_string(r.markers) +
              " markers: " + std::to_string(r.failed) + " refused, e.g. " + r.first_failure + "\n";
      break;
    }
  }
  return text;
}

Json errorSweepRowsJson(const std::vector<pose::ErrorSweepRow>& rows) {
  Json out = Json::array();
  for (const pose::ErrorSweepRow& r : rows) {
    out.push_back({{"solver", pose::poseSolverName(r.solver)},
                   {"layout", pose::layoutKindName(r.layout)},
                   {"markers", r.markers},
                   {"noise", r.noise},
                   {"dropout", r.dropout},
                   {"trials", r.trials},
                   {"failed", r.failed},
                   {"first_failure", r.first_failure},
                   {"rotation_deg_median", number(r.rotation_deg_median)},
                   {"rotation_deg_p90", number(r.rotation_deg_p90)},
                   {"translation_median", number(r.translation_median)},
                   {"translation_p90", number(r.translation_p90)},
                   {"worst_vertex_median", number(r.worst_vertex_median)},
                   {"worst_vertex_p90", number(r.worst_vertex_p90)},
                   {"pose_worst_vertex_median", number(r.pose_worst_vertex_median)},
                   {"solve_us_median", number(r.solve_us_median)}});
  }
  return out;
}

}  // namespace collido
