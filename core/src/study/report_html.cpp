#include <collido/study/report_html.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include <collido/host/install_layout.h>
#include <collido/io/files.h>
#include <collido/io/html_page.h>
#include <collido/runner/measurement_columns.h>
#include <collido/study/figures.h>
#include <collido/study/robustness.h>
#include <collido/study/selection_table.h>
#include <collido/study/time_changes.h>

namespace collido::study {
namespace {

using Json = nlohmann::json;

std::string backendLabel(const Combination& c) {
  const std::string setting = c.settingText();
  return setting.empty() ? c.backend : c.backend + " " + setting;
}

// A dashboard row: the setting, scene and query, then every figure the dashboard shows.
Json row(const CombinationResult& r, const QueryMeasurement& m) {
  const Combination& c = r.combination;
  const std::size_t variant_end = c.backend.find('[');
  Json row = measurementIdentity<Json>(c, m);
  row.update({{"key", c.backend + "|" + c.settingText() + "|" + c.scene_name + "|" + m.query},
              {"label", backendLabel(c)},
              {"variant", c.backend.substr(0, variant_end)},
              {"setting", c.settingText()},
              {"status", m.status.text()}});
  for (const Figure& figure : measurementFigures()) {
    if ((figure.uses & kInDashboard) != 0u) row[figure.name] = figure.value(r, m);
  }
  // The cells of table.txt's row (measurement_columns.h), for the page's table of every row.
  row["cells"] = m.ok() ? Json(measurementCells(m)) : Json::array();
  return row;
}

Json rowsOf(const std::vector<CombinationResult>& results) {
  Json rows = Json::array();
  for (const CombinationResult& r : results) {
    for (const QueryMeasurement& m : tableMeasurements(r))
      rows.push_back(row(r, m));
  }
  return rows;
}

Json failuresOf(const std::vector<CombinationResult>& results) {
  Json failures = Json::array();
  for (const CombinationResult& r : results) {
    const Combination& c = r.combination;
    if (!r.outcome.ok()) {
      const std::string status = workerStatusName(r.outcome.status);
      std::string detail = "worker " + status;
      if (!r.outcome.signal_name.empty()) detail += " by " + r.outcome.signal_name;
      if (r.outcome.status == WorkerStatus::kFailed)
        detail += " with exit code " + std::to_string(r.outcome.exit_code);
      detail += " after " + std::to_string(r.outcome.wall_s).substr(0, 5) + " s";
      failures.push_back({{"what", status},
                          {"label", backendLabel(c)},
                          {"scene", c.scene_name},
                          {"query", "*"},
                          {"detail", detail},
                          {"log", r.outcome.log_tail}});
      continue;
    }
    for (const QueryMeasurement& m : tableMeasurements(r)) {
      std::string what;
      std::string detail = m.status.text();
      if (m.status.skipped()) {
        what = "unsupported";
      } else if (!m.ok()) {
        what = "failed";
      } else if (m.disagreements != 0) {
        what = "wrong answers";
        std::ostringstream text;
        text << m.disagreements << " of " << m.frames.size() << " frames differ from the oracle ("
             << m.false_negatives << " missed contacts, " << m.false_positives << " false contacts";
        if (queryKindInfo(m.kind).has(AnswerPart::kPairSet)) {
          text << ", pair recall " << m.recall << ", precision " << m.precision;
        }
        text << ")";
        detail = text.str();
      } else {
        continue;
      }
      failures.push_back({{"what", what},
                          {"label", backendLabel(c)},
                          {"scene", c.scene_name},
                          {"query", m.query},
                          {"detail", detail},
                          {"log", ""}});
    }
  }
  return failures;
}

Json timesOf(const std::vector<CombinationResult>& results) {
  Json times = Json::array();
  for (const CombinationResult& r : results) {
    for (const QueryMeasurement& m : tableMeasurements(r)) {
      if (!m.ok() || m.times_us.empty()) continue;
      // Every timed call up to a cap, evenly thinned beyond it, and always the fastest and the
      // slowest (the box plot's whiskers): the page stays small while the shape of each
      // distribution survives. One list per measurement, not one object per call.
      const std::vector<double>& all = m.times_us;
      const std::size_t cap = 600;
      const std::size_t step = all.size() > cap ? (all.size() + cap - 1) / cap : 1;
      const auto [fastest, slowest] = std::minmax_element(all.begin(), all.end());
      Json us = Json::array();
      for (std::size_t i = 0; i < all.size(); i += step)
        us.push_back(all[i]);
      if (step > 1) {
        us.push_back(*fastest);
        us.push_back(*slowest);
      }
      times.push_back({{"label", backendLabel(r.combination)},
                       {"scene", r.combination.scene_name},
                       {"query", m.query},
                       {"us", std::move(us)}});
    }
  }
  return times;
}

// Per frame of every measurement with updates (deforming scenes): the update cost, the
// structures it rebuilt (null where the backend does not count), the query's median and
// whether the answer differed from the oracle's.
Json deformingOf(const std::vector<CombinationResult>& results) {
  Json frames = Json::array();
  for (const CombinationResult& r : results) {
    for (const QueryMeasurement& m : tableMeasurements(r)) {
      if (!m.ok() || !m.update_median_us) continue;
      for (const FrameRecord& f : m.frames) {
        frames.push_back(
            {{"label", backendLabel(r.combination)},
             {"scene", r.combination.scene_name},
             {"query", m.query},
             {"frame", f.frame},
             {"update_us", f.update_us.value_or(0.0)},
             {"rebuilds", f.update_work.counted ? Json(f.update_work.rebuilds) : Json()},
             {"query_us", f.median_us},
             {"wrong", f.disagrees(m.kind)}});
      }
    }
  }
  return frames;
}

// Per frame of each tracked (scene, query), once (the oracle's answers, the same for every
// backend): whether the objects touch at the true poses and at the recovered ones.
Json trackingOf(const std::vector<CombinationResult>& results) {
  Json frames = Json::array();
  std::set<std::string> seen;
  for (const CombinationResult& r : results) {
    for (const QueryMeasurement& m : tableMeasurements(r)) {
      if (!m.ok() || !m.tracking_false_contacts) continue;
      if (!seen.insert(r.combination.scene_name + "\n" + m.query).second) continue;
      for (const FrameRecord& f : m.frames) {
        frames.push_back({{"scene", r.combination.scene_name},
                          {"query", m.query},
                          {"frame", f.frame},
                          {"truth", f.truth_intersecting.value_or(false)},
                          {"recovered", f.oracle_intersecting}});
      }
    }
  }
  return frames;
}

}  // namespace

Json reportData(const std::vector<CombinationResult>& results,
                const std::vector<CombinationResult>& baseline, const std::string& title,
                const std::vector<NotApplicable>& not_applicable) {
  Json not_planned = Json::array();
  for (const NotApplicable& n : not_applicable)
    not_planned.push_back({{"backend", n.backend}, {"scene", n.scene}, {"why", n.reason()}});
  const std::time_t now = std::time(nullptr);
  std::tm parts{};
  gmtime_r(&now, &parts);
  char generated[32];
  std::strftime(generated, sizeof generated, "%Y-%m-%d %H:%M UTC", &parts);
  return {{"title", title},
          {"generated", generated},
          {"rows", rowsOf(results)},
          {"columns", measurementHeaders()},
          {"columns_legend", measurementColumnsLegend("summary.json")},
          {"baseline_rows", rowsOf(baseline)},
          // Each setting, scene and query against the baseline: ratio, interval and verdict.
          {"baseline_changes",
           baseline.empty() ? Json() : timeChangesJson(timeChanges(baseline, results))},
          {"times", timesOf(results)},
          {"deforming", deformingOf(results)},
          {"tracking", trackingOf(results)},
          {"failures", failuresOf(results)},
          {"not_applicable", std::move(not_planned)},
          {"robustness", robustnessJson(robustnessMatrix(results))},
          {"what_to_pick", whatToPickJson(whatToPick(results), PickBudget{})}};
}

std::string webDirectory(const std::string& explicit_directory) {
  if (!explicit_directory.empty()) return explicit_directory;
  if (const char* env = std::getenv("COLLIDO_WEB_DIR"); env != nullptr && *env != '\0') return env;
  if (const std::string installed = installedDataDirectory(); !installed.empty()) {
    return installed + "/web";
  }
#ifdef COLLIDO_WEB_SOURCE_DIR
  return COLLIDO_WEB_SOURCE_DIR;
#else
  return "web";
#endif
}

// The dashboard's script: the files web/report/scripts.json lists, in its order (each file one
// part of the page, using what the files before it define), joined into one <script>.
Result<std::string> reportScript(const std::filesystem::path& web) {
  const std::filesystem::path manifest = web / "report" / "scripts.json";
  Result<Json> names = io::readJsonFile(manifest.string());
  if (!names.ok()) return names.status();
  if (!names.value().is_array() || names.value().empty()) {
    return Status(StatusCode::kInvalidArgument,
                  manifest.string() + ": expected a list of the dashboard's script files");
  }
  std::vector<io::PagePart> parts;
  for (const Json& entry : names.value()) {
    const std::string name = entry.is_string() ? entry.get<std::string>() : std::string();
    const bool plain = name.size() > 3 && name.compare(name.size() - 3, 3, ".js") == 0 &&
                       std::filesystem::path(name).filename() == name;
    if (!plain) {
      return Status(StatusCode::kInvalidArgument,
                    manifest.string() + ": " + entry.dump() +
                        " is not the name of a .js file beside the manifest");
    }
    parts.push_back({"@" + name + "@", web / "report" / name});
  }
  std::map<std::string, std::string> texts;
  if (Status read = io::readPageParts(web, parts, texts); !read.ok()) return read;
  std::string script;
  for (const io::PagePart& part : parts)
    script += "// " + part.file.filename().string() + "\n" + texts[part.marker] + "\n";
  return script;
}

Result<std::string> renderReport(const Json& data, const std::string& web_directory) {
  const std::filesystem::path web(web_directory);
  Result<std::string> page =
      io::readTextFile((web / "report" / "template.html").string(), "not found");
  if (!page.ok()) return page.status();
  std::map<std::string, std::string> values{
      {"@TITLE@", io::htmlText(data.value("title", std::string("study")))},
      {"@DATA@", io::dataSafe(data.dump(-1, ' ', false, Json::error_handler_t::replace))}};
  const Status read = io::readPageParts(
      web,
      {{"@CSS@", web / "report" / "report.css", false},
       {"@VEGA@", web / "node_modules" / "vega" / "build" / "vega.min.js"},
       {"@VEGA_LITE@", web / "node_modules" / "vega-lite" / "build" / "vega-lite.min.js"},
       {"@VEGA_EMBED@", web / "node_modules" / "vega-embed" / "build" / "vega-embed.min.js"}},
      values);
  if (!read.ok()) return read;
  Result<std::string> script = reportScript(web);
  if (!script.ok()) return script.status();
  values["@REPORT_JS@"] = std::move(script).value();
  return io::fillTemplate(page.value(), values);
}

}  // namespace collido::study
