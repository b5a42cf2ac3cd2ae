// collido merge: the folders of a sharded study joined into one.
#include <algorithm>
#include <filesystem>
#include <map>
#include <optional>
#include <set>

#include <collido/study/driver.h>
#include <collido/study/folder_lock.h>
#include <collido/study/outputs.h>
#include <collido/study/result_store.h>

namespace collido::study {
namespace {

// Whether `folder` holds a study's plan or results.
bool holdsStudy(const std::string& folder) {
  std::error_code ec;
  const std::filesystem::path path(folder);
  return std::filesystem::exists(path / "plan.json", ec) ||
         (std::filesystem::is_directory(path / "results", ec) &&
          !std::filesystem::is_empty(path / "results", ec));
}

bool sameFolder(const std::string& a, const std::string& b) {
  std::error_code ec;
  return std::filesystem::equivalent(a, b, ec) && !ec;
}

std::string describeOrder(const RunOrder& order) {
  return std::to_string(order.rounds) + (order.rounds == 1 ? " round" : " rounds") +
         " in the order of seed " + std::to_string(order.seed);
}

int mergeImpl(const std::string& out_dir, const std::vector<std::string>& inputs, bool replace,
              std::ostream& out, std::ostream& err) {
  std::vector<Combination> plan;
  std::set<std::string> planned;
  std::map<std::string, std::pair<std::string, std::string>> label_source;  // label: id, folder
  std::map<std::string, CombinationResult> results;
  // Every shard lists the whole study's settings not applicable; each pair is kept once.
  std::vector<NotApplicable> not_applicable;
  std::set<std::pair<std::string, std::string>> not_applicable_seen;
  // Shards of one study share their sweep, and so its field sides, and their run order (the
  // rounds and the seed): the merged plan says the order its results were run in.
  FieldSides field;
  std::optional<RunOrder> order;
  std::string order_source;
  for (const std::string& input : inputs) {
    const ResultStore shard(input);
    Result<std::vector<Combination>> shard_plan = shard.readPlan();
    Result<std::vector<CombinationResult>> shard_results = shard.readAll();
    if (!shard_plan.ok() || !shard_results.ok()) {
      err << "error: " << (shard_plan.ok() ? shard_results.status() : shard_plan.status()).message()
          << "\n";
      return 2;
    }
    Result<std::vector<NotApplicable>> shard_not_applicable = shard.readNotApplicable();
    if (!shard_not_applicable.ok()) {
      err << "error: " << shard_not_applicable.status().message() << "\n";
      return 2;
    }
    Result<FieldSides> shard_field = shard.readFieldSides();
    if (!shard_field.ok()) {
      err << "error: " << shard_field.status().message() << "\n";
      return 2;
    }
    field = shard_field.value();
    Result<std::optional<RunOrder>> shard_order = shard.readRunOrder();
    if (!shard_order.ok()) {
      err << "error: " << shard_order.status().message() << "\n";
      return 2;
    }
    if (const std::optional<RunOrder>& o = shard_order.value()) {
      if (order && (order->rounds != o->rounds || order->seed != o->seed)) {
        err << "error: " << input << " ran " << describeOrder(*o) << " and " << order_source
            << " ran " << describeOrder(*order)
            << "; merge only shards of one study (the same --rounds and --order-seed)\n";
        return 2;
      }
      order = o;
      order_source = input;
    }
    for (NotApplicable& n : shard_not_applicable.value()) {
      if (not_applicable_seen.emplace(n.backend, n.scene).second)
        not_applicable.push_back(std::move(n));
    }
    if (shard_plan.value().empty() && shard_results.value().empty()) {
      err << "error: " << input << ": no study here (no plan.json, no results/)\n";
      return 2;
    }
    for (const Combination& c : shard_plan.value()) {
      // A shard's results hold each combination's rounds joined into its round 0.
      if (c.round != 0) continue;
      // Shards of one study share their inputs; the same combination run on other inputs (a
      // scene or plugin changed between shards) would sit beside itself in the table.
      const auto [known, fresh] = label_source.emplace(c.label(), std::make_pair(c.id, input));
      if (!fresh && known->second.first != c.id) {
        err << "error: " << input << " and " << known->second.second << " ran " << c.label()
            << " on different inputs (a scene file, mesh, plugin or the repetitions "
               "changed between them); merge only shards of one study\n";
        return 2;
      }
      if (planned.insert(c.id).second) plan.push_back(c);
    }
    for (CombinationResult& r : shard_results.value()) {
      if (planned.insert(r.combination.id).second) plan.push_back(r.combination);
      const auto existing = results.find(r.combination.id);
      // The same combination in two inputs: keep a finished run over a failed one.
      if (existing == results.end() || (!existing->second.outcome.ok() && r.outcome.ok())) {
        results[r.combination.id] = std::move(r);
      }
    }
  }
  // A folder that holds another study would keep its results beside the merged ones: the table
  // would then count combinations of neither input.
  Result<FolderLock> lock = FolderLock::acquire(out_dir);
  if (!lock.ok()) {
    err << "error: " << lock.status().message() << "\n";
    return 2;
  }
  const bool out_is_input =
      std::any_of(inputs.begin(), inputs.end(),
                  [&out_dir](const std::string& in) { return sameFolder(in, out_dir); });
  if (holdsStudy(out_dir) && !out_is_input) {
    if (!replace) {
      err << "error: " << out_dir
          << " already holds a study; merge into a new folder, or pass --replace to "
             "replace what it holds\n";
      return 2;
    }
    std::error_code ec;
    for (const char* stale : {"results", "plan.json", "robustness.txt"})
      std::filesystem::remove_all(std::filesystem::path(out_dir) / stale, ec);
  }
  const ResultStore store(out_dir);
  if (Status s = store.prepare(); !s.ok()) {
    err << "error: " << s.message() << "\n";
    return 2;
  }
  // In plan order, as a study's own outputs are (ResultStore::readAll), not in id order.
  std::vector<CombinationResult> merged;
  for (const Combination& c : plan) {
    const auto found = results.find(c.id);
    if (found == results.end()) continue;
    if (Status s = store.write(found->second); !s.ok()) {
      err << "error: " << s.message() << "\n";
      return 2;
    }
    merged.push_back(found->second);
  }
  if (Status s = store.writePlan(plan, not_applicable, order, field); !s.ok()) {
    err << "error: " << s.message() << "\n";
    return 2;
  }
  if (Status s = writeStudyOutputs(out_dir, merged); !s.ok()) {
    err << "error: " << s.message() << "\n";
    return 2;
  }
  out << studyTable(merged, not_applicable, field);
  const std::size_t missing = plan.size() - merged.size();
  err << "merged " << merged.size() << " of " << plan.size() << " planned combinations into "
      << out_dir << (missing != 0 ? " (" + std::to_string(missing) + " not run yet)" : "") << "\n";
  return 0;
}

}  // namespace

int mergeStudies(const std::string& out_dir, const std::vector<std::string>& inputs, bool replace,
                 std::ostream& out, std::ostream& err) {
  return mergeImpl(out_dir, inputs, replace, out, err);
}

}  // namespace collido::study
