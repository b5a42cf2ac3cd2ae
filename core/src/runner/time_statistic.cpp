#include <collido/runner/time_statistic.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <memory>
#include <mutex>
#include <random>
#include <tuple>

#include <collido/runner/statistics.h>
#include <collido/runner/text_table.h>

namespace collido {
namespace {

// FNV-1a over the times' bytes: the same measurement seeds the same call draws, and two
// measurements seed different ones.
std::uint64_t seedOf(const std::vector<std::vector<double>>& calls) {
  std::uint64_t hash = 14695981039346656037ull;
  for (const std::vector<double>& frame : calls) {
    for (const double t : frame) {
      unsigned char bytes[sizeof t];
      std::memcpy(bytes, &t, sizeof t);
      for (const unsigned char b : bytes) {
        hash ^= b;
        hash *= 1099511628211ull;
      }
    }
  }
  return hash;
}

// The median of `values` (type 7, as quantile(values, 0.5)); reorders them.
double medianInPlace(std::vector<double>& values) {
  const std::size_t k = values.size();
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(k / 2);
  std::nth_element(values.begin(), middle, values.end());
  if (k % 2 == 1) return *middle;
  const double below = *std::max_element(values.begin(), middle);
  return (below + *middle) / 2.0;
}

Interval percentileInterval(const std::vector<double>& values) {
  return {quantile(values, 0.025), quantile(values, 0.975)};
}

bool sameMedian(const std::vector<double>& calls, double median) {
  const double of_calls = quantile(calls, 0.5);
  return std::abs(of_calls - median) <= 1e-9 * std::max(1.0, std::abs(median));
}

}  // namespace

double meanFrameTimeUs(const QueryMeasurement& m) {
  if (m.frames.empty()) return 0.0;
  double total = 0.0;
  for (const FrameRecord& f : m.frames)
    total += f.median_us;
  return total / static_cast<double>(m.frames.size());
}

std::optional<std::vector<std::vector<double>>> splitEvenly(const std::vector<double>& values,
                                                            std::size_t parts) {
  if (parts == 0 || values.empty() || values.size() % parts != 0) return std::nullopt;
  const std::size_t length = values.size() / parts;
  std::vector<std::vector<double>> runs(parts);
  for (std::size_t i = 0; i < parts; ++i) {
    const auto first = values.begin() + static_cast<std::ptrdiff_t>(i * length);
    runs[i].assign(first, first + static_cast<std::ptrdiff_t>(length));
  }
  return runs;
}

std::vector<std::vector<double>> callsPerFrame(const QueryMeasurement& m) {
  std::vector<std::vector<double>> calls =
      splitEvenly(m.times_us, m.frames.size())
          .value_or(std::vector<std::vector<double>>(m.frames.size()));
  for (std::size_t f = 0; f < calls.size(); ++f) {
    if (calls[f].empty() || !sameMedian(calls[f], m.frames[f].median_us))
      calls[f] = {m.frames[f].median_us};
  }
  return calls;
}

TimeBootstrap::TimeBootstrap(const QueryMeasurement& m)
    : TimeBootstrap(callsPerFrame(m), m.rounds) {}

namespace {

// The replicates of `calls` (TimeBootstrap's doc says how they are drawn).
std::vector<double> drawReplicates(const std::vector<std::vector<double>>& calls,
                                   std::size_t rounds, std::uint64_t seed) {
  const std::size_t frames = calls.size();
  if (frames == 0) return std::vector<double>(TimeBootstrap::kReplicates, 0.0);
  // Rounds resampled only where every frame's calls divide into them evenly.
  const bool by_round = rounds > 1 && std::all_of(calls.begin(), calls.end(), [&](const auto& f) {
                          return !f.empty() && f.size() % rounds == 0;
                        });
  if (!by_round) rounds = 1;
  // The frames drawn depend on their count alone (pairing, above); rounds and calls on the times.
  std::mt19937_64 frame_draws(0x5EEDF4A3E5ull ^ frames);
  std::mt19937_64 call_draws(seed);
  std::uniform_int_distribution<std::size_t> pick_frame(0, frames - 1);
  std::uniform_int_distribution<std::size_t> pick_round(0, rounds - 1);
  std::vector<std::size_t> drawn_rounds(rounds);
  std::vector<double> pool;
  std::vector<double> drawn;
  std::vector<double> replicates;
  replicates.reserve(TimeBootstrap::kReplicates);
  for (int r = 0; r < TimeBootstrap::kReplicates; ++r) {
    for (std::size_t& round : drawn_rounds)
      round = rounds == 1 ? 0 : pick_round(call_draws);
    double total = 0.0;
    for (std::size_t i = 0; i < frames; ++i) {
      const std::vector<double>& frame = calls[pick_frame(frame_draws)];
      if (frame.size() <= 1) {
        total += frame.empty() ? 0.0 : frame.front();
        continue;
      }
      // This frame's calls from the rounds drawn, then drawn again call by call.
      const std::size_t per_round = frame.size() / rounds;
      pool.clear();
      for (const std::size_t round : drawn_rounds) {
        const auto first = frame.begin() + static_cast<std::ptrdiff_t>(round * per_round);
        pool.insert(pool.end(), first, first + static_cast<std::ptrdiff_t>(per_round));
      }
      std::uniform_int_distribution<std::size_t> pick_call(0, pool.size() - 1);
      drawn.resize(pool.size());
      for (double& d : drawn)
        d = pool[pick_call(call_draws)];
      total += medianInPlace(drawn);
    }
    replicates.push_back(total / static_cast<double>(frames));
  }
  return replicates;
}

// Replicates drawn before in this process, by what they were drawn from: one output pass asks
// for a measurement's interval from several tables, and each draw is thousands of medians.
using DrawKey = std::tuple<std::uint64_t, std::size_t, std::size_t, std::size_t>;
constexpr std::size_t kMemoLimit = 20000;

std::shared_ptr<const std::vector<double>> memoisedReplicates(
    const std::vector<std::vector<double>>& calls, std::size_t rounds) {
  static std::mutex mutex;
  static std::map<DrawKey, std::shared_ptr<const std::vector<double>>> memo;
  std::size_t count = 0;
  for (const std::vector<double>& frame : calls)
    count += frame.size();
  const std::uint64_t seed = seedOf(calls);
  const DrawKey key{seed, calls.size(), rounds, count};
  {
    const std::lock_guard<std::mutex> lock(mutex);
    if (const auto found = memo.find(key); found != memo.end()) return found->second;
  }
  auto drawn = std::make_shared<const std::vector<double>>(drawReplicates(calls, rounds, seed));
  const std::lock_guard<std::mutex> lock(mutex);
  if (memo.size() >= kMemoLimit) memo.clear();
  memo.emplace(key, drawn);
  return drawn;
}

}  // namespace

TimeBootstrap::TimeBootstrap(const std::vector<std::vector<double>>& calls, std::size_t rounds)
    : replicates_(memoisedReplicates(calls, rounds)) {
  for (const std::vector<double>& frame : calls)
    estimate_ += frame.empty() ? 0.0 : quantile(frame, 0.5);
  if (!calls.empty()) estimate_ /= static_cast<double>(calls.size());
}

namespace {

// Each round's statistic: the mean over frames of the median of that round's calls; none where
// the calls do not divide evenly into the rounds.
std::optional<std::vector<double>> roundMeans(const QueryMeasurement& m) {
  const std::size_t rounds = m.rounds;
  if (rounds < 2) return std::nullopt;
  const std::vector<std::vector<double>> calls = callsPerFrame(m);
  if (calls.empty()) return std::nullopt;
  std::vector<double> means(rounds, 0.0);
  for (const std::vector<double>& frame : calls) {
    const std::optional<std::vector<std::vector<double>>> by_round = splitEvenly(frame, rounds);
    if (!by_round) return std::nullopt;
    for (std::size_t r = 0; r < rounds; ++r)
      means[r] += quantile((*by_round)[r], 0.5);
  }
  for (double& mean : means)
    mean /= static_cast<double>(calls.size());
  return means;
}

// Student's t, two-sided 95%, for `df` degrees of freedom (the normal's beyond the table).
double studentT95(std::size_t df) {
  static constexpr double kTable[] = {12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306,
                                      2.262,  2.228, 2.201, 2.179, 2.160, 2.145, 2.131, 2.120,
                                      2.110,  2.101, 2.093, 2.086, 2.080, 2.074, 2.069, 2.064,
                                      2.060,  2.056, 2.052, 2.048, 2.045, 2.042};
  constexpr std::size_t kRows = sizeof kTable / sizeof kTable[0];
  return df >= 1 && df <= kRows ? kTable[df - 1] : 1.960;
}

}  // namespace

std::optional<double> roundSpread(const QueryMeasurement& m) {
  const std::optional<std::vector<double>> means = roundMeans(m);
  if (!means) return std::nullopt;
  const auto [low, high] = std::minmax_element(means->begin(), means->end());
  if (*low <= 0.0) return std::nullopt;
  return *high / *low;
}

std::optional<double> roundHalfWidth(const QueryMeasurement& m) {
  const std::optional<std::vector<double>> means = roundMeans(m);
  if (!means) return std::nullopt;
  const auto n = static_cast<double>(means->size());
  double mean = 0.0;
  for (const double x : *means)
    mean += x / n;
  if (mean <= 0.0) return std::nullopt;
  double squares = 0.0;
  for (const double x : *means)
    squares += (x - mean) * (x - mean);
  const double standard_error = std::sqrt(squares / (n - 1.0) / n);
  return studentT95(means->size() - 1) * standard_error / mean;
}

bool unstable(const QueryMeasurement& m) {
  const std::optional<double> half_width = roundHalfWidth(m);
  return half_width && *half_width > kEquivalenceBand;
}

Interval TimeBootstrap::ci95() const {
  return percentileInterval(*replicates_);
}

std::optional<Ratio> timeRatio(const TimeBootstrap& numerator, const TimeBootstrap& denominator) {
  if (denominator.estimate() <= 0.0) return std::nullopt;
  const std::vector<double>& top = numerator.replicates();
  const std::vector<double>& bottom = denominator.replicates();
  std::vector<double> ratios(top.size());
  for (std::size_t r = 0; r < top.size(); ++r) {
    if (bottom[r] <= 0.0) return std::nullopt;
    ratios[r] = top[r] / bottom[r];
  }
  return Ratio{numerator.estimate() / denominator.estimate(), percentileInterval(ratios)};
}

Difference differenceOf(const Interval& ratio, double band) {
  if (ratio.lo > 1.0 + band) return Difference::kClearlyMore;
  if (ratio.hi < 1.0 / (1.0 + band)) return Difference::kClearlyLess;
  return Difference::kSame;
}

std::string withInterval(double value, const Interval& ci) {
  return formatNumber("%.1f", value) + " [" + formatNumber("%.1f", ci.lo) + ", " +
         formatNumber("%.1f", ci.hi) + "]";
}

std::string ratioWithInterval(const Ratio& ratio) {
  if (ratio.ci95.lo == ratio.ci95.hi) return formatNumber("%.2f", ratio.value) + "x";
  return formatNumber("%.2f", ratio.value) + "x [" + formatNumber("%.2f", ratio.ci95.lo) + ", " +
         formatNumber("%.2f", ratio.ci95.hi) + "]";
}

}  // namespace collido
