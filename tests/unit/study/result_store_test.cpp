// The study folder: atomic writes, stored results and plans, and the measurement JSON they hold.
#include <collido/study/result_store.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <collido/io/files.h>
#include <collido/runner/measurement_json.h>

#include "record_fields_walk.h"
#include "study_test_data.h"
#include "support/test_paths.h"

namespace collido::study {
namespace {

namespace fs = std::filesystem;

std::string readText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::vector<std::string> filesIn(const std::string& folder) {
  std::vector<std::string> names;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder))
    names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

// Walks record_fields.h's declarations: every stored field, summary figure and frame field
// survives, and the samples set every stored field, so a new one needs a value here first.
TEST(MeasurementJson, RoundTripsEveryField) {
  const std::vector<QueryMeasurement> samples = {
      testdata::pairsMeasurement("obbtree", true), testdata::pairsMeasurement("fcl:obb", false),
      testdata::booleanMeasurement("ode"), testdata::skippedMeasurement("ode"),
      testdata::everyFieldMeasurement("obbtree")};
  EXPECT_EQ(testdata::fieldsLeftAtDefault(samples), std::vector<std::string>{});
  for (const QueryMeasurement& m : samples) {
    SCOPED_TRACE(m.backend + " " + m.query);
    const Result<QueryMeasurement> back = measurementFromJson(measurementToJson(m));
    ASSERT_TRUE(back.ok()) << back.status().message();
    testdata::expectSameDeclaredFields(back.value(), m);
    // Through text as well: doubles survive nlohmann's shortest round-trip form.
    const Result<QueryMeasurement> reparsed =
        measurementFromJson(nlohmann::json::parse(measurementToJson(m).dump()));
    ASSERT_TRUE(reparsed.ok()) << reparsed.status().message();
    testdata::expectSameDeclaredFields(reparsed.value(), m);
  }
}

TEST(MeasurementJson, OptionalFieldsStayEmpty) {
  const QueryMeasurement m = testdata::pairsMeasurement("fcl:obb", false);
  const nlohmann::json json = measurementToJson(m);
  EXPECT_TRUE(json.at("heap_bytes").is_null());
  EXPECT_TRUE(json.at("heap_peak_bytes").is_null());
  EXPECT_TRUE(json.at("heap_allocations").is_null());
  EXPECT_TRUE(json.at("finest_disagreements").is_null());
  EXPECT_TRUE(json.at("frames").at(0).at("finest_intersecting").is_null());
  EXPECT_TRUE(json.at("frames").at(0).at("bv_tests").is_null());  // not counted
  EXPECT_EQ(json.at("timed_calls"), m.times_us.size());
  // Absent keys read as empty too (an older or hand-written record).
  nlohmann::json trimmed = json;
  for (const char* key : {"heap_bytes", "heap_peak_bytes", "heap_allocations", "heap_probe",
                          "finest_disagreements", "counts_bv_tests", "counts_primitive_tests"})
    trimmed.erase(key);
  const Result<QueryMeasurement> back = measurementFromJson(trimmed);
  ASSERT_TRUE(back.ok()) << back.status().message();
  EXPECT_FALSE(back.value().heap_bytes.has_value());
  EXPECT_FALSE(back.value().finest_disagreements.has_value());
  EXPECT_EQ(back.value().heap_probe, "");
}

TEST(MeasurementJson, DerivedFiguresAreRecomputed) {
  const QueryMeasurement m = testdata::pairsMeasurement("obbtree", true);
  nlohmann::json json = measurementToJson(m);
  // A file that contradicts its own records: the records win.
  json["median_us"] = 1e9;
  json["p90_us"] = -1;
  json["max_us"] = 0;
  json["disagreements"] = 99;
  json["false_negatives"] = 42;
  json["recall"] = 0.0;
  json["precision"] = 0.0;
  json["finest_disagreements"] = 17;
  json["frames"][1]["disagrees"] = false;
  const Result<QueryMeasurement> back = measurementFromJson(json);
  ASSERT_TRUE(back.ok()) << back.status().message();
  testdata::expectSameDeclaredFields(back.value(), m);
  EXPECT_EQ(back.value().median_us, 20.0);
  EXPECT_EQ(back.value().max_us, 40.0);
  EXPECT_EQ(back.value().disagreements, 1u);
  EXPECT_EQ(back.value().false_negatives, 1u);
  EXPECT_EQ(back.value().finest_disagreements, 1u);
  EXPECT_DOUBLE_EQ(back.value().recall, 0.6);
  EXPECT_DOUBLE_EQ(back.value().precision, 1.0);
}

TEST(MeasurementJson, MissingOrMistypedFieldsAreErrors) {
  const nlohmann::json good = measurementToJson(testdata::pairsMeasurement("obbtree", true));
  for (const char* key : {"backend", "scene", "query", "kind", "status", "build_ms", "triangles",
                          "memory_bytes", "times_us", "frames"}) {
    nlohmann::json bad = good;
    bad.erase(key);
    const Result<QueryMeasurement> m = measurementFromJson(bad);
    ASSERT_FALSE(m.ok()) << "accepted without " << key;
    EXPECT_NE(m.status().message().find(key), std::string::npos) << m.status().message();
  }
  nlohmann::json bad_kind = good;
  bad_kind["kind"] = "nearest";
  const Result<QueryMeasurement> kind = measurementFromJson(bad_kind);
  ASSERT_FALSE(kind.ok());
  EXPECT_NE(kind.status().message().find("nearest"), std::string::npos);
  nlohmann::json bad_frame = good;
  bad_frame["frames"][0].erase("truncated");
  EXPECT_FALSE(measurementFromJson(bad_frame).ok());
  nlohmann::json bad_type = good;
  bad_type["triangles"] = "many";
  EXPECT_FALSE(measurementFromJson(bad_type).ok());
}

TEST(ResultJson, RoundTripsOutcomeMeasurementsAndProblems) {
  CombinationResult r = testdata::okResult(testdata::combination("obbtree"));
  r.backend_rss_bytes = 3u * 1024u * 1024u;
  const Result<CombinationResult> back = resultFromJson(resultToJson(r), "label.json");
  ASSERT_TRUE(back.ok()) << back.status().message();
  EXPECT_EQ(back.value().combination.id, r.combination.id);
  EXPECT_EQ(back.value().outcome.status, WorkerStatus::kOk);
  EXPECT_EQ(back.value().outcome.wall_s, r.outcome.wall_s);
  EXPECT_EQ(back.value().outcome.peak_rss_bytes, r.outcome.peak_rss_bytes);
  EXPECT_EQ(back.value().backend_rss_bytes, r.backend_rss_bytes);
  EXPECT_EQ(back.value().residentBytes(), 3u * 1024u * 1024u);
  EXPECT_EQ(back.value().problems, r.problems);
  ASSERT_EQ(back.value().measurements.size(), r.measurements.size());
  for (std::size_t i = 0; i < r.measurements.size(); ++i)
    testdata::expectSameDeclaredFields(back.value().measurements[i], r.measurements[i]);

  const CombinationResult crashed = testdata::crashedResult(testdata::combination("fcl:obb"));
  const Result<CombinationResult> crash = resultFromJson(resultToJson(crashed), "label.json");
  ASSERT_TRUE(crash.ok()) << crash.status().message();
  EXPECT_EQ(crash.value().outcome.status, WorkerStatus::kCrashed);
  EXPECT_EQ(crash.value().outcome.signal, crashed.outcome.signal);
  EXPECT_EQ(crash.value().outcome.signal_name, "SIGSEGV");
  EXPECT_EQ(crash.value().outcome.log_tail, crashed.outcome.log_tail);
  EXPECT_TRUE(crash.value().measurements.empty());
}

TEST(ResultJson, ErrorsNameTheLabel) {
  const nlohmann::json good = resultToJson(testdata::okResult(testdata::combination("obbtree")));
  nlohmann::json not_ours = good;
  not_ours.erase("collidoscope_combination");
  const Result<CombinationResult> a = resultFromJson(not_ours, "r/a.json");
  ASSERT_FALSE(a.ok());
  EXPECT_EQ(a.status().message().rfind("r/a.json: ", 0), 0u) << a.status().message();
  nlohmann::json no_outcome = good;
  no_outcome.erase("outcome");
  const Result<CombinationResult> b = resultFromJson(no_outcome, "r/b.json");
  ASSERT_FALSE(b.ok());
  EXPECT_EQ(b.status().message().rfind("r/b.json: ", 0), 0u) << b.status().message();
  nlohmann::json bad_measurement = good;
  bad_measurement["measurements"][0].erase("frames");
  const Result<CombinationResult> c = resultFromJson(bad_measurement, "r/c.json");
  ASSERT_FALSE(c.ok());
  EXPECT_EQ(c.status().message().rfind("r/c.json: ", 0), 0u) << c.status().message();
  nlohmann::json bad_combination = good;
  bad_combination["combination"]["needs"] = "some";
  EXPECT_FALSE(resultFromJson(bad_combination, "r/d.json").ok());
  // "r/e.json: /outcome/status: unknown worker status \"exploded\""
  nlohmann::json bad_status = good;
  bad_status["outcome"]["status"] = "exploded";
  const Result<CombinationResult> e = resultFromJson(bad_status, "r/e.json");
  ASSERT_FALSE(e.ok());
  EXPECT_EQ(e.status().message(), "r/e.json: /outcome/status: unknown worker status \"exploded\"");
}

TEST(WriteFileAtomically, ReplacesTheFileAndLeavesNoPartialFile) {
  const std::string dir = test::makeTempDirectory("atomic");
  const std::string path = dir + "/out.json";
  ASSERT_TRUE(io::writeFileAtomically(path, "first").ok());
  EXPECT_EQ(readText(path), "first");
  ASSERT_TRUE(io::writeFileAtomically(path, "second, longer").ok());
  EXPECT_EQ(readText(path), "second, longer");
  ASSERT_TRUE(io::writeFileAtomically(path, "").ok());
  EXPECT_EQ(readText(path), "");
  EXPECT_EQ(filesIn(dir), (std::vector<std::string>{"out.json"}));
  EXPECT_FALSE(fs::exists(path + ".partial"));
}

/// Runs `body` in a child process whose files cannot grow past `limit_bytes` (RLIMIT_FSIZE), and
/// returns its wait status. Past the limit a write fails with EFBIG (a full disk), or, with
/// `killed_at_limit`, the child dies of SIGXFSZ in the middle of the write, as a study killed
/// mid-write would.
int runWithFileSizeLimit(rlim_t limit_bytes, bool killed_at_limit,
                         const std::function<int()>& body) {
  const pid_t pid = fork();
  if (pid == 0) {
    std::signal(SIGXFSZ, killed_at_limit ? SIG_DFL : SIG_IGN);
    const rlimit limit{limit_bytes, limit_bytes};
    if (setrlimit(RLIMIT_FSIZE, &limit) != 0) _exit(125);
    _exit(body());
  }
  int status = 0;
  waitpid(pid, &status, 0);
  return status;
}

// A write that fails half-way (the disk full after 4 KiB of 64) leaves the previous file as it
// was, and removes its temporary:
// "<dir>/out.json.partial.<host>.<pid>.<n>: cannot be written: File too large"
TEST(WriteFileAtomically, AFailedWriteLeavesThePreviousFileAndNoTemporary) {
  const std::string dir = test::makeTempDirectory("atomic_full");
  const std::string path = dir + "/out.json";
  ASSERT_TRUE(io::writeFileAtomically(path, "previous").ok());
  const int status = runWithFileSizeLimit(4096, false, [&] {
    const Status s = io::writeFileAtomically(path, std::string(64 * 1024, 'x'));
    std::ofstream(dir + "/message.txt") << s.message();
    return s.ok() ? 0 : 1;
  });
  ASSERT_TRUE(WIFEXITED(status)) << status;
  EXPECT_EQ(WEXITSTATUS(status), 1);
  EXPECT_EQ(readText(path), "previous");
  EXPECT_EQ(filesIn(dir), (std::vector<std::string>{"message.txt", "out.json"}));
  const std::string message = readText(dir + "/message.txt");
  EXPECT_NE(message.find(path + ".partial."), std::string::npos) << message;
  EXPECT_NE(message.find("cannot be written: File too large"), std::string::npos) << message;
}

// A writer killed in the middle of the write leaves the previous file whole; what it had
// written is only in its temporary, which no reader takes for the file.
TEST(WriteFileAtomically, AWriterKilledMidWriteLeavesThePreviousFile) {
  const std::string dir = test::makeTempDirectory("atomic_killed");
  const std::string path = dir + "/out.json";
  ASSERT_TRUE(io::writeFileAtomically(path, "previous").ok());
  const int status = runWithFileSizeLimit(4096, true, [&] {
    return io::writeFileAtomically(path, std::string(64 * 1024, 'x')).ok() ? 0 : 1;
  });
  ASSERT_TRUE(WIFSIGNALED(status)) << status;
  EXPECT_EQ(WTERMSIG(status), SIGXFSZ);
  EXPECT_EQ(readText(path), "previous");
  for (const std::string& name : filesIn(dir)) {
    EXPECT_TRUE(name == "out.json" || name.rfind("out.json.partial.", 0) == 0) << name;
  }
}

// A study killed while storing a combination's result has no result for it (so --resume runs it
// again), and the results it stored before stay readable.
TEST(ResultStore, AStudyKilledWhileWritingAResultStoresNothingHalfWritten) {
  const std::string dir = test::makeTempDirectory("store_killed");
  const ResultStore store(dir);
  ASSERT_TRUE(store.prepare().ok());
  const Combination kept = testdata::combination("aa");
  const Combination cut = testdata::combination("zz");
  ASSERT_TRUE(store.write(testdata::okResult(kept)).ok());
  const std::string kept_text = readText(store.resultPath(kept.id));
  const int status = runWithFileSizeLimit(
      64, true, [&] { return store.write(testdata::okResult(cut)).ok() ? 0 : 1; });
  ASSERT_TRUE(WIFSIGNALED(status)) << status;
  EXPECT_EQ(WTERMSIG(status), SIGXFSZ);
  EXPECT_FALSE(store.has(cut.id));
  EXPECT_EQ(readText(store.resultPath(kept.id)), kept_text);
  const Result<std::vector<CombinationResult>> all = store.readAll();
  ASSERT_TRUE(all.ok()) << all.status().message();
  ASSERT_EQ(all.value().size(), 1u);
  EXPECT_EQ(all.value()[0].combination.id, kept.id);
}

TEST(WriteFileAtomically, FailsWithTheFileNamedWhenTheFolderIsMissing) {
  const std::string dir = test::makeTempDirectory("atomic_missing");
  const std::string path = dir + "/no/such/folder/out.json";
  const Status s = io::writeFileAtomically(path, "text");
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find(path), std::string::npos) << s.message();
  EXPECT_TRUE(filesIn(dir).empty());
}

