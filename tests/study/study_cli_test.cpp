// `collido study` and `collido merge` end to end: the built executable runs studies that mix the
// obbtree backend with a test plugin that crashes, aborts, hangs and exits on purpose
// (tests/study/plugins/misbehaving_plugin.cpp), and the tests read the study folder back.
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <collido/scene/scene.h>
#include <collido/study/folder_lock.h>
#include <collido/study/plan.h>
#include <collido/study/result_store.h>

#include "support/test_paths.h"

namespace collido::study {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

struct CommandRun {
  int exit_code = -1;  ///< 128 + signal when killed by one
  std::string out;
  std::string err;
};

std::string readText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// Starts `collido --plugin <test plugins> args...` with stdout and stderr sent to files.
pid_t startCollido(const std::vector<std::string>& args, const std::string& out_path,
                   const std::string& err_path) {
  std::vector<std::string> storage = {COLLIDO_EXECUTABLE, "--plugin", COLLIDO_TEST_PLUGIN_DIR};
  storage.insert(storage.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& s : storage)
    argv.push_back(s.data());
  argv.push_back(nullptr);
  const pid_t pid = fork();
  if (pid == 0) {
    const int out = open(out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err = open(err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (out < 0 || err < 0) _exit(126);
    dup2(out, STDOUT_FILENO);
    dup2(err, STDERR_FILENO);
    execv(argv[0], argv.data());
    _exit(127);
  }
  return pid;
}

/// Waits for `pid` at most `limit_s` seconds (then kills it); the exit code, or 128 + signal.
int waitFor(pid_t pid, double limit_s) {
  const Clock::time_point start = Clock::now();
  int status = 0;
  for (;;) {
    const pid_t done = waitpid(pid, &status, WNOHANG);
    if (done == pid) break;
    if (std::chrono::duration<double>(Clock::now() - start).count() > limit_s) {
      ADD_FAILURE() << "collido still running after " << limit_s << " s; killed";
      kill(pid, SIGKILL);
      waitpid(pid, &status, 0);
      return -1;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return -1;
}

/// Runs collido to the end; `dir` receives its stdout and stderr.
CommandRun collido(const std::vector<std::string>& args, const std::string& dir) {
  static int serial = 0;
  const std::string stem = dir + "/command" + std::to_string(++serial);
  CommandRun run;
  // A guard against a hang, far beyond any run here even instrumented on a loaded machine.
  run.exit_code = waitFor(startCollido(args, stem + ".out", stem + ".err"), 300.0);
  run.out = readText(stem + ".out");
  run.err = readText(stem + ".err");
  return run;
}

std::string describe(const CommandRun& run) {
  return "exit code " + std::to_string(run.exit_code) + "\nstderr:\n" + run.err + "\nstdout:\n" +
         run.out;
}

/// Two thick tori linked through each other (intersecting in every frame), 3 jittered frames:
/// every backend here runs it in well under a second, even the brute force under sanitizers.
std::string writeSmallScene(const std::string& dir) {
  const std::string path = dir + "/linked.json";
  test::writeFile(path, R"({
    "name": "linked",
    "frames": 3,
    "objects": [
      {"name": "a", "shape": {"generator": "torus", "minor_radius": 0.4,
                              "major_segments": 12, "minor_segments": 6}},
      {"name": "b", "shape": {"generator": "torus", "minor_radius": 0.4,
                              "major_segments": 12, "minor_segments": 6},
       "pose": {"translation": [1.5, 0, 0], "rotation": {"axis": [1, 0, 0], "degrees": 90}},
       "motion": {"jitter": {"seed": 5, "translation": 0.05, "rotation_deg": 5}}}
    ],
    "queries": [
      {"name": "pairs", "a": "a", "b": "b", "kind": "all_pairs"},
      {"name": "hit", "a": "a", "b": "b", "kind": "boolean"}
    ]})");
  return path;
}

std::vector<CombinationResult> readResults(const std::string& out) {
  const Result<std::vector<CombinationResult>> all = ResultStore(out).readAll();
  if (!all.ok()) {
    ADD_FAILURE() << all.status().message();
    return {};
  }
  return all.value();
}

std::map<std::string, CombinationResult> byBackend(const std::vector<CombinationResult>& results) {
  std::map<std::string, CombinationResult> map;
  for (const CombinationResult& r : results)
    map[r.combination.backend] = r;
  return map;
}

std::vector<std::string> jsonFilesIn(const std::string& folder) {
  std::vector<std::string> names;
  std::error_code ec;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder, ec)) {
    if (entry.path().extension() == ".json") names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

std::size_t lineCount(const std::string& text) {
  return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

std::vector<std::string> studyArgs(const std::string& scene, const std::string& backends,
                                   const std::string& out) {
  return {"study", scene, "--backends", backends, "--out", out, "--repetitions", "1"};
}

// A crash, an abort and a hang each cost one combination; the rest of the study is whole.
TEST(StudyCli, CrashAbortAndHangCostOneCombinationEach) {
  const std::string dir = test::makeTempDirectory("study_mixed");
  const std::string out = dir + "/study";
  std::vector<std::string> args = studyArgs(
      writeSmallScene(dir), "obbtree,misbehaving:crash,misbehaving:abort,misbehaving:hang", out);
  // The hang costs the whole timeout; the others must finish well within it, even instrumented on a
  // loaded machine.
  args.insert(args.end(), {"--timeout", "10"});
  const CommandRun run = collido(args, dir);
  ASSERT_EQ(run.exit_code, 0) << describe(run);
  EXPECT_NE(run.err.find("study: 4 combinations, 4 to run"), std::string::npos) << run.err;

  const std::vector<CombinationResult> results = readResults(out);
  ASSERT_EQ(results.size(), 4u);
  EXPECT_EQ(jsonFilesIn(out + "/results").size(), 4u);
  // In plan order: the backends as --backends lists them.
  EXPECT_EQ(results[0].combination.backend, "obbtree");
  EXPECT_EQ(results[1].combination.backend, "misbehaving:crash");
  EXPECT_EQ(results[2].combination.backend, "misbehaving:abort");
  EXPECT_EQ(results[3].combination.backend, "misbehaving:hang");

  const CombinationResult& obbtree = results[0];
  EXPECT_EQ(obbtree.outcome.status, WorkerStatus::kOk);
  EXPECT_EQ(obbtree.combination.scene_name, "linked");
  ASSERT_EQ(obbtree.measurements.size(), 2u);
  for (const QueryMeasurement& m : obbtree.measurements) {
    SCOPED_TRACE(m.query);
    EXPECT_EQ(m.status, "ok");
    EXPECT_EQ(m.frames.size(), 3u);
    EXPECT_EQ(m.times_us.size(), 12u);  // --repetitions 1, raised to 12 calls a round
    EXPECT_EQ(m.disagreements, 0u);
  }
  EXPECT_GT(obbtree.outcome.peak_rss_bytes, 0u);
  // The backend's share, apart from the scene and the exact answers the worker held.
  ASSERT_TRUE(obbtree.backend_rss_bytes.has_value());
  EXPECT_LT(*obbtree.backend_rss_bytes, obbtree.outcome.peak_rss_bytes);

  const CombinationResult& crash = results[1];
  EXPECT_EQ(crash.outcome.status, WorkerStatus::kCrashed);
  EXPECT_EQ(crash.outcome.signal, SIGSEGV);
  EXPECT_EQ(crash.outcome.signal_name, "SIGSEGV");
  EXPECT_TRUE(crash.measurements.empty());
  const CombinationResult& abort = results[2];
  EXPECT_EQ(abort.outcome.status, WorkerStatus::kCrashed);
  EXPECT_EQ(abort.outcome.signal_name, "SIGABRT");
  EXPECT_TRUE(abort.measurements.empty());
  const CombinationResult& hang = results[3];
  EXPECT_EQ(hang.outcome.status, WorkerStatus::kTimeout);
  EXPECT_TRUE(hang.measurements.empty());

  // Every worker left its log; no request or answer is left behind in scratch/.
  for (const CombinationResult& r : results)
    EXPECT_TRUE(fs::exists(out + "/logs/" + r.combination.id + ".log")) << r.combination.id;
  EXPECT_TRUE(fs::is_empty(out + "/scratch"));

  // The outputs.
  const std::string table = readText(out + "/table.txt");
  EXPECT_NE(table.find("obbtree"), std::string::npos) << table;
  EXPECT_NE(table.find("linked · misbehaving:crash: worker crashed (SIGSEGV)"), std::string::npos)
      << table;
  EXPECT_NE(table.find("linked · misbehaving:abort: worker crashed (SIGABRT)"), std::string::npos)
      << table;
  EXPECT_NE(table.find("linked · misbehaving:hang: worker timeout"), std::string::npos) << table;
  EXPECT_EQ(run.out, table);  // the table is also what stdout shows
  const std::string records = readText(out + "/records.jsonl");
  EXPECT_EQ(lineCount(records), 2u * 3u);  // obbtree's frames only
  std::istringstream lines(records);
  for (std::string line; std::getline(lines, line);) {
    const nlohmann::json record = nlohmann::json::parse(line);
    EXPECT_EQ(record.at("backend"), "obbtree");
    EXPECT_EQ(record.at("disagrees"), false);
  }
  const nlohmann::json summary = nlohmann::json::parse(readText(out + "/summary.json"));
  ASSERT_EQ(summary.at("benchmarks").size(), 2u);
  EXPECT_EQ(summary.at("benchmarks")[0].at("name"), "obbtree/linked/pairs");
  EXPECT_TRUE(summary.contains("context"));
}

// The same failures in build(), before any query runs: each still costs its combination only,
// is recorded with its signal or the timeout, and the study goes on to the end. A crash when an
// instance is created also kills the child that learns what the plugin's settings answer: they
// are then all planned, with a warning, and the crash costs its own combination only.
TEST(StudyCli, CrashAbortAndHangInBuildCostOneCombinationEach) {
  const std::string dir = test::makeTempDirectory("study_build_failures");
  const std::string out = dir + "/study";
  std::vector<std::string> args = studyArgs(writeSmallScene(dir),
                                            "misbehaving:crash_in_build,misbehaving:abort_in_build,"
                                            "misbehaving:hang_in_build,obbtree,"
                                            "misbehaving:crash_in_create",
                                            out);
  args.insert(args.end(), {"--timeout", "10"});  // as above: ample for obbtree, spent by the hang
  const CommandRun run = collido(args, dir);
  ASSERT_EQ(run.exit_code, 0) << describe(run);
  EXPECT_NE(run.err.find("libcollido_plugin_misbehaving.so: crashed while creating its settings "
                         "(SIGSEGV); its settings are planned on every scene"),
            std::string::npos)
      << run.err;
  const std::vector<CombinationResult> results = readResults(out);
  ASSERT_EQ(results.size(), 5u);
  EXPECT_EQ(results[4].combination.backend, "misbehaving:crash_in_create");
  EXPECT_EQ(results[4].outcome.status, WorkerStatus::kCrashed);
  EXPECT_EQ(results[0].combination.backend, "misbehaving:crash_in_build");
  EXPECT_EQ(results[0].outcome.status, WorkerStatus::kCrashed);
  EXPECT_EQ(results[0].outcome.signal_name, "SIGSEGV");
  EXPECT_EQ(results[1].combination.backend, "misbehaving:abort_in_build");
  EXPECT_EQ(results[1].outcome.status, WorkerStatus::kCrashed);
  EXPECT_EQ(results[1].outcome.signal_name, "SIGABRT");
  EXPECT_EQ(results[2].combination.backend, "misbehaving:hang_in_build");
  EXPECT_EQ(results[2].outcome.status, WorkerStatus::kTimeout);
  for (std::size_t i = 0; i < 3; ++i)
    EXPECT_TRUE(results[i].measurements.empty()) << results[i].combination.backend;
  // The combination after them ran whole.
  EXPECT_EQ(results[3].combination.backend, "obbtree");
  EXPECT_EQ(results[3].outcome.status, WorkerStatus::kOk);
  ASSERT_EQ(results[3].measurements.size(), 2u);
  for (const QueryMeasurement& m : results[3].measurements)
    EXPECT_EQ(m.disagreements, 0u) << m.query;
  const std::string table = readText(out + "/table.txt");
  EXPECT_NE(table.find("linked · misbehaving:crash_in_build: worker crashed (SIGSEGV)"),
            std::string::npos)
      << table;
  EXPECT_NE(table.find("linked · misbehaving:abort_in_build: worker crashed (SIGABRT)"),
            std::string::npos)
      << table;
  EXPECT_NE(table.find("linked · misbehaving:hang_in_build: worker timeout"), std::string::npos)
      << table;
}

// A bundled scene from mesh files, through a worker and the stored result, agrees with the
// oracle (no time limit: under the sanitizers this takes a while).
TEST(StudyCli, EnvRobOnObbtreeAgreesWithTheOracle) {
  const std::string dir = test::makeTempDirectory("study_env_rob");
  const std::string out = dir + "/study";
  const CommandRun run =
      collido(studyArgs(test::sourcePath("scenes/env_rob.json"), "obbtree", out), dir);
  ASSERT_EQ(run.exit_code, 0) << describe(run);
  const std::vector<CombinationResult> results = readResults(out);
  ASSERT_EQ(results.size(), 1u);
  EXPECT_EQ(results[0].outcome.status, WorkerStatus::kOk);
  EXPECT_EQ(results[0].combination.scene_name, "env_rob");
  ASSERT_EQ(results[0].measurements.size(), 3u);  // all pairs, boolean, distance
  for (const QueryMeasurement& m : results[0].measurements) {
    SCOPED_TRACE(m.query);
    EXPECT_EQ(m.status, "ok");
    EXPECT_EQ(m.frames.size(), 40u);
    EXPECT_EQ(m.disagreements, 0u);
    EXPECT_EQ(m.triangles, 2180u + 216u);
  }
  EXPECT_EQ(lineCount(readText(out + "/records.jsonl")), 3u * 40u);
  const nlohmann::json summary = nlohmann::json::parse(readText(out + "/summary.json"));
  ASSERT_EQ(summary.at("benchmarks").size(), 3u);
  EXPECT_EQ(summary.at("benchmarks")[0].at("name"), "obbtree/env_rob/all_pairs");

  // The oracle's answers were kept for the next combination on this scene: one file.
  std::size_t stored = 0;
  for (const auto& entry : fs::directory_iterator(out + "/oracle")) {
    stored += entry.path().extension() == ".json" ? 1 : 0;
  }
  EXPECT_EQ(stored, 1u);
}

// Failures that are not signals: an exit code, an exception (caught by the adapter: the worker
// finishes, its queries fail), and wrong answers (counted, not failed).
TEST(StudyCli, ExitThrowAndWrongAnswersAreRecorded) {
  const std::string dir = test::makeTempDirectory("study_other");
  const std::string out = dir + "/study";
  const CommandRun run = collido(
      studyArgs(writeSmallScene(dir),
                "misbehaving:exit,misbehaving:throw,misbehaving:wrong,misbehaving:exact", out),
      dir);
  ASSERT_EQ(run.exit_code, 0) << describe(run);
  std::map<std::string, CombinationResult> results = byBackend(readResults(out));
  ASSERT_EQ(results.size(), 4u);

  const CombinationResult& exited = results["misbehaving:exit"];
  EXPECT_EQ(exited.outcome.status, WorkerStatus::kFailed);
  EXPECT_EQ(exited.outcome.exit_code, 7);
  EXPECT_EQ(exited.outcome.signal, 0);

  const CombinationResult& threw = results["misbehaving:throw"];
  EXPECT_EQ(threw.outcome.status, WorkerStatus::kOk);
  ASSERT_EQ(threw.measurements.size(), 2u);
  for (const QueryMeasurement& m : threw.measurements) {
    EXPECT_TRUE(m.status.failed()) << m.status;
    EXPECT_NE(m.status.reason().find("throws on purpose"), std::string::npos) << m.status;
  }

  const CombinationResult& wrong = results["misbehaving:wrong"];
  EXPECT_EQ(wrong.outcome.status, WorkerStatus::kOk);
  ASSERT_EQ(wrong.measurements.size(), 2u);
  for (const QueryMeasurement& m : wrong.measurements) {
    SCOPED_TRACE(m.query);
    EXPECT_EQ(m.status, "ok");
    EXPECT_EQ(m.disagreements, 3u);
    EXPECT_EQ(m.false_negatives, 3u);
  }

  const CombinationResult& exact = results["misbehaving:exact"];
  EXPECT_EQ(exact.outcome.status, WorkerStatus::kOk);
  for (const QueryMeasurement& m : exact.measurements) {
    EXPECT_EQ(m.status, "ok");
    EXPECT_EQ(m.disagreements, 0u) << m.query;
  }

  const std::string table = readText(out + "/table.txt");
  EXPECT_NE(table.find("linked · misbehaving:exit: worker failed (exit 7)"), std::string::npos)
      << table;
  EXPECT_NE(table.find("linked · misbehaving:throw / hit: failed: "), std::string::npos) << table;
}

// A study stores each combination as it finishes; --resume runs only what is missing.
TEST(StudyCli, ResumeRunsOnlyWhatIsMissing) {
  const std::string dir = test::makeTempDirectory("study_resume");
  const std::string out = dir + "/study";
  const std::string scene = writeSmallScene(dir);
  const std::vector<std::string> args = studyArgs(scene, "obbtree,misbehaving:exact", out);
  const CommandRun first = collido(args, dir);
  ASSERT_EQ(first.exit_code, 0) << describe(first);
  const std::vector<CombinationResult> stored = readResults(out);
  ASSERT_EQ(stored.size(), 2u);
  const std::string kept = out + "/results/" + stored[0].combination.id + ".json";
  const std::string removed = out + "/results/" + stored[1].combination.id + ".json";
  const std::string kept_text = readText(kept);
  ASSERT_TRUE(fs::remove(removed));

  std::vector<std::string> resume = args;
  resume.push_back("--resume");
  const CommandRun second = collido(resume, dir);
  ASSERT_EQ(second.exit_code, 0) << describe(second);
  EXPECT_NE(second.err.find("study: 2 combinations, 1 to run"), std::string::npos) << second.err;
  EXPECT_TRUE(fs::exists(removed));
  EXPECT_EQ(readText(kept), kept_text);  // not run again
  const std::vector<CombinationResult> again = readResults(out);
  ASSERT_EQ(again.size(), 2u);
  EXPECT_EQ(again[1].combination.id, stored[1].combination.id);
  EXPECT_EQ(again[1].outcome.status, WorkerStatus::kOk);

  const CommandRun nothing_left = collido(resume, dir);
  ASSERT_EQ(nothing_left.exit_code, 0) << describe(nothing_left);
  EXPECT_NE(nothing_left.err.find("0 to run"), std::string::npos) << nothing_left.err;

  // The same folder without --resume is refused, and so is another study with --resume.
  const CommandRun refused = collido(args, dir);
  EXPECT_EQ(refused.exit_code, 2) << describe(refused);
  EXPECT_NE(refused.err.find("already holds a study"), std::string::npos) << refused.err;
  std::vector<std::string> other = studyArgs(scene, "obbtree", out);
  other.push_back("--resume");
  const CommandRun different = collido(other, dir);
  EXPECT_EQ(different.exit_code, 2) << describe(different);
  EXPECT_NE(different.err.find("holds a different study"), std::string::npos) << different.err;
  EXPECT_EQ(readResults(out).size(), 2u);  // neither touched the results

  // A changed input gives other ids: resuming is refused, naming what changed.
  std::vector<std::string> more_repetitions = resume;
  *(std::find(more_repetitions.begin(), more_repetitions.end(), "--repetitions") + 1) = "2";
  const CommandRun repeated = collido(more_repetitions, dir);
  EXPECT_EQ(repeated.exit_code, 2) << describe(repeated);
  EXPECT_NE(repeated.err.find("the inputs changed since this study started (repetitions 1 -> 2)"),
            std::string::npos)
      << repeated.err;
  const std::string scene_text = readText(scene);
  std::string thicker = scene_text;
  thicker.replace(thicker.find("0.4"), 3, "0.45");
  test::writeFile(scene, thicker);
  const CommandRun edited = collido(resume, dir);
  test::writeFile(scene, scene_text);
  EXPECT_EQ(edited.exit_code, 2) << describe(edited);
  EXPECT_NE(edited.err.find("the files (scene file or meshes) of linked"), std::string::npos)
      << edited.err;
  EXPECT_EQ(readResults(out).size(), 2u);

  // While another driver holds the folder, a second one is refused before it touches anything.
  {
    const Result<study::FolderLock> held = study::FolderLock::acquire(out);
    ASSERT_TRUE(held.ok()) << held.status().message();
    const CommandRun locked_out = collido(resume, dir);
    EXPECT_EQ(locked_out.exit_code, 2) << describe(locked_out);
    EXPECT_NE(locked_out.err.find("in use by another collido study (PID " +
                                  std::to_string(getpid()) + ")"),
              std::string::npos)
        << locked_out.err;
  }
  EXPECT_EQ(readText(kept), kept_text);
}

TEST(StudyCli, RetryFailedRunsFailuresAgain) {
  const std::string dir = test::makeTempDirectory("study_retry");
  const std::string out = dir + "/study";
  std::vector<std::string> args = studyArgs(writeSmallScene(dir), "obbtree,misbehaving:crash", out);
  args.push_back("--resume");  // also fine on a fresh folder
  const CommandRun first = collido(args, dir);
  ASSERT_EQ(first.exit_code, 0) << describe(first);
  EXPECT_NE(first.err.find("2 to run"), std::string::npos) << first.err;
  const CommandRun resumed = collido(args, dir);
  EXPECT_NE(resumed.err.find("0 to run"), std::string::npos) << resumed.err;
  args.push_back("--retry-failed");
  const CommandRun retried = collido(args, dir);
  ASSERT_EQ(retried.exit_code, 0) << describe(retried);
  EXPECT_NE(retried.err.find("1 to run"), std::string::npos) << retried.err;
  EXPECT_EQ(byBackend(readResults(out))["misbehaving:crash"].outcome.status,
            WorkerStatus::kCrashed);
}

// A lost session (SIGHUP to the study; Ctrl-C and SIGTERM take the same path) kills the running
// worker, keeps what finished, and exits 130; --resume then completes the study.
TEST(StudyCli, InterruptedStudyResumes) {
  const std::string dir = test::makeTempDirectory("study_interrupt");
  const std::string out = dir + "/study";
  std::vector<std::string> args =
      studyArgs(writeSmallScene(dir), "misbehaving:hang,misbehaving:exact", out);
  std::vector<std::string> first_args = args;
  first_args.insert(first_args.end(), {"--timeout", "60"});
  const pid_t pid = startCollido(first_args, dir + "/first.out", dir + "/first.err");
  // The hang worker has started once its log exists (the study installs its SIGINT handler
  // before it starts any worker).
  const Clock::time_point start = Clock::now();
  const auto worker_started = [&out] {
    std::error_code ec;
    return fs::is_directory(out + "/logs", ec) && !fs::is_empty(out + "/logs", ec);
  };
  // Guards against a study that never starts or never stops, far beyond what either takes.
  while (!worker_started() && Clock::now() - start < std::chrono::seconds(60))
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  if (!worker_started()) {
    kill(pid, SIGINT);
    waitFor(pid, 60.0);
    FAIL() << "no worker started\n" << readText(dir + "/first.err");
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  ASSERT_EQ(kill(pid, SIGHUP), 0);
  const int code = waitFor(pid, 60.0);
  const std::string err = readText(dir + "/first.err");
  EXPECT_EQ(code, 130) << err;
  EXPECT_NE(err.find("study interrupted: 0 of 2 combinations are stored"), std::string::npos)
      << err;
  EXPECT_TRUE(jsonFilesIn(out + "/results").empty());
  EXPECT_TRUE(fs::exists(out + "/table.txt"));

  std::vector<std::string> resume = args;
  resume.insert(resume.end(), {"--resume", "--timeout", "10"});  // ample for the exact worker
  const CommandRun second = collido(resume, dir);
  ASSERT_EQ(second.exit_code, 0) << describe(second);
  EXPECT_NE(second.err.find("2 to run"), std::string::npos) << second.err;
  std::map<std::string, CombinationResult> results = byBackend(readResults(out));
  ASSERT_EQ(results.size(), 2u);
  EXPECT_EQ(results["misbehaving:hang"].outcome.status, WorkerStatus::kTimeout);
  EXPECT_EQ(results["misbehaving:exact"].outcome.status, WorkerStatus::kOk);
}

// Shards split the plan; merge joins them into the whole study.
TEST(StudyCli, ShardsMergeIntoTheWholeStudy) {
  const std::string dir = test::makeTempDirectory("study_shards");
  const std::string scene = writeSmallScene(dir);
  const std::string backends = "obbtree,misbehaving:exact,misbehaving:wrong";
  std::vector<std::string> a = studyArgs(scene, backends, dir + "/a");
  // One oracle store for both shards, as on a cluster's shared filesystem; two timing rounds,
  // each shard running both of each of its combinations.
  a.insert(a.end(), {"--shard", "0/2", "--oracle-store", dir + "/store", "--rounds", "2"});
  std::vector<std::string> b = studyArgs(scene, backends, dir + "/b");
  b.insert(b.end(), {"--shard", "1/2", "--oracle-store", dir + "/store", "--rounds", "2"});
  const CommandRun run_a = collido(a, dir);
  ASSERT_EQ(run_a.exit_code, 0) << describe(run_a);
  EXPECT_NE(run_a.err.find("study: 4 combinations in shard 0/2"), std::string::npos) << run_a.err;
  EXPECT_NE(readText(dir + "/a/plan.json").find(R"("rounds": 2)"), std::string::npos);
  const CommandRun run_b = collido(b, dir);
  ASSERT_EQ(run_b.exit_code, 0) << describe(run_b);
  EXPECT_NE(run_b.err.find("study: 2 combinations in shard 1/2"), std::string::npos) << run_b.err;
  // The scene's exact answers were kept once, in the store given, not in either shard's folder.
  EXPECT_EQ(jsonFilesIn(dir + "/store").size(), 1u);
  EXPECT_FALSE(fs::exists(dir + "/a/oracle"));
  EXPECT_FALSE(fs::exists(dir + "/b/oracle"));

  const CommandRun merged = collido({"merge", "--out", dir + "/m", dir + "/a", dir + "/b"}, dir);
  ASSERT_EQ(merged.exit_code, 0) << describe(merged);
  EXPECT_NE(merged.err.find("merged 3 of 3 planned combinations"), std::string::npos) << merged.err;

  // The merged folder holds exactly the plan an unsharded study would have, a result for each.
  const std::vector<Combination> plan = planStudy(
      {{scene, "linked", true}}, {"obbtree", "misbehaving:exact", "misbehaving:wrong"}, Sweep{});
  std::set<std::string> planned_labels;
  for (const Combination& c : plan)
    planned_labels.insert(c.label());
  const Result<std::vector<Combination>> merged_plan = ResultStore(dir + "/m").readPlan();
  ASSERT_TRUE(merged_plan.ok()) << merged_plan.status().message();
  std::set<std::string> merged_labels;
  std::set<std::string> merged_files;
  for (const Combination& c : merged_plan.value()) {
    merged_labels.insert(c.label());
    merged_files.insert(c.id + ".json");
  }
  EXPECT_EQ(merged_labels, planned_labels);
  const std::vector<std::string> files = jsonFilesIn(dir + "/m/results");
  EXPECT_EQ(std::set<std::string>(files.begin(), files.end()), merged_files);
  EXPECT_EQ(merged_plan.value().size(), 3u);
  // ... and the run order the shards ran, not a default one.
  const Result<std::optional<RunOrder>> merged_order = ResultStore(dir + "/m").readRunOrder();
  ASSERT_TRUE(merged_order.ok() && merged_order.value().has_value());
  EXPECT_EQ(merged_order.value()->rounds, 2);
  EXPECT_EQ(merged_order.value()->seed, RunOrder{}.seed);
  std::map<std::string, CombinationResult> results = byBackend(readResults(dir + "/m"));
  ASSERT_EQ(results.size(), 3u);
  for (const auto& [backend, r] : results) {
    EXPECT_EQ(r.outcome.status, WorkerStatus::kOk) << backend;
    // Both rounds' calls, 12 a round, joined frame by frame.
    EXPECT_EQ(r.measurements.at(0).rounds, 2u) << backend;
    EXPECT_EQ(r.measurements.at(0).times_us.size(), 24u) << backend;
  }
  EXPECT_EQ(results["misbehaving:wrong"].measurements.at(0).disagreements, 3u);
  for (const char* file : {"table.txt", "records.jsonl", "summary.json"})
    EXPECT_TRUE(fs::exists(dir + "/m/" + file)) << file;
  EXPECT_EQ(lineCount(readText(dir + "/m/records.jsonl")), 3u * 2u * 3u);
  EXPECT_EQ(merged.out, readText(dir + "/m/table.txt"));

  // Merging onto a folder that holds a study would keep its results beside the new ones.
  const CommandRun again = collido({"merge", "--out", dir + "/m", dir + "/a"}, dir);
  EXPECT_EQ(again.exit_code, 2) << describe(again);
  EXPECT_NE(again.err.find("already holds a study"), std::string::npos) << again.err;
  const CommandRun replaced = collido({"merge", "--out", dir + "/m", "--replace", dir + "/a"}, dir);
  ASSERT_EQ(replaced.exit_code, 0) << describe(replaced);
  EXPECT_NE(replaced.err.find("merged 2 of 2 planned combinations"), std::string::npos)
      << replaced.err;
  EXPECT_EQ(jsonFilesIn(dir + "/m/results").size(), 2u);
  EXPECT_EQ(lineCount(readText(dir + "/m/records.jsonl")), 2u * 2u * 3u);

  // The same combinations run on other inputs (here the repetitions) are not one study.
  std::vector<std::string> a2 = studyArgs(scene, backends, dir + "/a2");
  *(std::find(a2.begin(), a2.end(), "--repetitions") + 1) = "2";
  a2.insert(a2.end(), {"--shard", "0/2", "--rounds", "2"});
  ASSERT_EQ(collido(a2, dir).exit_code, 0);
  const CommandRun mixed = collido({"merge", "--out", dir + "/x", dir + "/a", dir + "/a2"}, dir);
  EXPECT_EQ(mixed.exit_code, 2) << describe(mixed);
  EXPECT_NE(mixed.err.find("on different inputs"), std::string::npos) << mixed.err;

  // Shards run in another order (another seed) are not one study either.
  std::vector<std::string> b2 = studyArgs(scene, backends, dir + "/b2");
  b2.insert(b2.end(), {"--shard", "1/2", "--oracle-store", dir + "/store", "--rounds", "2",
                       "--order-seed", "7"});
  ASSERT_EQ(collido(b2, dir).exit_code, 0);
  const CommandRun reordered =
      collido({"merge", "--out", dir + "/y", dir + "/a", dir + "/b2"}, dir);
  EXPECT_EQ(reordered.exit_code, 2) << describe(reordered);
  EXPECT_NE(reordered.err.find("in the order of seed 7"), std::string::npos) << reordered.err;
  EXPECT_NE(reordered.err.find("merge only shards of one study"), std::string::npos)
      << reordered.err;

  const CommandRun not_a_study = collido({"merge", "--out", dir + "/n", dir}, dir);
  EXPECT_EQ(not_a_study.exit_code, 2) << describe(not_a_study);
  EXPECT_NE(not_a_study.err.find("no study here"), std::string::npos) << not_a_study.err;
}

// Every stored time of a study folder (its results and summary) multiplied by `factor`: a study
// whose every call took that much longer, without timing anything.
void scaleStoredTimes(const std::string& folder, double factor) {
  const std::function<void(nlohmann::json&)> scale = [&](nlohmann::json& node) {
    if (node.is_array()) {
      for (nlohmann::json& item : node)
        scale(item);
      return;
    }
    if (!node.is_object()) return;
    for (auto& [key, value] : node.items()) {
      const bool time = key == "real_time" || key == "cpu_time" ||
                        (key.size() > 3 && key.compare(key.size() - 3, 3, "_us") == 0);
      if (time && value.is_number()) {
        value = value.get<double>() * factor;
      } else if (time && value.is_array()) {
        for (nlohmann::json& number : value) {
          if (number.is_number()) number = number.get<double>() * factor;
        }
      } else {
        scale(value);
      }
    }
  };
  std::vector<std::string> files = {folder + "/summary.json"};
  for (const fs::directory_entry& entry : fs::directory_iterator(folder + "/results"))
    files.push_back(entry.path().string());
  for (const std::string& file : files) {
    nlohmann::json document = nlohmann::json::parse(readText(file));
    scale(document);
    std::ofstream(file, std::ios::binary | std::ios::trunc) << document.dump();
  }
}

// collido compare and report --baseline end to end, on stored studies (no timing, so nothing a
// shared machine or the sanitizers can change): a study compared with a copy of itself is the
// same on every row, its ratios exactly 1; the copy with every stored time made 4x dearer is
// slower on every row and fails --fail-on-slower. How the statistics decide finer changes is
// tested on fixed samples (time_changes_test.cpp), and how often they catch a 25% slowdown is
// measured, not asserted (bench/compare_detection.sh).
TEST(StudyCli, CompareGatesOnAFarSlowdownAndACopyIsTheSame) {
  const std::string dir = test::makeTempDirectory("study_compare");
  const std::string scene = writeSmallScene(dir);
  ASSERT_EQ(
      collido(studyArgs(scene, "misbehaving:exact,misbehaving:exact[build_mib=1]", dir + "/before"),
              dir)
          .exit_code,
      0);
  fs::copy(dir + "/before", dir + "/copy", fs::copy_options::recursive);
  fs::copy(dir + "/before", dir + "/slow", fs::copy_options::recursive);
  scaleStoredTimes(dir + "/slow", 4.0);

  const auto changes = [&](const std::string& now) {
    const CommandRun run = collido(
        {"compare", dir + "/before", dir + "/" + now, "--json", dir + "/" + now + ".json"}, dir);
    EXPECT_EQ(run.exit_code, 0) << describe(run);
    EXPECT_NE(run.out.find("4 rows: "), std::string::npos) << run.out;
    return nlohmann::json::parse(readText(dir + "/" + now + ".json"));
  };
  const nlohmann::json copy = changes("copy");
  ASSERT_EQ(copy.at("rows").size(), 4u);  // two settings, two queries
  EXPECT_EQ(copy.at("counts").at("same"), 4) << copy.dump(1);
  for (const nlohmann::json& row : copy.at("rows")) {
    EXPECT_EQ(row.at("ratio"), 1.0) << row.dump();
    EXPECT_EQ(row.at("ratio_ci95"), nlohmann::json::array({1.0, 1.0})) << row.dump();
  }
  const nlohmann::json slow = changes("slow");
  ASSERT_EQ(slow.at("rows").size(), 4u);
  EXPECT_EQ(slow.at("counts").at("slower"), 4) << slow.dump(1);
  for (const nlohmann::json& row : slow.at("rows")) {
    for (const char* field : {"backend", "setting", "scene", "query", "before_us", "now_us",
                              "before_ci95_us", "now_ci95_us", "ratio", "ratio_ci95", "change"})
      EXPECT_TRUE(row.contains(field)) << field << " in " << row.dump();
  }
  // As a CI gate; and from the summaries alone, where the intervals combine unpaired.
  EXPECT_EQ(collido({"compare", dir + "/before", dir + "/slow", "--fail-on-slower"}, dir).exit_code,
            1);
  EXPECT_EQ(collido({"compare", dir + "/before", dir + "/copy", "--fail-on-slower"}, dir).exit_code,
            0);
  const CommandRun summaries =
      collido({"compare", dir + "/before/summary.json", dir + "/copy/summary.json"}, dir);
  EXPECT_NE(summaries.out.find("4 rows: 0 faster, 0 slower, 4 the same"), std::string::npos)
      << describe(summaries);
  const CommandRun slow_summaries =
      collido({"compare", dir + "/before/summary.json", dir + "/slow/summary.json"}, dir);
  EXPECT_NE(slow_summaries.out.find("4 rows: 0 faster, 4 slower, 0 the same"), std::string::npos)
      << describe(slow_summaries);
  const CommandRun bad = collido({"compare", dir + "/before", dir + "/nothing_here"}, dir);
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("nothing_here: not found"), std::string::npos) << bad.err;

  // The dashboard carries the same verdicts.
  const CommandRun report = collido(
      {"report", dir + "/copy", "--baseline", dir + "/before", "-o", dir + "/report.html"}, dir);
  ASSERT_EQ(report.exit_code, 0) << describe(report);
  EXPECT_NE(readText(dir + "/report.html").find(R"("counts":{"faster":0,"same":4,"slower":0})"),
            std::string::npos);
}

// Rounds that disagree by 4x (every other worker of the test plugin makes each query four times
// as long), far beyond noise, get more rounds within the time budget, up to three, and the rows
// that stay unstable are flagged. Noise could only make rounds disagree more, never less.
TEST(StudyCli, UnstableRowsGetMoreRoundsThenAreFlagged) {
  const std::string dir = test::makeTempDirectory("study_adaptive");
  setenv("COLLIDO_TEST_QUERY_JITTER", "3", 1);
  setenv("COLLIDO_TEST_QUERY_JITTER_FILE", (dir + "/created").c_str(), 1);
  std::vector<std::string> args = studyArgs(writeSmallScene(dir), "misbehaving:exact", dir + "/s");
  args.insert(args.end(), {"--rounds", "2", "--adaptive-seconds", "600"});
  const CommandRun run = collido(args, dir);
  unsetenv("COLLIDO_TEST_QUERY_JITTER");
  unsetenv("COLLIDO_TEST_QUERY_JITTER_FILE");
  ASSERT_EQ(run.exit_code, 0) << describe(run);
  EXPECT_NE(run.err.find("study: round 3 for 1 combinations whose rounds disagree"),
            std::string::npos)
      << run.err;
  const std::vector<CombinationResult> results = readResults(dir + "/s");
  ASSERT_EQ(results.size(), 1u);
  // Two planned rounds and three more, joined; plan.json still lists the two planned.
  for (const QueryMeasurement& m : results[0].measurements) {
    EXPECT_EQ(m.rounds, 5u) << m.query;
    EXPECT_EQ(m.times_us.size(), 5u * 12u) << m.query;
  }
  EXPECT_EQ(ResultStore(dir + "/s").readPlan().value().size(), 2u);
  EXPECT_NE(readText(dir + "/s/table.txt").find(" unstable"), std::string::npos);
}

// A setting that answers none of the kinds a scene asks is not planned there, its options
// probed as well, and the table lists it once; a setting that cannot be created is planned, and
// its worker says why.
TEST(StudyCli, SettingsThatAnswerNothingAskedAreNotPlanned) {
  const std::string dir = test::makeTempDirectory("study_not_applicable");
  const std::string out = dir + "/study";
  const std::string scene = dir + "/clearance.json";
  test::writeFile(scene, R"({
    "name": "clearance",
    "frames": 2,
    "objects": [
      {"name": "a", "shape": {"generator": "sphere", "radius": 1, "slices": 8, "stacks": 4}},
      {"name": "b", "shape": {"generator": "sphere", "radius": 1, "slices": 8, "stacks": 4},
       "pose": {"translation": [3, 0, 0]}}
    ],
    "queries": [{"name": "gap", "a": "a", "b": "b", "kind": "distance"}]})");
  const CommandRun run =
      collido(studyArgs(scene,
                        "obbtree,misbehaving:exact,misbehaving:exact[build_mib=1],"
                        "misbehaving:exact[build_mib=5000]",
                        out),
              dir);
  ASSERT_EQ(run.exit_code, 0) << describe(run);
  EXPECT_NE(run.err.find("study: 2 combinations, 2 to run"), std::string::npos) << run.err;
  const std::map<std::string, CombinationResult> results = byBackend(readResults(out));
  ASSERT_EQ(results.size(), 2u);
  EXPECT_EQ(results.at("obbtree").outcome.status, WorkerStatus::kOk);
  const CombinationResult& refused = results.at("misbehaving:exact[build_mib=5000]");
  ASSERT_EQ(refused.measurements.size(), 1u);
  EXPECT_NE(refused.measurements[0].status.text().find("build_mib = '5000'"), std::string::npos)
      << refused.measurements[0].status.text();

  const Result<std::vector<NotApplicable>> left_out = ResultStore(out).readNotApplicable();
  ASSERT_TRUE(left_out.ok()) << left_out.status().message();
  ASSERT_EQ(left_out.value().size(), 2u);
  EXPECT_EQ(left_out.value()[0].backend, "misbehaving:exact");
  EXPECT_EQ(left_out.value()[1].backend, "misbehaving:exact[build_mib=1]");
  EXPECT_EQ(left_out.value()[1].reason(), "answers boolean, all_pairs; the scene asks distance");
  const std::string table = readText(out + "/table.txt");
  EXPECT_EQ(run.out, table);
  const std::size_t section = table.find("Not applicable, so not planned");
  ASSERT_NE(section, std::string::npos) << table;
  EXPECT_NE(table.find("misbehaving:exact[build_mib=1]  boolean, all_pairs  clearance (distance)",
                       section),
            std::string::npos)
      << table;

  // A merge keeps the list (each shard holds the whole study's).
  const CommandRun merged = collido({"merge", "--out", dir + "/m", out, out}, dir);
  ASSERT_EQ(merged.exit_code, 0) << describe(merged);
  const Result<std::vector<NotApplicable>> merged_left_out =
      ResultStore(dir + "/m").readNotApplicable();
  ASSERT_TRUE(merged_left_out.ok()) << merged_left_out.status().message();
  EXPECT_EQ(merged_left_out.value().size(), 2u);
  EXPECT_NE(merged.out.find(table.substr(section, table.find("\n\n", section) - section)),
            std::string::npos)
      << merged.out;
}

// A sweep file: option grid, needs, resolutions, limits and its own repetitions; an optional
// backend no plugin offers is left out with a warning.
TEST(StudyCli, SweepFileSetsTheGrid) {
  const std::string dir = test::makeTempDirectory("study_sweep");
  const std::string out = dir + "/study";
  const std::string sweep = dir + "/sweep.json";
  test::writeFile(sweep, R"({
    "backends": [{"variant": "misbehaving:exact", "options": {"build_mib": [0, 1]}},
                 {"variant": "not_built_here", "optional": true}],
    "needs": ["declared", "every"],
    "resolutions": [1, 0.5],
    "limits": [2],
    "repetitions": 2,
    "protocol": "cycled",
    "timeout_s": 60})");
  const CommandRun run =
      collido({"study", writeSmallScene(dir), "--sweep", sweep, "--out", out}, dir);
  ASSERT_EQ(run.exit_code, 0) << describe(run);
  EXPECT_NE(run.err.find("study: 8 combinations, 8 to run"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("warning: sweep: no plugin offers the optional 'not_built_here'; left "
                         "out"),
            std::string::npos)
      << run.err;
  const std::vector<CombinationResult> results = readResults(out);
  ASSERT_EQ(results.size(), 8u);
  std::set<std::string> settings;
  for (const CombinationResult& r : results) {
    SCOPED_TRACE(r.combination.label());
    settings.insert(r.combination.backend);
    EXPECT_EQ(r.outcome.status, WorkerStatus::kOk);
    EXPECT_EQ(r.combination.limit, 2u);
    ASSERT_EQ(r.measurements.size(), 2u);
    for (const QueryMeasurement& m : r.measurements) {
      EXPECT_EQ(m.status, "ok");
      // The sweep's 2 repetitions on 3 frames, raised to 12 calls (at least 12 a round).
      EXPECT_EQ(m.times_us.size(), 12u);
      EXPECT_EQ(m.protocol, TimingProtocol::kCycled);
      EXPECT_EQ(m.disagreements, 0u);
      EXPECT_EQ(m.finest_disagreements.has_value(), r.combination.resolution != 1.0);
      if (m.kind == QueryKind::kAllPairs) {
        for (const FrameRecord& f : m.frames)
          EXPECT_TRUE(f.truncated);
      }
    }
  }
  EXPECT_EQ(settings, (std::set<std::string>{"misbehaving:exact[build_mib=0]",
                                             "misbehaving:exact[build_mib=1]"}));
  const std::string table = readText(out + "/table.txt");
  EXPECT_NE(table.find("What the scene's needs save"), std::string::npos) << table;
  EXPECT_NE(table.find("needs=every r=0.5 limit=2"), std::string::npos) << table;
  EXPECT_EQ(table.find("Failures"), std::string::npos) << table;
  const nlohmann::json summary = nlohmann::json::parse(readText(out + "/summary.json"));
  EXPECT_EQ(summary.at("benchmarks").size(), 16u);

  // A bad sweep is refused before anything runs, naming the file and the value.
  test::writeFile(sweep, R"({"backends": [{"variant": "misbehaving:exact",
                                           "options": {"build_mib": []}}]})");
  const CommandRun bad =
      collido({"study", writeSmallScene(dir), "--sweep", sweep, "--out", dir + "/bad"}, dir);
  EXPECT_EQ(bad.exit_code, 2) << describe(bad);
  EXPECT_NE(bad.err.find(sweep + ": /backends/0/options/build_mib: "), std::string::npos)
      << bad.err;
  EXPECT_FALSE(fs::exists(dir + "/bad/plan.json"));
}

// `collido study part.obj fixture.stl`: mesh files become two scenes written beside the results
// (overlapping at random, and a close approach through first contact), run with the default
// sweep, every other option still applying.
TEST(StudyCli, MeshFilesBecomeScenesWrittenBesideTheResults) {
  const std::string dir = test::makeTempDirectory("study_meshes");
  const std::string out = dir + "/study";
  test::writeFile(dir + "/part.obj",
                  "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 0 0 1\nv 1 0 1\nv 0 1 1\nv 1 1 1\n"
                  "f 1 3 4\nf 1 4 2\nf 5 6 8\nf 5 8 7\nf 1 2 6\nf 1 6 5\n"
                  "f 3 7 8\nf 3 8 4\nf 1 5 7\nf 1 7 3\nf 2 4 8\nf 2 8 6\n");
  std::string stl = "solid fixture\n";
  const char* faces[4][3] = {{"0 0 0", "0 2 0", "2 0 0"},
                             {"0 0 0", "2 0 0", "0 0 2"},
                             {"0 0 0", "0 0 2", "0 2 0"},
                             {"2 0 0", "0 2 0", "0 0 2"}};
  for (const auto& face : faces) {
    stl += " facet normal 0 0 0\n  outer loop\n";
    for (const char* corner : face)
      stl += std::string("   vertex ") + corner + "\n";
    stl += "  endloop\n endfacet\n";
  }
  test::writeFile(dir + "/fixture.stl", stl + "endsolid fixture\n");
  const CommandRun run =
      collido({"study", dir + "/part.obj", dir + "/fixture.stl", "--backends", "obbtree",
               "--rounds", "1", "--adaptive-seconds", "0", "--repetitions", "1", "--out", out},
              dir);
  ASSERT_EQ(run.exit_code, 0) << describe(run);
  for (const char* scene : {"part_vs_fixture_overlap", "part_vs_fixture_approach"}) {
    const std::string path = out + "/scenes/" + scene + ".json";
    EXPECT_NE(run.err.find("scene of the meshes: " + path), std::string::npos) << run.err;
    const Result<Scene> loaded = loadScene(path);
    ASSERT_TRUE(loaded.ok()) << loaded.status().toString();
    EXPECT_EQ(loaded.value().queries.size(), 3u);  // boolean, all pairs, distance
  }
  const std::vector<CombinationResult> results = readResults(out);
  ASSERT_EQ(results.size(), 4u);  // the default sweep's two OBB tree settings on each scene
  for (const CombinationResult& r : results) {
    SCOPED_TRACE(r.combination.label());
    EXPECT_EQ(r.outcome.status, WorkerStatus::kOk);
    for (const QueryMeasurement& m : r.measurements) {
      EXPECT_EQ(m.disagreements, 0u) << m.query;
      if (m.kind != QueryKind::kBoolean || r.combination.scene_name != "part_vs_fixture_approach")
        continue;
      // Through first contact: apart in the first frame, touching in the last.
      EXPECT_FALSE(m.frames.front().oracle_intersecting);
      EXPECT_TRUE(m.frames.back().oracle_intersecting);
    }
  }

  // The same command again keeps a scene the user edited (the folder's study then stops it).
  const std::string edited = out + "/scenes/part_vs_fixture_overlap.json";
  test::writeFile(edited, readText(edited) + " ");
  const CommandRun again =
      collido({"study", dir + "/part.obj", dir + "/fixture.stl", "--out", out}, dir);
  EXPECT_NE(again.err.find("scene of the meshes: " + edited + " (edited: kept as it is"),
            std::string::npos)
      << again.err;
  EXPECT_EQ(readText(edited).back(), ' ');
}

// A robot studied in one command: its URDF imported into OUT/scenes as collido import urdf does,
// with its trajectory and a placed environment mesh, then run like any scene.
TEST(StudyCli, ARobotIsStudiedFromItsUrdfInOneCommand) {
  const std::string dir = test::makeTempDirectory("study_robot");
  const std::string out = dir + "/study";
  test::writeFile(dir + "/arm.urdf", R"(<robot name="two_link">
  <link name="base"><collision><geometry><box size="0.2 0.2 0.2"/></geometry></collision></link>
  <link name="arm"><collision><origin xyz="0.3 0 0"/><geometry><box size="0.6 0.05 0.05"/>
    </geometry></collision></link>
  <joint name="swing" type="continuous"><parent link="base"/><child link="arm"/>
    <origin xyz="0 0 0.2"/><axis xyz="0 0 1"/></joint>
</robot>
)");
  test::writeFile(dir + "/joints.csv", "swing\n0\n1.5707963\n3.1415926\n");
  // A unit cube about its corner, placed so that the arm sweeps into it in the last frame.
  test::writeFile(dir + "/post.obj",
                  "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 0 0 1\nv 1 0 1\nv 0 1 1\nv 1 1 1\n"
                  "f 1 3 4\nf 1 4 2\nf 5 6 8\nf 5 8 7\nf 1 2 6\nf 1 6 5\n"
                  "f 3 7 8\nf 3 8 4\nf 1 5 7\nf 1 7 3\nf 2 4 8\nf 2 8 6\n");
  const CommandRun run =
      collido({"study", dir + "/arm.urdf", "--trajectory", dir + "/joints.csv", "--environment",
               dir + "/post.obj@-1.5,-0.5,0", "--backends", "obbtree", "--rounds", "1",
               "--adaptive-seconds", "0", "--repetitions", "1", "--out", out},
              dir);
  ASSERT_EQ(run.exit_code, 0) << describe(run);
  const std::string scene = out + "/scenes/arm.json";
  EXPECT_NE(run.err.find("scene of the robot: " + scene), std::string::npos) << run.err;
  const Result<Scene> loaded = loadScene(scene);
  ASSERT_TRUE(loaded.ok()) << loaded.status().toString();
  EXPECT_EQ(loaded.value().frames, 3u);
  const std::vector<CombinationResult> results = readResults(out);
  ASSERT_EQ(results.size(), 1u);
  EXPECT_EQ(results[0].outcome.status, WorkerStatus::kOk);
  bool robot_vs_environment_asked = false;
  for (const QueryMeasurement& m : results[0].measurements) {
    EXPECT_EQ(m.disagreements, 0u) << m.query;
    if (m.query != "robot vs environment") continue;
    robot_vs_environment_asked = true;
    ASSERT_EQ(m.frames.size(), 3u);
    EXPECT_FALSE(m.frames[0].oracle_intersecting);  // the arm along +x
    EXPECT_TRUE(m.frames[2].oracle_intersecting);   // swung to -x, into the post
  }
  EXPECT_TRUE(robot_vs_environment_asked);

  // The robot's options without a robot, and a pose that is not one, are refused up front.
  const CommandRun no_robot =
      collido({"study", scene, "--environment", dir + "/post.obj", "--out", dir + "/other"}, dir);
  EXPECT_EQ(no_robot.exit_code, 2);
  EXPECT_NE(no_robot.err.find("--environment is for a robot"), std::string::npos) << no_robot.err;
  const CommandRun bad_pose = collido(
      {"study", dir + "/arm.urdf", "--environment", dir + "/post.obj@1,2", "--out", dir + "/other"},
      dir);
  EXPECT_EQ(bad_pose.exit_code, 2);
  EXPECT_NE(bad_pose.err.find("got 2 numbers"), std::string::npos) << bad_pose.err;
  EXPECT_FALSE(fs::exists(dir + "/other"));
}

// Surface and FRep files run as combinations too: the seed method and each backend setting in a
// worker of its own (a crashing backend costs its own rows only), stored, resumable, joined per
// file into what collido report shows.
TEST(StudyCli, SurfaceAndFrepFilesRunInWorkersOfTheirOwn) {
  const std::string dir = test::makeTempDirectory("study_comparisons");
  const std::string out = dir + "/study";
  const std::string sweep = dir + "/sweep.json";
  test::writeFile(sweep, R"({"repetitions": 1,
    "surfaces": {"backends": ["nurbs:hull", "obbtree"], "tessellations": [4]},
    "frep": {"backends": ["obbtree", "misbehaving:crash"], "resolutions": [16]}})");
  const std::vector<std::string> args = {"study",
                                         "--surfaces",
                                         test::sourcePath("scenes/surfaces/saddle_cap.json"),
                                         "--frep",
                                         test::sourcePath("scenes/frep/seed_quadric.json"),
                                         "--sweep",
                                         sweep,
                                         "--out",
                                         out};
  const CommandRun run = collido(args, dir);
  ASSERT_EQ(run.exit_code, 0) << describe(run);
  EXPECT_NE(run.err.find("study: 6 combinations, 6 to run"), std::string::npos) << run.err;
  const std::vector<CombinationResult> results = readResults(out);
  ASSERT_EQ(results.size(), 6u);
  for (const CombinationResult& r : results) {
    SCOPED_TRACE(r.combination.label());
    EXPECT_NE(r.combination.kind, InputKind::kScene);
    EXPECT_TRUE(r.measurements.empty());
    if (r.combination.backend == "misbehaving:crash") {
      EXPECT_EQ(r.outcome.status, WorkerStatus::kCrashed);
      EXPECT_EQ(r.outcome.signal_name, "SIGSEGV");
    } else {
      EXPECT_EQ(r.outcome.status, WorkerStatus::kOk) << r.outcome.log_tail;
      EXPECT_EQ(r.surfaces.has_value(), r.combination.kind == InputKind::kSurfaces);
      EXPECT_EQ(r.frep.has_value(), r.combination.kind == InputKind::kFrep);
    }
  }

