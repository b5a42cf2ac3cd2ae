#pragma once

#include <string>

#include <collido/runner/runner.h>
#include <collido/scene/scene.h>

namespace collido {

/// A backend's answers on a scene as the viewer embeds them (JSON, docs/VIEW.md): per query its
/// status and, per frame, whether the answer disagrees with the oracle and, per object pair
/// asked, the triangle pairs the backend named (all pairs, a witness, or its contacts'
/// triangles) and the oracle's, both verdicts, for boolean and contact queries whether each
/// named pair really intersects, and for distance queries both closest-point pairs. `report`
/// must come from one backend's runScene on `scene` with RunOptions::keep_answers.
std::string viewAnswersJson(const Scene& scene, const RunReport& report,
                            const std::string& backend_label);

}  // namespace collido