TEST(ResultStore, WritesHasAndReadsBackInPlanOrder) {
  const std::string dir = test::makeTempDirectory("store") + "/study";
  const ResultStore store(dir);
  ASSERT_TRUE(store.prepare().ok());
  for (const char* sub : {"results", "logs", "scratch"})
    EXPECT_TRUE(fs::is_directory(dir + "/" + sub)) << sub;
  EXPECT_EQ(store.resultPath("x~1"), dir + "/results/x~1.json");
  EXPECT_EQ(store.logPath("x~1"), dir + "/logs/x~1.log");
  EXPECT_EQ(store.scratchPath("x~1"), dir + "/scratch/x~1.json");

  // Ids in reverse alphabetical order, so plan order and file order differ.
  std::vector<Combination> plan = {testdata::combination("zz"), testdata::combination("mm"),
                                   testdata::combination("aa")};
  ASSERT_TRUE(plan[0].id > plan[1].id && plan[1].id > plan[2].id);
  const Result<std::vector<Combination>> none = store.readPlan();
  ASSERT_TRUE(none.ok());
  EXPECT_TRUE(none.value().empty());
  ASSERT_TRUE(store.writePlan(plan).ok());
  const Result<std::vector<Combination>> stored_plan = store.readPlan();
  ASSERT_TRUE(stored_plan.ok()) << stored_plan.status().message();
  ASSERT_EQ(stored_plan.value().size(), 3u);
  for (std::size_t i = 0; i < plan.size(); ++i)
    EXPECT_EQ(stored_plan.value()[i].id, plan[i].id);

  EXPECT_FALSE(store.has(plan[0].id));
  ASSERT_TRUE(store.write(testdata::okResult(plan[2])).ok());
  ASSERT_TRUE(store.write(testdata::crashedResult(plan[0])).ok());
  EXPECT_TRUE(store.has(plan[0].id));
  EXPECT_FALSE(store.has(plan[1].id));
  EXPECT_TRUE(store.has(plan[2].id));
  // A result outside the plan (e.g. from an older plan) comes last.
  const Combination stray = testdata::combination("00");
  ASSERT_TRUE(store.write(testdata::okResult(stray)).ok());
  // A half-written file of a killed study is not a result.
  test::writeFile(store.resultPath(plan[1].id) + ".partial", "{\"collidosc");

  const Result<std::vector<CombinationResult>> all = store.readAll();
  ASSERT_TRUE(all.ok()) << all.status().message();
  ASSERT_EQ(all.value().size(), 3u);
  EXPECT_EQ(all.value()[0].combination.id, plan[0].id);
  EXPECT_EQ(all.value()[0].outcome.status, WorkerStatus::kCrashed);
  EXPECT_EQ(all.value()[1].combination.id, plan[2].id);
  EXPECT_EQ(all.value()[1].outcome.status, WorkerStatus::kOk);
  EXPECT_EQ(all.value()[1].measurements.size(), 3u);
  EXPECT_EQ(all.value()[2].combination.id, stray.id);
}