  const nlohmann::json surfaces =
      nlohmann::json::parse(readText(out + "/surfaces/saddle_cap.json"));
  EXPECT_EQ(surfaces.at("seed").size(), 4u);  // hull and box bounds, each with and without descent
  EXPECT_TRUE(surfaces.contains("reference"));
  std::map<std::string, nlohmann::json> surface_rows;
  for (const nlohmann::json& row : surfaces.at("backends"))
    surface_rows[row.at("backend").get<std::string>()] = row;
  ASSERT_EQ(surface_rows.size(), 2u) << surfaces.dump(1);
  EXPECT_EQ(surface_rows["nurbs:hull"].at("segments"), 0);
  EXPECT_EQ(surface_rows["obbtree"].at("segments"), 4);
  for (const auto& [backend, row] : surface_rows)
    EXPECT_EQ(row.at("status"), "ok") << backend;

  const nlohmann::json frep = nlohmann::json::parse(readText(out + "/frep/seed_quadric.json"));
  EXPECT_FALSE(frep.at("seed").empty());
  EXPECT_EQ(frep.at("preview_png").get<std::string>().rfind("data:image/png;base64,", 0), 0u);
  std::map<std::string, nlohmann::json> frep_rows;
  for (const nlohmann::json& row : frep.at("comparators"))
    frep_rows[row.at("backend").get<std::string>()] = row;
  ASSERT_EQ(frep_rows.size(), 2u) << frep.dump(1);
  EXPECT_EQ(frep_rows["obbtree"].at("status"), "ok");
  EXPECT_EQ(frep_rows["obbtree"].at("resolution"), 16);
  EXPECT_EQ(
      frep_rows["misbehaving:crash"].at("status").get<std::string>().rfind("crashed (SIGSEGV)", 0),
      0u)
      << frep_rows["misbehaving:crash"];

