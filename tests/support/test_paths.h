#pragma once

#include <string>

namespace collido::test {

/// Absolute path of a file in the source tree, e.g. sourcePath("scenes/meshes/bunny.obj").
std::string sourcePath(const std::string& relative);

/// Directory of the plugin shared libraries built with the tests.
std::string pluginDirectory();

/// A fresh, empty temporary directory for one test (removed by the OS, not by the test).
std::string makeTempDirectory(const std::string& hint);

/// Writes `contents` to `path`, creating or replacing the file.
void writeFile(const std::string& path, const std::string& contents);

}  // namespace collido::test
