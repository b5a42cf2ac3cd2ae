// Worker processes: each combination runs in a child so that a crash, abort or hang of an
// engine costs that combination only. The child gets its own process group, so a timeout kills
// whatever the engine started too, and dies with its parent.
#include <collido/study/worker_process.h>

#include <fcntl.h>
#include <poll.h>
#include <sched.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <fstream>
#include <optional>
#include <string>

namespace collido::study {
namespace {

using Clock = std::chrono::steady_clock;

std::string signalName(int signal) {
  const char* abbreviation = sigabbrev_np(signal);
  return abbreviation != nullptr ? std::string("SIG") + abbreviation
                                 : "signal " + std::to_string(signal);
}

// Parses complete "progress D T" lines out of `buffer`, and hands the others to on_line,
// keeping a partial last line.
void consumeProgress(std::string& buffer, const WorkerLaunch& launch) {
  std::size_t newline;
  while ((newline = buffer.find('\n')) != std::string::npos) {
    const std::string line = buffer.substr(0, newline);
    buffer.erase(0, newline + 1);
    unsigned long long done = 0;
    unsigned long long total = 0;
    if (std::sscanf(line.c_str(), "progress %llu %llu", &done, &total) == 2) {
      if (launch.on_progress)
        launch.on_progress(static_cast<std::size_t>(done), static_cast<std::size_t>(total));
    } else if (launch.on_line) {
      launch.on_line(line);
    }
  }
}

// Reads what is left in the non-blocking pipe `reader` into `buffer`, handing out its lines:
// stops at its end, or where nothing more is there now (a process the worker started may still
// hold the pipe open; its later output is not waited for).
void drainPipe(int reader, std::string& buffer, const WorkerLaunch& launch) {
  char chunk[4096];
  for (;;) {
    const ssize_t got = read(reader, chunk, sizeof chunk);
    if (got > 0) {
      buffer.append(chunk, static_cast<std::size_t>(got));
      consumeProgress(buffer, launch);
    } else if (got < 0 && errno == EINTR) {
      continue;
    } else {
      return;
    }
  }
}

[[noreturn]] void execChild(const WorkerLaunch& launch, int stdout_fd, pid_t parent) {
  setpgid(0, 0);
  if (launch.cpu >= 0) {
    cpu_set_t one;
    CPU_ZERO(&one);
    CPU_SET(launch.cpu, &one);
    (void)sched_setaffinity(0, sizeof one, &one);  // not fatal: the worker runs unpinned
  }
  // A worker dies with its driver (SIGKILL, or a lost session), instead of running on without a
  // time limit. The parent may have died before this line: then nobody would send the signal.
  prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (getppid() != parent) _exit(129);
  dup2(stdout_fd, STDOUT_FILENO);
  const int log = open(launch.log_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (log >= 0) dup2(log, STDERR_FILENO);
  for (const std::string& assignment : launch.environment) {
    const std::size_t equals = assignment.find('=');
    if (equals != std::string::npos) {
      setenv(assignment.substr(0, equals).c_str(), assignment.substr(equals + 1).c_str(), 1);
    }
  }
  std::vector<std::string> storage{launch.executable};
  storage.insert(storage.end(), launch.arguments.begin(), launch.arguments.end());
  std::vector<char*> argv;
  argv.reserve(storage.size() + 1);
  for (std::string& s : storage)
    argv.push_back(s.data());
  argv.push_back(nullptr);
  execv(launch.executable.c_str(), argv.data());
  const std::string message =
      "cannot start " + launch.executable + ": " + std::strerror(errno) + "\n";
  (void)!write(STDERR_FILENO, message.data(), message.size());
  _exit(127);
}

}  // namespace

std::string fileTail(const std::string& path, std::size_t bytes) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) return "";
  const std::streamoff size = in.tellg();
  const std::streamoff start =
      size > static_cast<std::streamoff>(bytes) ? size - static_cast<std::streamoff>(bytes) : 0;
  in.seekg(start);
  std::string text(static_cast<std::size_t>(size - start), '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  // A cut may fall inside a UTF-8 character; its continuation bytes (10xxxxxx) alone are not
  // text, and JSON writers refuse them.
  if (start > 0) {
    std::size_t first = 0;
    while (first < text.size() && first < 3 &&
           (static_cast<unsigned char>(text[first]) & 0xC0) == 0x80)
      ++first;
    text.erase(0, first);
  }
  return text;
}

namespace {

bool setProcessors(const std::vector<int>& cpus) {
  cpu_set_t set;
  CPU_ZERO(&set);
  for (int cpu : cpus)
    CPU_SET(cpu, &set);
  return sched_setaffinity(0, sizeof set, &set) == 0;
}

}  // namespace

WorkerProcessor::WorkerProcessor() {
  cpu_set_t allowed;
  CPU_ZERO(&allowed);
  if (sched_getaffinity(0, sizeof allowed, &allowed) != 0) return;
  for (int cpu = 0; cpu < CPU_SETSIZE; ++cpu) {
    if (CPU_ISSET(cpu, &allowed)) driver_cpus_.push_back(cpu);
  }
  if (driver_cpus_.size() < 2) return;
  std::vector<int> rest(driver_cpus_.begin(), driver_cpus_.end() - 1);
  if (setProcessors(rest)) cpu_ = driver_cpus_.back();
}

WorkerProcessor::~WorkerProcessor() {
  if (cpu_ >= 0) (void)setProcessors(driver_cpus_);
}

namespace {

// A worker started: its process, the read end of its progress pipe, and a descriptor readable
// once it has exited (-1 where the kernel has no pidfd_open).
struct StartedWorker {
  pid_t pid = -1;
  int reader = -1;
  int exited = -1;
};

// How a worker ended: its wait status and resources, and whether it was killed for its time or
// for a stop request.
struct WorkerEnd {
  int wait_status = 0;
  struct rusage usage {};
  bool timed_out = false;
  bool interrupted = false;
};

// Forks and executes the worker in a process group of its own; empty with the reason in
// `problem` when no process could be started.
std::optional<StartedWorker> startWorker(const WorkerLaunch& launch, std::string& problem) {
  int pipe_fds[2];
  if (pipe2(pipe_fds, O_CLOEXEC) != 0) {
    problem = std::string("cannot create a pipe: ") + std::strerror(errno);
    return std::nullopt;
  }
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid < 0) {
    close(pipe_fds[0]);
    close(pipe_fds[1]);
    problem = std::string("cannot fork: ") + std::strerror(errno);
    return std::nullopt;
  }
  if (pid == 0) {
    close(pipe_fds[0]);
    // dup2 clears close-on-exec on the copy, so stdout survives the exec.
    execChild(launch, pipe_fds[1], parent);
  }
  setpgid(pid, pid);  // also here: whichever of parent and child runs first
  close(pipe_fds[1]);
  StartedWorker worker;
  worker.pid = pid;
  worker.reader = pipe_fds[0];
  fcntl(worker.reader, F_SETFL, fcntl(worker.reader, F_GETFL) | O_NONBLOCK);
  // Readable when the worker has exited. A worker closes its output a moment before it exits;
  // waiting for that exit on a fixed 50 ms sleep cost about that much a worker (a one-scene study
  // of 31 workers, run one after another: 12.4 s, now 10.7 s).
#ifdef SYS_pidfd_open
  worker.exited = static_cast<int>(syscall(SYS_pidfd_open, pid, 0));
#endif
  return worker;
}

// Reads the worker's progress until it exits, killing its group at the time limit or on a stop
// request; closes the worker's descriptors.
WorkerEnd superviseWorker(const WorkerLaunch& launch, const StartedWorker& worker,
                          Clock::time_point start) {
  WorkerEnd end;
  std::string buffer;
  bool reader_open = true;
  for (;;) {
    if (reader_open) {
      pollfd descriptor{worker.reader, POLLIN, 0};
      if (poll(&descriptor, 1, 200) > 0) {
        char chunk[4096];
        const ssize_t got = read(worker.reader, chunk, sizeof chunk);
        if (got > 0) {
          buffer.append(chunk, static_cast<std::size_t>(got));
          consumeProgress(buffer, launch);
        } else if (got == 0 || (errno != EAGAIN && errno != EINTR)) {
          reader_open = false;
        }
      }
    } else if (worker.exited >= 0) {
      pollfd descriptor{worker.exited, POLLIN, 0};
      poll(&descriptor, 1, 200);
    } else {
      usleep(10 * 1000);  // a kernel without pidfd_open (before Linux 5.3)
    }
    const pid_t done = wait4(worker.pid, &end.wait_status, WNOHANG, &end.usage);
    if (done == worker.pid) {
      // What the worker wrote before it exited may still be in the pipe (a read takes a chunk
      // per turn of this loop): read it all before the exit is taken.
      if (reader_open) drainPipe(worker.reader, buffer, launch);
      break;
    }
    const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
    const bool stop_asked = launch.stop != nullptr && launch.stop->load();
    if (!end.timed_out && !end.interrupted &&
        ((launch.timeout_s > 0.0 && elapsed > launch.timeout_s) || stop_asked)) {
      (stop_asked ? end.interrupted : end.timed_out) = true;
      kill(-worker.pid, SIGKILL);
      kill(worker.pid, SIGKILL);
    }
    if (launch.on_tick) launch.on_tick();
  }
  close(worker.reader);
  if (worker.exited >= 0) close(worker.exited);
  return end;
}

}  // namespace