  // The dashboard shows the study's own comparisons without naming them.
  const CommandRun report = collido({"report", out}, dir);
  ASSERT_EQ(report.exit_code, 0) << describe(report);
  const std::string page = readText(out + "/report.html");
  EXPECT_NE(page.find("saddle_cap"), std::string::npos);
  EXPECT_NE(page.find("crashed (SIGSEGV)"), std::string::npos);

  std::vector<std::string> resume = args;
  resume.push_back("--resume");
  const CommandRun again = collido(resume, dir);
  ASSERT_EQ(again.exit_code, 0) << describe(again);
  EXPECT_NE(again.err.find("study: 6 combinations, 0 to run"), std::string::npos) << again.err;
}

// A seed method that answers otherwise than its file expects is a finding: `collido frep` exits
// with 1, and in a study its combination fails with its answers kept and the reason shown.
TEST(StudyCli, AFrepSeedThatContradictsItsFileFailsAndKeepsItsAnswers) {
  const std::string dir = test::makeTempDirectory("study_frep_expected");
  const std::string file = dir + "/overlap.json";
  test::writeFile(file, R"({"name": "overlap", "precision": 0.01,
    "solids": [{"name": "a", "solid": {"type": "sphere", "centre": [0, 0, 0], "radius": 1}},
               {"name": "b", "solid": {"type": "sphere", "centre": [1, 0, 0], "radius": 1}}],
    "pairs": [["a", "b", "separated"]]})");
  const CommandRun alone = collido({"frep", file, "--repetitions", "1"}, dir);
  EXPECT_EQ(alone.exit_code, 1) << describe(alone);
  EXPECT_NE(alone.out.find("colliding (expected separated)"), std::string::npos) << alone.out;

  const std::string sweep = dir + "/sweep.json";
  test::writeFile(sweep,
                  R"({"repetitions": 1, "frep": {"backends": ["obbtree"], "resolutions": [8]}})");
  const std::string out = dir + "/study";
  const CommandRun run =
      collido({"study", "--frep", file, "--sweep", sweep, "--out", out, "--quiet"}, dir);
  const std::vector<CombinationResult> results = readResults(out);
  ASSERT_EQ(results.size(), 2u) << describe(run);
  for (const CombinationResult& r : results) {
    SCOPED_TRACE(r.combination.label());
    ASSERT_TRUE(r.frep.has_value()) << describe(run);
    if (r.combination.backend != "seed") {
      EXPECT_EQ(r.outcome.status, WorkerStatus::kOk);
      continue;
    }
    EXPECT_EQ(r.outcome.status, WorkerStatus::kFailed);
    ASSERT_EQ(r.frep->seed.size(), 1u);
    EXPECT_EQ(r.frep->seed[0].result.verdict, frep::CollisionVerdict::kColliding);
    EXPECT_EQ(r.frep->unexpected, 1u);
  }
  const nlohmann::json document = nlohmann::json::parse(readText(out + "/frep/overlap.json"));
  ASSERT_EQ(document.at("problems").size(), 1u) << document.dump(1);
  EXPECT_NE(document.at("problems")
                .at(0)
                .get<std::string>()
                .find("1 answers differ from the file's expected ones"),
            std::string::npos)
      << document.at("problems");
}

