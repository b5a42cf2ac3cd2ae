#pragma once

#include <string>
#include <vector>

#include <collido/study/result_store.h>
#include <collido/study/sweep.h>

namespace collido::study {

/// "Between the frames": the queries asked over a step (first contact), per scene and query,
/// first what to pick: the fastest certified answer (a backend's own continuous answer, not the
/// runner's sub-steps) with no step wrong, against the fastest of the peer's family
/// (`sides.peer`'s, e.g. FCL's conservative advancement), their ratio with its interval; and the
/// fastest discrete setting (sub-steps) that happened to miss nothing here. Then every setting:
/// time per step, the steps the oracle finds touching, those missed and falsely reported, the
/// largest error of the first-contact time, the steps coarser than asked and the wrong
/// brackets. Empty when no such query was measured.
std::string continuousTable(const std::vector<CombinationResult>& results,
                            const FieldSides& sides = {});

}  // namespace collido::study
