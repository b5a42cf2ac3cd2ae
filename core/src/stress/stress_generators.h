#pragma once

// The generators of the stress categories, one function per category. Each makes one case from
// its severity, its index among the cases of that severity and a sampler seeded for that case
// alone; stress_cases.cpp names the case and checks the arguments.
#include <collido/stress/stress_cases.h>

#include "stress_geometry.h"

namespace collido::stress::detail {

/// What a generator is given for one case.
struct CaseRequest {
  int severity = 0;
  std::size_t index = 0;
  const StressInputs* inputs = nullptr;
};

/// A generator's case: the kind, meshes, poses and aim (name, category, severity and index are
/// filled in by the caller).
using CaseGenerator = StressCase (*)(const CaseRequest& request, Rng& rng);

/// A case from a placed configuration.
StressCase caseOf(std::string kind, Placed placed, Aim aim);

StressCase coplanarCase(const CaseRequest& request, Rng& rng);
StressCase touchingCase(const CaseRequest& request, Rng& rng);
StressCase nearTouchingCase(const CaseRequest& request, Rng& rng);
StressCase farFromOriginCase(const CaseRequest& request, Rng& rng);
StressCase scaledCase(const CaseRequest& request, Rng& rng);
StressCase degenerateCase(const CaseRequest& request, Rng& rng);
StressCase tinyFeaturesCase(const CaseRequest& request, Rng& rng);
StressCase axisRotationsCase(const CaseRequest& request, Rng& rng);
StressCase meshDefectsCase(const CaseRequest& request, Rng& rng);
StressCase distanceCase(const CaseRequest& request, Rng& rng);

}  // namespace collido::stress::detail