TEST(ResultStore, ThePlanKeepsItsRunOrderOrSaysNone) {
  const std::string dir = test::makeTempDirectory("store_order");
  const ResultStore store(dir);
  ASSERT_TRUE(store.prepare().ok());
  const Result<std::optional<RunOrder>> no_plan = store.readRunOrder();
  ASSERT_TRUE(no_plan.ok());
  EXPECT_FALSE(no_plan.value().has_value());

  const std::vector<Combination> plan = {testdata::combination("aa")};
  ASSERT_TRUE(store.writePlan(plan, {}, RunOrder{3, 12345678901234ULL}).ok());
  const Result<std::optional<RunOrder>> kept = store.readRunOrder();
  ASSERT_TRUE(kept.ok()) << kept.status().message();
  ASSERT_TRUE(kept.value().has_value());
  EXPECT_EQ(kept.value()->rounds, 3);
  EXPECT_EQ(kept.value()->seed, 12345678901234ULL);

  ASSERT_TRUE(store.writePlan(plan, {}, std::nullopt).ok());
  const Result<std::optional<RunOrder>> unknown = store.readRunOrder();
  ASSERT_TRUE(unknown.ok());
  EXPECT_FALSE(unknown.value().has_value());

  test::writeFile(dir + "/plan.json",
                  R"({"collidoscope_plan": 1, "combinations": [], "order": {"rounds": 0}})");
  const Result<std::optional<RunOrder>> bad = store.readRunOrder();
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.status().message().find(dir + "/plan.json: /order"), std::string::npos)
      << bad.status().message();
}

