#pragma once

#include <cstdint>
#include <string>

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

}  // namespace collido
