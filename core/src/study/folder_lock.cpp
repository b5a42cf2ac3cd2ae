#include <collido/study/folder_lock.h>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <string>
#include <utility>

namespace collido::study {
namespace {

std::string readHolder(int fd) {
  char text[32] = {};
  const ssize_t got = pread(fd, text, sizeof text - 1, 0);
  std::string pid = got > 0 ? std::string(text, static_cast<std::size_t>(got)) : std::string();
  while (!pid.empty() && (pid.back() == '\n' || pid.back() == ' '))
    pid.pop_back();
  return pid.empty() ? std::string("unknown") : pid;
}

}  // namespace

Result<FolderLock> FolderLock::acquire(const std::string& folder) {
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error) {
    return Status(StatusCode::kInvalidArgument,
                  "cannot create the study folder " + folder + ": " + error.message());
  }
  const std::string path = folder + "/.lock";
  // Close-on-exec: the workers the driver starts must not inherit (and so keep) the hold.
  const int fd = open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0) {
    return Status(StatusCode::kInvalidArgument,
                  "cannot open " + path + ": " + std::strerror(errno));
  }
  if (flock(fd, LOCK_EX | LOCK_NB) != 0) {
    const int why = errno;
    const std::string holder = readHolder(fd);
    close(fd);
    if (why == EWOULDBLOCK) {
      return Status(StatusCode::kInvalidArgument,
                    folder + " is in use by another collido study (PID " + holder +
                        "); wait for it to end, or choose another --out");
    }
    return Status(StatusCode::kInvalidArgument, "cannot lock " + path + ": " + std::strerror(why));
  }
  const std::string pid = std::to_string(getpid()) + "\n";
  if (ftruncate(fd, 0) != 0 ||
      pwrite(fd, pid.data(), pid.size(), 0) != static_cast<ssize_t>(pid.size())) {
    const int why = errno;
    close(fd);
    return Status(StatusCode::kInvalidArgument, "cannot write " + path + ": " + std::strerror(why));
  }
  return FolderLock(fd);
}

FolderLock::FolderLock(FolderLock&& other) noexcept : fd_(std::exchange(other.fd_, -1)) {}

FolderLock& FolderLock::operator=(FolderLock&& other) noexcept {
  if (this != &other) {
    if (fd_ >= 0) close(fd_);
    fd_ = std::exchange(other.fd_, -1);
  }
  return *this;
}

FolderLock::~FolderLock() {
  // Closing the last descriptor of the open file releases the flock.
  if (fd_ >= 0) close(fd_);
}

}  // namespace collido::study
