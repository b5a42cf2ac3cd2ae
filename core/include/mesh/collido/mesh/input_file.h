#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <collido/status.h>

namespace collido {

/// The most bytes one input file (scene, mesh, sweep, surface, FRep, recording) may hold:
/// COLLIDO_MAX_INPUT_MB mebibytes when that is set to a positive number, else 1,024 MiB. A
/// sparse 2 GB mesh or /dev/zero is then refused at once, instead of read until memory runs out.
std::uint64_t inputLimitBytes();

/// Refuses, naming `path` and calling it `what` ("scene file", "mesh"), a file that is missing,
/// not a regular file (a folder, a device such as /dev/zero, a pipe) or larger than
/// inputLimitBytes().
Status checkInputFile(const std::string& path, const std::string& what);

/// The whole of an input file after checkInputFile; running out of memory while reading it is an
/// error naming the file, not a bare std::bad_alloc.
Result<std::string> readInputFile(const std::string& path, const std::string& what);

/// While one is alive on a thread, every file checkInputFile passes on that thread is listed in
/// it: a scene's loader gathers this way every file the scene was read from (the scene file, its
/// meshes, recordings and tracks), which a study fingerprints. Nested recorders pass their files
/// on to the enclosing one.
class InputFileRecorder {
 public:
  InputFileRecorder();
  ~InputFileRecorder();
  InputFileRecorder(const InputFileRecorder&) = delete;
  InputFileRecorder& operator=(const InputFileRecorder&) = delete;

  /// The files read so far, each once, in the order first read.
  const std::vector<std::string>& files() const { return files_; }

 private:
  friend Status checkInputFile(const std::string& path, const std::string& what);
  void add(const std::string& path);

  InputFileRecorder* enclosing_;
  std::vector<std::string> files_;
};

}  // namespace collido
