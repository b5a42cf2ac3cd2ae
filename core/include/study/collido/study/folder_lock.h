#pragma once

#include <string>

#include <collido/status.h>

namespace collido::study {

/// An exclusive hold on a study folder for one driver: `collido study` takes it before it
/// reads or writes anything there, so two drivers on one --out cannot delete each other's
/// scratch files or store each other's results. A lock file (flock on OUT/.lock) holds the
/// holder's PID; the kernel drops the lock when the holder exits, however it exits, so a killed
/// driver never leaves the folder locked. Moving it hands the hold over.
class FolderLock {
 public:
  /// Takes the hold on `folder` (created if missing). Refused, naming the holder's PID, while
  /// another process holds it.
  static Result<FolderLock> acquire(const std::string& folder);

  FolderLock(FolderLock&& other) noexcept;
  FolderLock& operator=(FolderLock&& other) noexcept;
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;
  ~FolderLock();

 private:
  explicit FolderLock(int fd) : fd_(fd) {}
  int fd_ = -1;
};

}  // namespace collido::study
