#include <collido/study/outputs.h>

#include <collido/runner/measurement_json.h>

#include <unistd.h>

#include <chrono>
#include <ctime>
#include <filesystem>
#include <map>
#include <sstream>
#include <thread>

#include <nlohmann/json.hpp>

#include <collido/io/files.h>
#include <collido/runner/measurement_columns.h>
#include <collido/runner/text_table.h>
#include <collido/runner/time_statistic.h>
#include <collido/study/comparison_files.h>
#include <collido/study/contact_table.h>
#include <collido/study/continuous_table.h>
#include <collido/study/deform_table.h>
#include <collido/study/expected_time.h>
#include <collido/study/field_table.h>
#include <collido/study/figures.h>
#include <collido/study/needs_table.h>
#include <collido/study/robustness.h>
#include <collido/study/selection_table.h>
#include <collido/study/tracking_table.h>

namespace collido::study {
namespace {

using OrderedJson = nlohmann::ordered_json;

std::string benchmarkName(const Combination& c, const QueryMeasurement& m) {
  const std::string setting = c.settingText();
  std::string name = c.backend + "/" + c.scene_name + "/" + m.query;
  if (!setting.empty()) name += "/" + setting;
  return name;
}

// "3 1.04x", "3 1.31x unstable", or "1".
std::string localTime() {
  const std::time_t now = std::time(nullptr);
  std::tm parts{};
  localtime_r(&now, &parts);
  char text[64];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%S%z", &parts);
  return text;
}

std::string hostName() {
  char name[256] = {};
  if (gethostname(name, sizeof name - 1) != 0) return "";
  return name;
}

}  // namespace

std::string recordsJsonLines(const std::vector<CombinationResult>& results) {
  std::ostringstream out;
  for (const CombinationResult& r : results) {
    const Combination& c = r.combination;
    for (const QueryMeasurement& m : r.measurements) {
      for (const FrameRecord& f : m.frames) {
        OrderedJson line = {{"combination", c.id}};
        line.update(measurementIdentity<OrderedJson>(c, m));
        line.update(frameRecordJson<OrderedJson>(f, m));
        out << line.dump() << "\n";
      }
    }
  }
  return out.str();
}

namespace {

// summary.json's text with the picks computed once for every output.
std::string benchmarkJsonWith(const std::vector<CombinationResult>& results,
                              const std::vector<SceneQueryPicks>& picks) {
  OrderedJson benchmarks = OrderedJson::array();
  for (const CombinationResult& r : results) {
    for (const QueryMeasurement& m : tableMeasurements(r)) {
      if (!m.ok()) continue;
      const std::string name = benchmarkName(r.combination, m);
      OrderedJson entry = {{"name", name},
                           {"family_index", benchmarks.size()},
                           {"per_family_instance_index", 0},
                           {"run_name", name},
                           {"run_type", "iteration"},
                           {"repetitions", 1},
                           {"repetition_index", 0},
                           {"threads", 1},
                           {"iterations", m.times_us.size()},
                           {"real_time", meanFrameTimeUs(m)},
                           {"cpu_time", meanFrameTimeUs(m)},
                           {"time_unit", "us"}};
      // Every summary figure the measurement has, as a counter.
      for (const Figure& figure : measurementFigures()) {
        if ((figure.uses & kInSummary) == 0u) continue;
        const nlohmann::json value = figure.value(r, m);
        if (!value.is_null()) entry[figure.name] = value;
      }
      benchmarks.push_back(entry);
    }
  }
  const unsigned cpus = std::thread::hardware_concurrency();
  const OrderedJson context = {{"date", localTime()},
                               {"host_name", hostName()},
                               {"executable", "collido study"},
                               {"num_cpus", cpus},
                               {"mhz_per_cpu", 0},
                               {"cpu_scaling_enabled", false},
                               {"caches", OrderedJson::array()},
                               {"load_avg", OrderedJson::array()},
                               // What real_time is (Google Benchmark's readers ignore other keys).
                               {"time_statistic", kTimeStatisticText},
#ifdef NDEBUG
                               {"library_build_type", "release"}
#else
                               {"library_build_type", "debug"}
#endif
  };
  OrderedJson document = {{"context", context}, {"benchmarks", benchmarks}};
  // Beside Google Benchmark's keys (its readers ignore others): the robustness matrix of the
  // stress scenes, when the study ran any.
  const std::vector<RobustnessCell> robustness = robustnessMatrix(results);
  if (!robustness.empty()) document["robustness_matrix"] = robustnessJson(robustness);
  // And what to pick per scene and query (the section at the top of table.txt).
  if (!picks.empty()) document["what_to_pick"] = whatToPickJson(picks, PickBudget{});
  return document.dump(2) + "\n";
}

// One of table.txt's summary sections (outputs.h, sections.json): `heading` is the line printed
// over it, its title with what its rows are.
struct TableSection {
  std::string key;
  std::string title;
  std::string heading;
  std::string text;
};

// The summary sections, each found by its key (what to pick first: table.txt prints it above
// the table of every setting, the others below it, in this order).
std::vector<TableSection> summarySectionsWith(const std::vector<CombinationResult>& results,
                                              const std::vector<SceneQueryPicks>& picks,
                                              const std::vector<NotApplicable>& not_applicable,
                                              const FieldSides& sides) {
  std::vector<TableSection> sections;
  const auto add = [&sections](const char* key, std::string title, const std::string& detail,
                               std::string text) {
    if (text.empty()) return;
    std::string heading = title + (detail.empty() ? "" : " (" + detail + ")");
    sections.push_back({key, std::move(title), std::move(heading), std::move(text)});
  };
  add("what_to_pick", "What to pick", "per scene and query", whatToPickText(picks, PickBudget{}));
  add("not_applicable", "Not applicable, so not planned",
      "the setting answers none of the query kinds the scene asks",
      notApplicableText(not_applicable));
  add("needs", "What the scene's needs save",
      "every against declared and changed, per backend setting, scene and query",
      needsTable(results));
  add("field", fieldTableTitle(sides), "single thread, exact answers; per scene and query",
      fieldTable(results, sides));
  add("continuous", "Between the frames",
      "first contact over each step: time against missed contacts and time error; per scene and "
      "query",
      continuousTable(results, sides));
  add("contacts", "Contacts against the exact reference", "", contactTable(results));
  add("deforming", "Deforming scenes", "update, then query, every frame", deformTable(results));
  add("tracking", "Poses from tracked markers", "collision error against the true poses",
      trackingTable(results));
  if (const std::string robustness = robustnessText(robustnessMatrix(results));
      !robustness.empty()) {
    // The two rate matrices: the text up to the table of every count.
    add("robustness", "Robustness matrix",
        "stress scenes by category; every count in robustness.txt",
        robustness.substr(0, robustness.find("\nEvery count")));
  }
  return sections;
}

std::string sectionsJson(const std::vector<TableSection>& sections) {
  OrderedJson list = OrderedJson::array();
  for (const TableSection& section : sections) {
    list.push_back({{"key", section.key},
                    {"title", section.title},
                    {"heading", section.heading},
                    {"text", section.text}});
  }
  return OrderedJson{{"collidoscope_sections", 1}, {"sections", list}}.dump(1) + "\n";
}

std::string studyTableWith(const std::vector<CombinationResult>& results,
                           const std::vector<TableSection>& sections) {
  std::vector<std::string> header = {"backend", "setting", "scene", "query"};
  for (const std::string& column : measurementHeaders())
    header.push_back(column);
  header.push_back("RSS MiB");
  std::vector<std::vector<std::string>> rows;
  std::vector<std::string> failures;
  for (const CombinationResult& r : results) {
    const Combination& c = r.combination;
    if (!r.outcome.ok()) {
      const std::string why = r.outcome.text();
      rows.push_back({c.backend, c.settingText(), c.scene_name, "*", why});
      failures.push_back(c.label() + ": worker " + why);
      continue;
    }
    for (const QueryMeasurement& m : tableMeasurements(r)) {
      if (!m.ok()) {
        rows.push_back({c.backend, c.settingText(), c.scene_name, m.query,
                        m.status.skipped() ? "skipped" : "failed"});
        if (m.status.failed())
          failures.push_back(c.label() + " / " + m.query + ": " + m.status.text());
        continue;
      }
      std::vector<std::string> row = {c.backend, c.settingText(), c.scene_name, m.query};
      for (std::string& cell : measurementCells(m))
        row.push_back(std::move(cell));
      row.push_back(formatNumber("%.0f", static_cast<double>(r.residentBytes()) / 1048576.0));
      rows.push_back(std::move(row));
    }
  }
  std::ostringstream out;
  for (const TableSection& section : sections) {
    if (section.key == "what_to_pick")
      out << section.heading << ":\n" << section.text << "\nEvery setting:\n";
  }
  out << formatTextTable(header, rows, 4);
  out << measurementColumnsLegend("summary.json");
  for (const TableSection& section : sections) {
    if (section.key != "what_to_pick") out << "\n" << section.heading << ":\n" << section.text;
  }
  if (!failures.empty()) {
    out << "\nFailures:\n";
    for (const std::string& f : failures)
      out << "  " << f << "\n";
  }
  return out.str();
}

}  // namespace

std::string benchmarkJson(const std::vector<CombinationResult>& results) {
  return benchmarkJsonWith(results, whatToPick(results));
}

std::string studyTable(const std::vector<CombinationResult>& results,
                       const std::vector<NotApplicable>& not_applicable, const FieldSides& field) {
  return studyTableWith(results,
                        summarySectionsWith(results, whatToPick(results), not_applicable, field));
}

Status writeStudyOutputs(const std::string& directory,
                         const std::vector<CombinationResult>& results) {
  const std::filesystem::path folder(directory);
  const ResultStore store(directory);
  Result<std::vector<NotApplicable>> not_applicable = store.readNotApplicable();
  if (!not_applicable.ok()) return not_applicable.status();
  Result<FieldSides> field = store.readFieldSides();
  if (!field.ok()) return field.status();
  if (Status s =
          io::writeFileAtomically((folder / "records.jsonl").string(), recordsJsonLines(results));
      !s.ok()) {
    return s;
  }
  const std::vector<SceneQueryPicks> picks = whatToPick(results);
  if (Status s = io::writeFileAtomically((folder / "summary.json").string(),
                                         benchmarkJsonWith(results, picks));
      !s.ok()) {
    return s;
  }
  if (Status s = io::writeFileAtomically((folder / "times.json").string(), timesJson(results));
      !s.ok()) {
    return s;
  }
  if (Status s = writeComparisonFiles(directory, results); !s.ok()) return s;
  if (const std::string robustness = robustnessReport(results); !robustness.empty()) {
    if (Status s = io::writeFileAtomically((folder / "robustness.txt").string(), robustness);
        !s.ok()) {
      return s;
    }
  }
  const std::vector<TableSection> sections =
      summarySectionsWith(results, picks, not_applicable.value(), field.value());
  if (Status s =
          io::writeFileAtomically((folder / "sections.json").string(), sectionsJson(sections));
      !s.ok()) {
    return s;
  }
  return io::writeFileAtomically((folder / "table.txt").string(),
                                 studyTableWith(results, sections));
}

std::string robustnessReport(const std::vector<CombinationResult>& results) {
  const std::string matrix = robustnessText(robustnessMatrix(results));
  if (matrix.empty()) return "";
  return "Robustness matrix: every backend setting on the stress scenes, by category; every "
         "answer checked against the exact oracle.\n\n" +
         matrix;
}

}  // namespace collido::study
