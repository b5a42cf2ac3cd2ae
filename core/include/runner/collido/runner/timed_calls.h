#pragma once

#include <chrono>
#include <vector>

#include <collido/status.h>

namespace collido {

/// The microseconds one call of `call` took (a callable returning Status), or its failure. Every
/// timed query of every kind of input (mesh scenes, NURBS surface pairs, FRep pairs) is timed
/// through this, so that they all start and stop the clock the same way.
template <typename Call>
Result<double> timeCall(const Call& call) {
  const std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
  if (Status s = call(); !s.ok()) return s;
  return std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start)
      .count();
}

/// The repeated timing protocol (TimingProtocol::kRepeated) on one input: `call` once, untimed
/// (the answer the caller checks; it also warms caches and lazy set-up, which a first timed
/// call would otherwise include), then `repetitions` timed calls. Returns the microseconds of
/// each timed call, or the first failure.
template <typename Call>
Result<std::vector<double>> timeRepeated(int repetitions, const Call& call) {
  if (Status s = call(); !s.ok()) return s;
  std::vector<double> times;
  for (int rep = 0; rep < repetitions; ++rep) {
    Result<double> took = timeCall(call);
    if (!took.ok()) return took.status();
    times.push_back(took.value());
  }
  return times;
}

}  // namespace collido
