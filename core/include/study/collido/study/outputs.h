#pragma once

#include <string>
#include <vector>

#include <collido/status.h>
#include <collido/study/result_store.h>

namespace collido::study {

/// One JSON object per line for every (combination, query, frame): the setting, the answer,
/// its error against the oracle, the frame's median time and work counters.
std::string recordsJsonLines(const std::vector<CombinationResult>& results);

/// A summary in Google Benchmark's JSON output format, one benchmark per (combination, query)
/// named "backend/scene/query[/setting]", real_time = median per query in microseconds, the
/// other figures as user counters; readable by compare.py and benchmark dashboards. With stress
/// scenes, a further top-level key "robustness_matrix" (robustnessJson), which those tools
/// ignore.
std::string benchmarkJson(const std::vector<CombinationResult>& results);

/// The table people read: per (combination, query) time quantiles, error, build and memory; then
/// what building every need costs over the declared ones; then the OBB tree against the field
/// (field_table.h); then the deforming scenes' update and query costs (deform_table.h); then,
/// with stress scenes, the
/// robustness matrix's rates; then every failure. Settings `not_applicable` lists (plan.h) come
/// once, after the table of every setting; `field` names the field table's sides.
std::string studyTable(const std::vector<CombinationResult>& results,
                       const std::vector<NotApplicable>& not_applicable = {},
                       const FieldSides& field = {});

/// robustness.txt: the robustness matrix of the stress scenes (study/robustness.h); empty when
/// the study ran none.
std::string robustnessReport(const std::vector<CombinationResult>& results);

/// Writes records.jsonl, summary.json, times.json (expected_time.h), sections.json and table.txt
/// into `directory`, and robustness.txt when the study ran stress scenes, each atomically; the
/// settings not applicable and the field table's sides come from the folder's plan.json.
/// sections.json holds table.txt's summary sections (what_to_pick, not_applicable, needs, field,
/// contacts, deforming, tracking, robustness; one with nothing to show is left out), each with
/// its title, the heading table.txt prints over it and its text: tools that publish them
/// (tools/publish_results.sh) find them by key, not by a title a sweep can rename.
Status writeStudyOutputs(const std::string& directory,
                         const std::vector<CombinationResult>& results);

}  // namespace collido::study