// The conformance kit as a plugin author meets it: progress while it runs, every failing query
// of a scene, the command that shows the differing pairs, backend options through --variant,
// and no scratch folder left behind.
TEST(ConformanceCli, ShowsProgressEveryFailureAndTheViewCommand) {
  const std::string dir = test::makeTempDirectory("conformance_cli");
  fs::create_directories(dir + "/scenes");
  writeSmallScene(dir + "/scenes");
  const std::string plugin =
      std::string(COLLIDO_TEST_PLUGIN_DIR) + "/libcollido_plugin_misbehaving.so";
  const auto scratch = [] {
    std::set<std::string> folders;
    for (const fs::directory_entry& entry : fs::directory_iterator(fs::temp_directory_path())) {
      if (entry.path().filename().string().rfind("collido_conformance_", 0) == 0)
        folders.insert(entry.path().string());
    }
    return folders;
  };
  const std::set<std::string> before = scratch();
  const CommandRun wrong = collido({"conformance", plugin, "--variant", "misbehaving:wrong",
                                    "--scenes-dir", dir + "/scenes", "--log", dir + "/kit.txt"},
                                   dir);
  EXPECT_EQ(wrong.exit_code, 1) << describe(wrong);
  EXPECT_NE(wrong.out.find("[1/"), std::string::npos) << wrong.out;
  // Both queries of the linked scene fail, each shown.
  EXPECT_NE(wrong.out.find("linked/pairs: measured"), std::string::npos) << wrong.out;
  EXPECT_NE(wrong.out.find("linked/hit: measured"), std::string::npos) << wrong.out;
  EXPECT_NE(wrong.out.find(" view " + dir + "/scenes/linked.json --backends 'misbehaving:wrong'"),
            std::string::npos)
      << wrong.out;
  EXPECT_TRUE(fs::exists(dir + "/kit.txt"));
  EXPECT_EQ(scratch(), before);

  // Options reach the backend: an unknown one is refused by every check that builds.
  const CommandRun options =
      collido({"conformance", plugin, "--variant", "misbehaving:exact[no_such_option=1]",
               "--scenes-dir", dir + "/scenes"},
              dir);
  EXPECT_EQ(options.exit_code, 1) << describe(options);
  EXPECT_NE(options.out.find("no_such_option"), std::string::npos) << options.out;
  EXPECT_EQ(scratch(), before);
}

