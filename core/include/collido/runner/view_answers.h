#pragma once

#include <string>

#include <collido/runner/runner.h>
#include <collido/scene/scene.h>

namespace collido {

/// A backend's answers on a scene as the viewer embeds them (JSON, docs/VIEW.md): per query its
/// status and, per frame and object pair asked, the triangle pairs the backend reported and the
/// oracle's, both verdicts and, for distance queries, both closest-point pairs. `report` must
/// come from one backend's runScene with RunOptions::keep_answers.
std::string viewAnswersJson(const Scene& scene, const RunReport& report,
                            const std::string& backend_label);

}  // namespace collido