TEST(ResultStore, ReadAllWithoutAPlanIsInIdOrder) {
  const ResultStore store(test::makeTempDirectory("store_noplan"));
  ASSERT_TRUE(store.prepare().ok());
  for (const char* backend : {"mm", "zz", "aa"})
    ASSERT_TRUE(store.write(testdata::okResult(testdata::combination(backend))).ok());
  const Result<std::vector<CombinationResult>> all = store.readAll();
  ASSERT_TRUE(all.ok()) << all.status().message();
  ASSERT_EQ(all.value().size(), 3u);
  EXPECT_LT(all.value()[0].combination.id, all.value()[1].combination.id);
  EXPECT_LT(all.value()[1].combination.id, all.value()[2].combination.id);
}

TEST(ResultStore, EmptyOrMissingFolderHasNothing) {
  const ResultStore store(test::makeTempDirectory("store_empty") + "/not_made");
  const Result<std::vector<CombinationResult>> all = store.readAll();
  ASSERT_TRUE(all.ok());
  EXPECT_TRUE(all.value().empty());
  const Result<std::vector<Combination>> plan = store.readPlan();
  ASSERT_TRUE(plan.ok());
  EXPECT_TRUE(plan.value().empty());
  EXPECT_FALSE(store.has("anything"));
}