TEST(StudyCli, BadArgumentsAreRefused) {
  const std::string dir = test::makeTempDirectory("study_bad");
  const std::string scene = writeSmallScene(dir);
  std::vector<std::string> shard = studyArgs(scene, "obbtree", dir + "/s");
  shard.insert(shard.end(), {"--shard", "2/2"});
  const CommandRun bad_shard = collido(shard, dir);
  EXPECT_EQ(bad_shard.exit_code, 2) << describe(bad_shard);
  EXPECT_NE(bad_shard.err.find("--shard '2/2'"), std::string::npos) << bad_shard.err;

  const CommandRun unknown = collido(studyArgs(scene, "misbehaving:nothing", dir + "/u"), dir);
  EXPECT_EQ(unknown.exit_code, 2) << describe(unknown);
  EXPECT_NE(unknown.err.find("misbehaving:nothing"), std::string::npos) << unknown.err;

  const CommandRun no_scene = collido(studyArgs(dir + "/none.json", "obbtree", dir + "/n"), dir);
  EXPECT_EQ(no_scene.exit_code, 2) << describe(no_scene);
  EXPECT_NE(no_scene.err.find(dir + "/none.json"), std::string::npos) << no_scene.err;
  // A surface or FRep file that does not read is refused before anything runs, naming it; so
  // is a study with nothing to study.
  test::writeFile(dir + "/broken_frep.json", R"({"name": "x", "solids": 3})");
  const CommandRun bad_surfaces =
      collido({"study", "--surfaces", dir + "/none.json", "--out", dir + "/f"}, dir);
  EXPECT_EQ(bad_surfaces.exit_code, 2) << describe(bad_surfaces);
  EXPECT_NE(bad_surfaces.err.find(dir + "/none.json"), std::string::npos) << bad_surfaces.err;
  const CommandRun bad_frep =
      collido({"study", "--frep", dir + "/broken_frep.json", "--out", dir + "/f"}, dir);
  EXPECT_EQ(bad_frep.exit_code, 2) << describe(bad_frep);
  EXPECT_NE(bad_frep.err.find(dir + "/broken_frep.json"), std::string::npos) << bad_frep.err;
  const CommandRun nothing = collido({"study", "--out", dir + "/f"}, dir);
  EXPECT_EQ(nothing.exit_code, 2) << describe(nothing);
  EXPECT_NE(nothing.err.find("no scene, surface or FRep file"), std::string::npos) << nothing.err;
  for (const char* folder : {"/s", "/u", "/n", "/f"})
    EXPECT_FALSE(fs::exists(dir + folder)) << folder;

  // An oracle store that is a file, not a folder, is refused before anything runs, as every
  // option that fails its check is (exit 2, the option named).
  const CommandRun file_store = collido({"run", scene, "--oracle-cache", scene}, dir);
  EXPECT_EQ(file_store.exit_code, 2) << describe(file_store);
  EXPECT_NE(file_store.err.find("--oracle-cache"), std::string::npos) << file_store.err;
  std::vector<std::string> file_study = studyArgs(scene, "obbtree", dir + "/o");
  file_study.insert(file_study.end(), {"--oracle-store", scene});
  const CommandRun study_file_store = collido(file_study, dir);
  EXPECT_EQ(study_file_store.exit_code, 2) << describe(study_file_store);
  EXPECT_NE(study_file_store.err.find("--oracle-store"), std::string::npos) << study_file_store.err;
  EXPECT_FALSE(fs::exists(dir + "/o"));
  const CommandRun view_file_store =
      collido({"view", scene, "--oracle-store", scene, "-o", dir + "/v.html"}, dir);
  EXPECT_EQ(view_file_store.exit_code, 2) << describe(view_file_store);
  EXPECT_NE(view_file_store.err.find("--oracle-store"), std::string::npos) << view_file_store.err;
  EXPECT_FALSE(fs::exists(dir + "/v.html"));
}

