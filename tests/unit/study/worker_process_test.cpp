// Worker processes, with small shell scripts standing in for the worker: how each ending is
// reported, progress lines, time limits, stop requests and the log tail.
#include <collido/study/worker_process.h>

#include <sched.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "support/test_paths.h"

namespace collido::study {
namespace {

using Clock = std::chrono::steady_clock;

/// A launch of `/bin/sh -c script` logging into a fresh folder.
WorkerLaunch shell(const std::string& script, const std::string& hint) {
  WorkerLaunch launch;
  launch.executable = "/bin/sh";
  launch.arguments = {"-c", script};
  launch.log_path = test::makeTempDirectory(hint) + "/worker.log";
  return launch;
}

std::string readText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// Whether `pid` is gone or a zombie waiting for a parent that is not us.
bool processEnded(pid_t pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  if (!stat) return true;
  std::string line;
  std::getline(stat, line);
  const std::size_t close = line.rfind(')');
  return close != std::string::npos && close + 2 < line.size() && line[close + 2] == 'Z';
}

TEST(RunWorkerProcess, CleanExitIsOk) {
  WorkerLaunch launch = shell("echo 'to stderr' >&2; exit 0", "worker_ok");
  const WorkerOutcome outcome = runWorkerProcess(launch);
  EXPECT_EQ(outcome.status, WorkerStatus::kOk);
  EXPECT_TRUE(outcome.ok());
  EXPECT_EQ(outcome.exit_code, 0);
  EXPECT_EQ(outcome.signal, 0);
  EXPECT_EQ(outcome.signal_name, "");
  EXPECT_EQ(outcome.log_tail, "");  // only failures carry the log
  EXPECT_EQ(readText(launch.log_path), "to stderr\n");
  EXPECT_GT(outcome.wall_s, 0.0);  // measured, whatever it is
  EXPECT_GT(outcome.peak_rss_bytes, 0u);
}

TEST(RunWorkerProcess, NonZeroExitIsFailedWithItsCodeAndLog) {
  const WorkerOutcome outcome =
      runWorkerProcess(shell("echo 'error: the scene is bad' >&2; exit 3", "worker_exit"));
  EXPECT_EQ(outcome.status, WorkerStatus::kFailed);
  EXPECT_FALSE(outcome.ok());
  EXPECT_EQ(outcome.exit_code, 3);
  EXPECT_EQ(outcome.signal, 0);
  EXPECT_EQ(outcome.log_tail, "error: the scene is bad\n");
}

TEST(RunWorkerProcess, SignalDeathIsCrashedWithTheSignalNamed) {
  for (const auto& [name, number] : std::vector<std::pair<std::string, int>>{
           {"SEGV", SIGSEGV}, {"ABRT", SIGABRT}, {"BUS", SIGBUS}, {"FPE", SIGFPE}}) {
    SCOPED_TRACE(name);
    const WorkerOutcome outcome = runWorkerProcess(
        shell("echo 'building torus_a' >&2; kill -" + name + " $$", "worker_signal"));
    EXPECT_EQ(outcome.status, WorkerStatus::kCrashed);
    EXPECT_EQ(outcome.signal, number);
    EXPECT_EQ(outcome.signal_name, "SIG" + name);
    EXPECT_EQ(outcome.exit_code, 0);
    EXPECT_EQ(outcome.log_tail, "building torus_a\n");
  }
}

TEST(RunWorkerProcess, TimeoutKillsTheWorkerAndEverythingItStarted) {
  const std::string dir = test::makeTempDirectory("worker_timeout");
  WorkerLaunch launch;
  launch.executable = "/bin/sh";
  // A grandchild in the background, as an engine's helper process would be.
  launch.arguments = {"-c", "sleep 30 & echo $! > " + dir + "/child.pid; sleep 30"};
  launch.log_path = dir + "/worker.log";
  launch.timeout_s = 0.5;
  std::size_t ticks = 0;
  launch.on_tick = [&ticks] { ++ticks; };
  const WorkerOutcome outcome = runWorkerProcess(launch);
  EXPECT_EQ(outcome.status, WorkerStatus::kTimeout);
  EXPECT_EQ(outcome.signal, SIGKILL);
  EXPECT_GE(ticks, 1u);
  std::ifstream pid_file(dir + "/child.pid");
  pid_t child = 0;
  ASSERT_TRUE(pid_file >> child) << "the script wrote no pid";
  // The kill reached the whole process group; give the kernel a moment to finish it.
  bool ended = false;
  for (int i = 0; i < 50 && !ended; ++i) {
    ended = processEnded(child);
    if (!ended) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  EXPECT_TRUE(ended) << "process " << child << " survived the timeout";
  if (!ended) kill(child, SIGKILL);
}

TEST(RunWorkerProcess, ProgressLinesReachTheCallback) {
  // The sleep splits a line across two writes.
  WorkerLaunch launch = shell(
      "echo progress 2 5; echo 'not progress'; printf 'progr'; sleep 0.3; printf 'ess 3 5\\n';"
      "echo progress 5 5; printf 'progress 6 5'",
      "worker_progress");
  std::vector<std::pair<std::size_t, std::size_t>> seen;
  launch.on_progress = [&seen](std::size_t done, std::size_t total) {
    seen.emplace_back(done, total);
  };
  const WorkerOutcome outcome = runWorkerProcess(launch);
  EXPECT_EQ(outcome.status, WorkerStatus::kOk);
  // A line split across writes is read whole; an unfinished last line is not a report.
  EXPECT_EQ(seen, (std::vector<std::pair<std::size_t, std::size_t>>{{2, 5}, {3, 5}, {5, 5}}));
}

TEST(RunWorkerProcess, OutputWrittenJustBeforeTheExitIsRead) {
  // Far more than one read's chunk, written at once, and the worker exits at once: every line
  // must still be seen, however soon the exit is noticed.
  WorkerLaunch launch = shell("printf 'progress %s 3000\\n' $(seq 1 3000)", "worker_burst");
  std::size_t lines = 0;
  std::size_t last = 0;
  launch.on_progress = [&](std::size_t done, std::size_t) {
    ++lines;
    last = done;
  };
  const WorkerOutcome outcome = runWorkerProcess(launch);
  EXPECT_EQ(outcome.status, WorkerStatus::kOk);
  EXPECT_EQ(lines, 3000u);
  EXPECT_EQ(last, 3000u);
}

std::vector<int> allowedProcessors() {
  cpu_set_t set;
  CPU_ZERO(&set);
  std::vector<int> cpus;
  if (sched_getaffinity(0, sizeof set, &set) != 0) return cpus;
  for (int cpu = 0; cpu < CPU_SETSIZE; ++cpu) {
    if (CPU_ISSET(cpu, &set)) cpus.push_back(cpu);
  }
  return cpus;
}

// The driver keeps off the last processor while a study runs, and a worker pinned there runs
// there alone; the driver gets its processors back afterwards.
TEST(WorkerProcessor, ReservesTheLastProcessorForPinnedWorkers) {
  const std::vector<int> before = allowedProcessors();
  {
    const WorkerProcessor reserved;
    if (before.size() < 2) {
      EXPECT_EQ(reserved.cpu(), -1);
      GTEST_SKIP() << "one processor: nothing to reserve";
    }
    ASSERT_EQ(reserved.cpu(), before.back());
    const std::vector<int> driver = allowedProcessors();
    EXPECT_EQ(driver, std::vector<int>(before.begin(), before.end() - 1));

    WorkerLaunch launch = shell("grep Cpus_allowed_list /proc/self/status", "worker_pinned");
    launch.cpu = reserved.cpu();
    std::string seen;
    launch.on_line = [&seen](const std::string& line) { seen += line; };
    EXPECT_EQ(runWorkerProcess(launch).status, WorkerStatus::kOk);
    EXPECT_EQ(seen, "Cpus_allowed_list:\t" + std::to_string(reserved.cpu()));
  }
  EXPECT_EQ(allowedProcessors(), before);
}

TEST(RunWorkerProcess, EnvironmentIsAddedToOurs) {
  WorkerLaunch launch =
      shell("echo \"$COLLIDO_STUDY_TEST_VALUE:${HOME:+home}\" >&2; exit 1", "worker_env");
  launch.environment = {"COLLIDO_STUDY_TEST_VALUE=a=b c", "NOT AN ASSIGNMENT"};
  const WorkerOutcome outcome = runWorkerProcess(launch);
  EXPECT_EQ(outcome.status, WorkerStatus::kFailed);
  const bool has_home = std::getenv("HOME") != nullptr && *std::getenv("HOME") != '\0';
  EXPECT_EQ(outcome.log_tail, std::string("a=b c:") + (has_home ? "home" : "") + "\n");
}

TEST(RunWorkerProcess, MissingExecutableIsFailed127) {
  WorkerLaunch launch = shell("", "worker_missing");
  launch.executable = "/no/such/collido";
  launch.arguments.clear();
  const WorkerOutcome outcome = runWorkerProcess(launch);
  EXPECT_EQ(outcome.status, WorkerStatus::kFailed);
  EXPECT_EQ(outcome.exit_code, 127);
  EXPECT_NE(outcome.log_tail.find("cannot start /no/such/collido"), std::string::npos)
      << outcome.log_tail;
}

TEST(RunWorkerProcess, StopRequestKillsTheWorkerAsInterrupted) {
  WorkerLaunch launch = shell("sleep 30", "worker_stop");
  std::atomic<bool> stop{false};
  launch.stop = &stop;
  const Clock::time_point start = Clock::now();
  launch.on_tick = [&stop, start] {
    if (Clock::now() - start > std::chrono::milliseconds(300)) stop.store(true);
  };
  const WorkerOutcome outcome = runWorkerProcess(launch);
  EXPECT_EQ(outcome.status, WorkerStatus::kInterrupted);
  EXPECT_EQ(outcome.signal, SIGKILL);
}

// A driver killed outright (SIGKILL: no handler runs) takes its worker with it, instead of
// leaving it to run on without a time limit.
TEST(RunWorkerProcess, AWorkerDiesWithItsDriver) {
  const std::string dir = test::makeTempDirectory("worker_orphan");
  const std::string pid_file = dir + "/worker.pid";
  WorkerLaunch launch = shell(
      "echo $$ > " + pid_file + ".part; mv " + pid_file + ".part " + pid_file + "; exec sleep 30",
      "worker_orphan");
  const pid_t driver = fork();
  if (driver == 0) {
    (void)runWorkerProcess(launch);
    _exit(0);
  }
  ASSERT_GT(driver, 0);
  const Clock::time_point start = Clock::now();
  while (readText(pid_file).empty() && Clock::now() - start < std::chrono::seconds(10))
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  const pid_t worker = static_cast<pid_t>(std::stol("0" + readText(pid_file)));
  kill(driver, SIGKILL);
  waitpid(driver, nullptr, 0);
  ASSERT_GT(worker, 0) << "the worker never started";
  bool ended = false;
  for (int i = 0; i < 250 && !ended; ++i) {
    ended = processEnded(worker);
    if (!ended) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  if (!ended) kill(worker, SIGKILL);
  EXPECT_TRUE(ended) << "worker " << worker << " outlived its driver";
}

TEST(RunWorkerProcess, ExitBeforeTheTimeoutIsNotATimeout) {
  WorkerLaunch launch = shell("sleep 0.2; exit 0", "worker_quick");
  launch.timeout_s = 20.0;
  const WorkerOutcome outcome = runWorkerProcess(launch);
  EXPECT_EQ(outcome.status, WorkerStatus::kOk);
  EXPECT_EQ(outcome.signal, 0);
}

TEST(FileTail, LastBytesOrAll) {
  const std::string path = test::makeTempDirectory("tail") + "/log";
  test::writeFile(path, "0123456789");
  EXPECT_EQ(fileTail(path, 4), "6789");
  EXPECT_EQ(fileTail(path, 10), "0123456789");
  EXPECT_EQ(fileTail(path, 100), "0123456789");
  EXPECT_EQ(fileTail(path, 0), "");
  EXPECT_EQ(fileTail(path + ".missing", 10), "");
}

}  // namespace
}  // namespace collido::study
