#pragma once

#include <string>

namespace collido {

/// Where an installed Collidoscope keeps its data (the bundled scenes, the conformance kit's
/// expectations, the dashboard's and viewer's front-end): PREFIX/share/collido, where PREFIX is
/// the folder above the running executable's bin/. Empty when the executable does not run from
/// an install (the build tree), so that callers fall back to the source tree.
std::string installedDataDirectory();

/// Where an installed Collidoscope keeps its loadable libraries (plugins/, the allocation hooks):
/// PREFIX/lib/collido; empty when the executable does not run from an install.
std::string installedLibraryDirectory();

}  // namespace collido