// Plugins are loaded by child processes before the driver uses them: one that crashes or hangs
// while loading is skipped with a warning naming it, and the study runs on without it.
TEST(StudyCli, APluginThatCrashesOrHangsWhileLoadingIsSkipped) {
  const std::string dir = test::makeTempDirectory("study_load_traps");
  std::vector<std::string> args = studyArgs(writeSmallScene(dir), "misbehaving:exact", dir + "/s");
  args.insert(args.begin(), {"--plugin", COLLIDO_LOAD_TRAP_PLUGIN_DIR});
  args.insert(args.end(), {"--plugin-timeout", "1"});
  const CommandRun run = collido(args, dir);
  ASSERT_EQ(run.exit_code, 0) << describe(run);
  EXPECT_NE(run.err.find("libcollido_plugin_crash_on_load.so: crashed while loading (SIGSEGV); "
                         "skipped"),
            std::string::npos)
      << run.err;
  EXPECT_NE(run.err.find("libcollido_plugin_hang_on_load.so: still loading after 1 s"),
            std::string::npos)
      << run.err;
  const std::vector<CombinationResult> results = readResults(dir + "/s");
  ASSERT_EQ(results.size(), 1u);
  EXPECT_EQ(results[0].outcome.status, WorkerStatus::kOk);
}

