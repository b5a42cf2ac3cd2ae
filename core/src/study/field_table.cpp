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

}  // namespace

std::string fieldTableTitle(const FieldSides& sides) {
  return (isTheObbTree(sides) ? std::string("The OBB tree") : sides.ours) + " against the field";
}

std::string fieldTable(const std::vector<CombinationResult>& results, const FieldSides& sides) {
  const std::string& ours_family = sides.ours;
  const std::string& peer = sides.peer;
  // (scene, resolution, query) -> every setting's answer, in result order.
  using Key = std::tuple<std::string, double, std::string>;
  std::map<Key, std::vector<Answer>> groups;
  std::vector<Key> order;
  std::vector<std::string> families;
  for (const CombinationResult& r : results) {
    const Combination& c = r.combination;
    if (!r.outcome.ok() || !c.category.empty() || c.needs != NeedsMode::kDeclared || c.limit != 0)
      continue;
    const std::string family = backendFamily(c.backend);
    if (family != ours_family &&
        std::find(families.begin(), families.end(), family) == families.end())
      families.push_back(family);
    for (const QueryMeasurement& m : tableMeasurements(r)) {
      if (!m.ok()) continue;
      const Key key{c.scene_name, c.resolution, m.query};
      if (groups.find(key) == groups.end()) order.push_back(key);
      groups[key].push_back({c.backend, m});
    }
  }
  const bool has_peer = std::any_of(groups.begin(), groups.end(), [&](const auto& group) {
    return std::any_of(group.second.begin(), group.second.end(),
                       [&](const Answer& a) { return a.backend == peer; });
  });

  std::vector<std::string> header = {"scene",    "query",   ours_family + " (fastest exact)",
                                     "mean us",  "B/tri",   "floor x",
                                     "box/pair", "tri/pair"};
  if (has_peer) {
    header.push_back(peer + " us");
    header.push_back("vs " + peer);
  }
  for (const std::string& family : families) {
    header.push_back(family + " us");
    header.push_back("vs " + family);
  }
  std::vector<std::vector<std::string>> rows;
  for (const Key& key : order) {
    const std::vector<Answer>& answers = groups[key];
    const Answer* ours = fastest(answers, [&](const Answer& a) {
      return backendFamily(a.backend) == ours_family && a.measurement.disagreements == 0 &&
             runsOnOneThread(a.backend);
    });
    const bool has_comparator = std::any_of(answers.begin(), answers.end(), [&](const Answer& a) {
      return backendFamily(a.backend) != ours_family;
    });
    if (!has_comparator) continue;
    const auto& [scene, resolution, query] = key;
    std::vector<std::string> row = {
        resolution == 1.0 ? scene : scene + " r=" + formatNumber("%g", resolution), query};
    if (ours == nullptr) {
      row.push_back("no exact setting");
      row.resize(header.size(), "-");
      rows.push_back(row);
      continue;
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
    if (has_peer) compare(fastest(answers, [&](const Answer& a) { return a.backend == peer; }));
    for (const std::string& family : families) {
      compare(
          fastest(answers, [&](const Answer& a) { return backendFamily(a.backend) == family; }));
    }
    rows.push_back(row);
  }
  if (rows.empty()) return "";
  std::ostringstream out;
  out << formatTextTable(header, rows, 3);
  out << "Times are the mean over frames of each frame's median call, in microseconds per query, "
         "with its 95% bootstrap interval [low, high]; a comparator's is its fastest setting's, "
         "and '!' marks one whose answer differed from the oracle's on some frame. 'vs X' = X's "
         "time over "
      << (isTheObbTree(sides) ? "the OBB tree" : ours_family)
      << "'s, its 95% interval paired by frame; '≈' marks a ratio whose "
         "interval meets the "
      << formatNumber("%g", kEquivalenceBand * 100.0)
      << "% equivalence band, a tie (docs/STUDY.md). floor x = "
         "query time over one exact triangle test per truly intersecting pair (1 is the floor); "
         "box/pair and tri/pair = box and triangle tests per truly intersecting pair.\n";
  return out.str();
}

}  // namespace collido::study
