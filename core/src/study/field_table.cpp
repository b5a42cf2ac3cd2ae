#include <collido/study/field_table.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <optional>
#include <sstream>
#include <tuple>

#include <collido/runner/text_table.h>
#include <collido/runner/time_statistic.h>
#include <collido/study/robustness.h>
#include <collido/study/selection_table.h>

namespace collido::study {
namespace {

/// A measurement with the backend text it came from.
struct Answer {
  std::string backend;
  QueryMeasurement measurement;
};

/// The fastest of `answers` that `admit` lets in, or none.
template <typename Admit>
const Answer* fastest(const std::vector<Answer>& answers, Admit admit) {
  const Answer* best = nullptr;
  for (const Answer& a : answers) {
    if (!admit(a)) continue;
    if (best == nullptr || meanFrameTimeUs(a.measurement) < meanFrameTimeUs(best->measurement))
      best = &a;
  }
  return best;
}

/// Work per truly intersecting pair over every frame, or "-" when not counted or no pair.
std::string perTruePair(const QueryMeasurement& m, bool counted, std::uint64_t FrameRecord::*work) {
  std::uint64_t total = 0;
  std::size_t pairs = 0;
  for (const FrameRecord& f : m.frames) {
    total += f.*work;
    pairs += f.oracle_pairs;
  }
  if (!counted || pairs == 0) return "-";
  return formatNumber("%.1f", static_cast<double>(total) / static_cast<double>(pairs));
}

std::string timeCell(const TimeBootstrap& time, const QueryMeasurement& m) {
  std::string text = withInterval(time.estimate(), time.ci95());
  if (m.disagreements > 0) text += "!";
  return text;
}

// The default sides: the table speaks of the OBB tree by its method's name.
bool isTheObbTree(const FieldSides& sides) {
  return sides.ours == FieldSides{}.ours;
}

// Their time over ours with its interval, paired by frame; "≈" where it meets the band.
std::string ratioCell(const TimeBootstrap& theirs, const TimeBootstrap& ours) {
  const std::optional<Ratio> ratio = timeRatio(theirs, ours);
  if (!ratio) return "-";
  const bool tie = differenceOf(ratio->ci95) == Difference::kSame;
  return (tie ? "≈" : "") + ratioWithInterval(*ratio);
}

// Every setting's answer per (scene, resolution, query), in result order, and the comparator
// families in the order they first appear.
struct FieldAnswers {
  using Key = std::tuple<std::string, double, std::string>;
  std::map<Key, std::vector<Answer>> groups;
  std::vector<Key> order;
  std::vector<std::string> families;
};

FieldAnswers fieldAnswers(const std::vector<CombinationResult>& results,
                          const std::string& ours_family) {
  FieldAnswers field;
  for (const CombinationResult& r : results) {
    const Combination& c = r.combination;
    if (!r.outcome.ok() || !c.category.empty() || c.needs != NeedsMode::kDeclared || c.limit != 0)
      continue;
    const std::string family = backendFamily(c.backend);
    if (family != ours_family &&
        std::find(field.families.begin(), field.families.end(), family) == field.families.end())
      field.families.push_back(family);
    for (const QueryMeasurement& m : tableMeasurements(r)) {
      // Queries over a step are compared in their own table (continuous_table.h).
      if (!m.ok() || queryKindInfo(m.kind).over_a_step) continue;
      const FieldAnswers::Key key{c.scene_name, c.resolution, m.query};
      if (field.groups.find(key) == field.groups.end()) field.order.push_back(key);
      field.groups[key].push_back({c.backend, m});
    }
  }
  return field;
}

// One row: our fastest exact single-thread setting with its figures, then each comparator's
// fastest with its ratio to ours; empty when no other family answered the query.
std::optional<std::vector<std::string>> fieldRow(const FieldAnswers::Key& key,
                                                 const std::vector<Answer>& answers,
                                                 const FieldSides& sides, bool has_peer,
                                                 const std::vector<std::string>& families,
                                                 std::size_t columns) {
  const Answer* ours = fastest(answers, [&](const Answer& a) {
    return backendFamily(a.backend) == sides.ours && a.measurement.disagreements == 0 &&
           runsOnOneThread(a.backend);
  });
  const bool has_comparator = std::any_of(answers.begin(), answers.end(), [&](const Answer& a) {
    return backendFamily(a.backend) != sides.ours;
  });
  if (!has_comparator) return std::nullopt;
  const auto& [scene, resolution, query] = key;
  std::vector<std::string> row = {
      resolution == 1.0 ? scene : scene + " r=" + formatNumber("%g", resolution), query};
  if (ours == nullptr) {
    row.push_back("no exact setting");
    row.resize(columns, "-");
    return row;
  }
  const QueryMeasurement& m = ours->measurement;
  const TimeBootstrap our_time(m);
  row.push_back(ours->backend);
  row.push_back(withInterval(our_time.estimate(), our_time.ci95()));
  row.push_back(bytesPerTriangleText(m.memory_bytes, m.triangles));
  row.push_back(m.floor_ratio ? formatNumber("%.1f", *m.floor_ratio) : "-");
  row.push_back(perTruePair(m, m.counts_bv_tests, &FrameRecord::bv_tests));
  row.push_back(perTruePair(m, m.counts_primitive_tests, &FrameRecord::primitive_tests));
  const auto compare = [&](const Answer* theirs) {
    if (theirs == nullptr) {
      row.insert(row.end(), {"-", "-"});
      return;
    }
    const TimeBootstrap their_time(theirs->measurement);
    row.push_back(timeCell(their_time, theirs->measurement));
    row.push_back(ratioCell(their_time, our_time));
  };
  if (has_peer) compare(fastest(answers, [&](const Answer& a) { return a.backend == sides.peer; }));
  for (const std::string& family : families)
    compare(fastest(answers, [&](const Answer& a) { return backendFamily(a.backend) == family; }));
  return row;
}

std::string fieldLegend(const FieldSides& sides) {
  return "Times are the mean over frames of each frame's median call, in microseconds per query, "
         "with its 95% bootstrap interval [low, high]; a comparator's is its fastest setting's, "
         "and '!' marks one whose answer differed from the oracle's on some frame. 'vs X' = X's "
         "time over " +
         (isTheObbTree(sides) ? std::string("the OBB tree") : sides.ours) +
         "'s, its 95% interval paired by frame; '≈' marks a ratio whose interval meets the " +
         formatNumber("%g", kEquivalenceBand * 100.0) +
         "% equivalence band, a tie (docs/STUDY.md). floor x = query time over one exact triangle "
         "test per truly intersecting pair (1 is the floor); box/pair and tri/pair = box and "
         "triangle tests per truly intersecting pair.\n";
}

}  // namespace

std::string fieldTableTitle(const FieldSides& sides) {
  return (isTheObbTree(sides) ? std::string("The OBB tree") : sides.ours) + " against the field";
}

std::string fieldTable(const std::vector<CombinationResult>& results, const FieldSides& sides) {
  const FieldAnswers field = fieldAnswers(results, sides.ours);
  const bool has_peer = std::any_of(field.groups.begin(), field.groups.end(), [&](const auto& g) {
    return std::any_of(g.second.begin(), g.second.end(),
                       [&](const Answer& a) { return a.backend == sides.peer; });
  });
  std::vector<std::string> header = {"scene",    "query",   sides.ours + " (fastest exact)",
                                     "mean us",  "B/tri",   "floor x",
                                     "box/pair", "tri/pair"};
  if (has_peer) header.insert(header.end(), {sides.peer + " us", "vs " + sides.peer});
  for (const std::string& family : field.families)
    header.insert(header.end(), {family + " us", "vs " + family});
  std::vector<std::vector<std::string>> rows;
  for (const FieldAnswers::Key& key : field.order) {
    std::optional<std::vector<std::string>> row =
        fieldRow(key, field.groups.at(key), sides, has_peer, field.families, header.size());
    if (row) rows.push_back(std::move(*row));
  }
  if (rows.empty()) return "";
  return formatTextTable(header, rows, 3) + fieldLegend(sides);
}

}  // namespace collido::study