// collido run keeps every backend in one process: a crash ends it, and says where isolation is.
TEST(StudyCli, RunExplainsACrashAndPointsToStudy) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "built with AddressSanitizer, whose own crash report is kept";
#else
  const std::string dir = test::makeTempDirectory("run_crash");
  const CommandRun run =
      collido({"run", writeSmallScene(dir), "--backends", "misbehaving:abort"}, dir);
  EXPECT_EQ(run.exit_code, 128 + SIGABRT) << describe(run);
  EXPECT_NE(run.err.find("collido run: a backend crashed"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("collido study runs each backend in a worker process"), std::string::npos)
      << run.err;
#endif
}

// The allocation hooks are preloaded into every worker: build memory is measured by them, also
// what a backend leaves out of its own count.
TEST(StudyCli, WorkersMeasureBuildsWithTheAllocationHooks) {
#ifndef COLLIDO_HAS_HEAP_HOOKS
  GTEST_SKIP() << "built with sanitizers: the allocation hooks are not built";
#else
  const std::string dir = test::makeTempDirectory("study_heap");
  const std::string out = dir + "/study";
  const CommandRun run =
      collido(studyArgs(writeSmallScene(dir), "obbtree,misbehaving:exact[build_mib=4]", out), dir);
  ASSERT_EQ(run.exit_code, 0) << describe(run);
  std::map<std::string, CombinationResult> results = byBackend(readResults(out));
  ASSERT_EQ(results.size(), 2u);
  for (const auto& [backend, r] : results) {
    ASSERT_EQ(r.measurements.size(), 2u) << backend;
    for (const QueryMeasurement& m : r.measurements) {
      SCOPED_TRACE(backend + " " + m.query);
      EXPECT_EQ(m.heap_probe, "hooks");
      ASSERT_TRUE(m.heap_bytes.has_value());
      ASSERT_TRUE(m.heap_peak_bytes.has_value());
      ASSERT_TRUE(m.heap_allocations.has_value());
      EXPECT_GT(*m.heap_bytes, 0u);
      EXPECT_GE(*m.heap_peak_bytes, *m.heap_bytes);
      EXPECT_GE(*m.heap_allocations, 2u);
    }
  }
  // 4 MiB of ballast per model that the backend does not report; the hooks see both.
  const QueryMeasurement& ballast = results["misbehaving:exact[build_mib=4]"].measurements[0];
  EXPECT_GE(*ballast.heap_bytes, 2u * 4u * 1024u * 1024u);
  EXPECT_LT(ballast.memory_bytes, 1024u * 1024u);
  // The stored file says so too.
  const std::string text =
      readText(out + "/results/" + results["obbtree"].combination.id + ".json");
  EXPECT_NE(text.find("\"heap_probe\": \"hooks\""), std::string::npos);
#endif
}