WorkerOutcome runWorkerProcess(const WorkerLaunch& launch) {
  WorkerOutcome outcome;
  const Clock::time_point start = Clock::now();
  std::string problem;
  const std::optional<StartedWorker> worker = startWorker(launch, problem);
  if (!worker) {
    outcome.status = WorkerStatus::kFailed;
    outcome.log_tail = problem;
    return outcome;
  }
  const WorkerEnd end = superviseWorker(launch, *worker, start);
  outcome.wall_s = std::chrono::duration<double>(Clock::now() - start).count();
  outcome.peak_rss_bytes = static_cast<std::size_t>(end.usage.ru_maxrss) * 1024;  // Linux: KiB
  if (WIFEXITED(end.wait_status)) outcome.exit_code = WEXITSTATUS(end.wait_status);
  if (WIFSIGNALED(end.wait_status)) {
    outcome.signal = WTERMSIG(end.wait_status);
    outcome.signal_name = signalName(outcome.signal);
  }
  if (end.interrupted) {
    outcome.status = WorkerStatus::kInterrupted;
  } else if (end.timed_out) {
    outcome.status = WorkerStatus::kTimeout;
  } else if (outcome.signal != 0) {
    outcome.status = WorkerStatus::kCrashed;
  } else if (outcome.exit_code != 0) {
    outcome.status = WorkerStatus::kFailed;
  }
  if (!outcome.ok()) outcome.log_tail = fileTail(launch.log_path, 4000);
  return outcome;
}

}  // namespace collido::study
