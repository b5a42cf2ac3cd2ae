#pragma once

#include <vector>

#include <collido/study/result_store.h>

namespace collido::study {

/// Joins each mesh combination's timing rounds (Combination::round) into its round 0's result:
/// every query's timed calls from every round that answered it over the same frames, each
/// frame's calls round after round (QueryMeasurement::rounds counts them), each frame's median
/// over them all, and the summary statistics made again. The answers, memory and build figures
/// stay round 0's (every round's answers were checked against the oracle in its own worker); a
/// later round that failed is named in the result's problems. The wall time becomes the mean
/// over the rounds that finished, the time of one worker as the expected time counts it.
/// Rounds whose round 0 is not stored yet are left out.
std::vector<CombinationResult> joinRounds(std::vector<CombinationResult> results);

}  // namespace collido::study