// collido pose-error on the tracked docking scene: a row per solver, layout and count, the
// JSON beside the table, and clear refusals of an unknown object and a layout it lacks.
TEST(PoseErrorCli, TableJsonAndRefusals) {
  const std::string dir = test::makeTempDirectory("pose_error");
  const std::string scene = test::sourcePath("scenes/station_docking_tracked.json");
  const CommandRun run =
      collido({"pose-error", scene, "--object", "module_b", "--layouts", "given,compact",
               "--markers", "4,6", "--trials", "20", "--json", dir + "/pose.json"},
              dir);
  ASSERT_EQ(run.exit_code, 0) << describe(run);
  EXPECT_NE(run.out.find("rigid   given"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("affine  compact"), std::string::npos) << run.out;
  const nlohmann::json json = nlohmann::json::parse(readText(dir + "/pose.json"));
  EXPECT_EQ(json.at("rows").size(), 2u * 2u * 2u);
  EXPECT_EQ(json.at("object"), "module_b");

  const CommandRun unknown = collido({"pose-error", scene, "--object", "nobody"}, dir);
  EXPECT_EQ(unknown.exit_code, 2) << describe(unknown);
  EXPECT_NE(unknown.err.find("no object named 'nobody'"), std::string::npos) << unknown.err;
  const CommandRun lacking =
      collido({"pose-error", scene, "--object", "module_a", "--layouts", "given"}, dir);
  EXPECT_EQ(lacking.exit_code, 2) << describe(lacking);
  EXPECT_NE(lacking.err.find("has no marker layout"), std::string::npos) << lacking.err;
}

// collido tracks writes the docking scene's generated tracks; a scene reading that file back
// recovers the same poses as the generated one.
TEST(TracksCli, GeneratedTracksWrittenAndReadBack) {
  const std::string dir = test::makeTempDirectory("tracks");
  const std::string scene = test::sourcePath("scenes/station_docking_tracked.json");
  const CommandRun run = collido({"tracks", scene, "-o", dir + "/docking.csv"}, dir);
  ASSERT_EQ(run.exit_code, 0) << describe(run);
  EXPECT_NE(run.err.find("1 tracked object, 24 frames"), std::string::npos) << run.err;
  nlohmann::json json = nlohmann::json::parse(readText(scene));
  json["objects"][1]["markers"].erase("generate");
  json["objects"][1]["markers"]["tracks"] = "docking.csv";
  // The module meshes are generated, so the scene may move to the temporary folder.
  std::ofstream(dir + "/docking.json") << json.dump();
  const Result<Scene> generated = loadScene(scene);
  const Result<Scene> read = loadScene(dir + "/docking.json");
  ASSERT_TRUE(generated.ok() && read.ok()) << read.status().message();
  for (std::size_t f = 0; f < generated.value().frames; ++f) {
    EXPECT_EQ(read.value().objects[1].poseAt(f).matrix(),
              generated.value().objects[1].poseAt(f).matrix())
        << "frame " << f;
  }
  const CommandRun untracked =
      collido({"tracks", test::sourcePath("scenes/env_rob.json"), "-o", dir + "/x.csv"}, dir);
  EXPECT_EQ(untracked.exit_code, 2) << describe(untracked);
  EXPECT_NE(untracked.err.find("no object has tracked markers"), std::string::npos);
}

}  // namespace
}  // namespace collido::study
