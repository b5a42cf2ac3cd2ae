#pragma once

// A backend linked into the tests whose failures are scripted, so that tests reach the runner's
// failure paths without an engine. Variant "scripted": every answer is "apart" (no pair, no
// contact), right for scenes whose objects do not touch. Options fail_build=N, fail_update=N
// and fail_query=N make the N-th call of that kind (counted from 1 over the instance's life)
// fail as an engine does, with the message "scripted failure of <kind> call N". Distance queries
// are answered with the option distance=D (default 0) and both closest points at the origin.
#include <memory>

#include <collido/host/plugin_library.h>

namespace collido::test {

/// The linked-in plugin offering "scripted".
std::shared_ptr<PluginLibrary> scriptedBackend();

}  // namespace collido::test
