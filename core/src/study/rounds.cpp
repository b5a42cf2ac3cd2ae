#include <collido/study/rounds.h>

#include <algorithm>
#include <map>
#include <optional>
#include <string>
#include <utility>

#include <collido/runner/statistics.h>
#include <collido/runner/time_statistic.h>

namespace collido::study {
namespace {

/// Each frame's calls of `m`, or none where the calls do not divide evenly over its frames.
std::optional<std::vector<std::vector<double>>> framesOf(const QueryMeasurement& m) {
  return splitEvenly(m.times_us, m.frames.size());
}

const QueryMeasurement* sameQuery(const CombinationResult& r, const QueryMeasurement& m) {
  for (const QueryMeasurement& other : r.measurements) {
    if (other.query == m.query) return &other;
  }
  return nullptr;
}

/// Appends `round`'s calls to `joined` (each frame's calls so far), when it answered the same
/// frames with as many calls a frame as round 0.
bool addRound(const QueryMeasurement& round, std::size_t per_frame,
              std::vector<std::vector<double>>& joined) {
  const std::optional<std::vector<std::vector<double>>> calls = framesOf(round);
  if (!round.ok() || !calls || calls->size() != joined.size() || calls->front().size() != per_frame)
    return false;
  for (std::size_t f = 0; f < joined.size(); ++f)
    joined[f].insert(joined[f].end(), (*calls)[f].begin(), (*calls)[f].end());
  return true;
}

void joinInto(CombinationResult& base, const std::vector<const CombinationResult*>& rounds) {
  double wall_s = base.outcome.wall_s;
  std::size_t finished = 1;
  for (const CombinationResult* round : rounds) {
    if (!round->outcome.ok()) {
      base.problems.push_back("round " + std::to_string(round->combination.round + 1) +
                              ": worker " + round->outcome.text());
      continue;
    }
    wall_s += round->outcome.wall_s;
    ++finished;
  }
  base.outcome.wall_s = wall_s / static_cast<double>(finished);
  for (QueryMeasurement& m : base.measurements) {
    std::optional<std::vector<std::vector<double>>> joined = framesOf(m);
    if (!m.ok() || !joined) continue;
    const std::size_t per_frame = joined->front().size();
    std::size_t joined_rounds = 1;
    for (const CombinationResult* round : rounds) {
      const QueryMeasurement* same = round->outcome.ok() ? sameQuery(*round, m) : nullptr;
      if (same != nullptr && addRound(*same, per_frame, *joined)) ++joined_rounds;
    }
    if (joined_rounds == 1) continue;
    m.rounds = joined_rounds;
    m.times_us.clear();
    for (std::size_t f = 0; f < joined->size(); ++f) {
      m.frames[f].median_us = quantile((*joined)[f], 0.5);
      m.times_us.insert(m.times_us.end(), (*joined)[f].begin(), (*joined)[f].end());
    }
    summariseMeasurement(m);
  }
}

}  // namespace

std::vector<CombinationResult> joinRounds(std::vector<CombinationResult> results) {
  std::map<std::string, std::vector<const CombinationResult*>> rounds_of;  // by round 0's id
  for (const CombinationResult& r : results) {
    if (r.combination.round != 0) rounds_of[inRound(r.combination, 0).id].push_back(&r);
  }
  std::vector<CombinationResult> joined;
  for (CombinationResult& r : results) {
    if (r.combination.round != 0) continue;
    if (const auto found = rounds_of.find(r.combination.id); found != rounds_of.end()) {
      std::vector<const CombinationResult*>& rounds = found->second;
      std::sort(rounds.begin(), rounds.end(), [](const auto* a, const auto* b) {
        return a->combination.round < b->combination.round;
      });
      if (r.outcome.ok()) joinInto(r, rounds);
    }
    joined.push_back(std::move(r));
  }
  return joined;
}

}  // namespace collido::study