TEST(ResultStore, UnreadableFilesAreErrorsNamingTheFile) {
  const std::string dir = test::makeTempDirectory("store_bad");
  const ResultStore store(dir);
  ASSERT_TRUE(store.prepare().ok());
  ASSERT_TRUE(store.write(testdata::okResult(testdata::combination("obbtree"))).ok());
  test::writeFile(dir + "/results/broken.json", "{ not json");
  const Result<std::vector<CombinationResult>> all = store.readAll();
  ASSERT_FALSE(all.ok());
  EXPECT_NE(all.status().message().find(dir + "/results/broken.json"), std::string::npos)
      << all.status().message();
  test::writeFile(dir + "/results/broken.json", R"({"collidoscope_combination": 2})");
  const Result<std::vector<CombinationResult>> other = store.readAll();
  ASSERT_FALSE(other.ok());
  EXPECT_NE(other.status().message().find("broken.json"), std::string::npos);

  test::writeFile(dir + "/plan.json", R"({"collidoscope_plan": 1, "combinations": [{"id": 1}]})");
  const Result<std::vector<Combination>> plan = store.readPlan();
  ASSERT_FALSE(plan.ok());
  EXPECT_NE(plan.status().message().find(dir + "/plan.json"), std::string::npos)
      << plan.status().message();
  test::writeFile(dir + "/plan.json", "[");
  EXPECT_FALSE(store.readPlan().ok());
}

TEST(ResultStore, PrepareFailsWithTheFolderNamed) {
  const std::string dir = test::makeTempDirectory("store_file");
  test::writeFile(dir + "/taken", "a file where the study folder should go");
  const Status s = ResultStore(dir + "/taken").prepare();
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find(dir + "/taken"), std::string::npos) << s.message();
}

}  // namespace
}  // namespace collido::study
