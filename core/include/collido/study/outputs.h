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
/// other figures as user counters; readable by compare.py and benchmark dashboards.
std::string benchmarkJson(const std::vector<CombinationResult>& results);

/// The table people read: per (combination, query) time quantiles, error, build and memory; then
/// what building every need costs over the declared ones; then every failure.
std::string studyTable(const std::vector<CombinationResult>& results);

/// Writes records.jsonl, summary.json and table.txt into `directory`, each atomically.
Status writeStudyOutputs(const std::string& directory,
                         const std::vector<CombinationResult>& results);

}  // namespace collido::study
