#pragma once

#include <string>
#include <vector>

#include <collido/study/result_store.h>

namespace collido::study {

/// "The OBB tree against the field": per scene (and resolution) and query of the ordinary scenes
/// (stress scenes are the robustness matrix's), built as declared, the fastest setting of ours
/// (`sides.ours`, by default the OBB tree) that answered every frame exactly and single-threaded,
/// with its memory, floor ratio and work per truly intersecting pair, against the fastest
/// setting of each other family ("fcl", "bullet", "ode", ...; the peer, by default FCL's OBB
/// tree, also on its own): the comparator's time and the speed-up, comparator time over ours,
/// both from one run. Times are the mean over frames of each frame's median (a scene's run time
/// per query, as benchmarks that cycle the frames report it), where the main table gives
/// quantiles over every call. Empty when the study ran no setting of ours beside a comparator.
std::string fieldTable(const std::vector<CombinationResult>& results, const FieldSides& sides = {});

/// The field table's title: "The OBB tree against the field", or "<ours> against the field".
std::string fieldTableTitle(const FieldSides& sides);

}  // namespace collido::study
