#pragma once

#include <string>
#include <vector>

#include <collido/scene/scene.h>
#include <collido/status.h>

namespace collido::view {

/// One backend's part of a view: its answers (viewAnswersJson), or why it has none (a crash,
/// a timeout, a failure to load), shown in the page instead.
struct ViewBackend {
  std::string label;
  std::string answers_json;  ///< empty when `problem` says why
  std::string problem;
};

/// The scene's view: one self-contained HTML page (opens offline) with three.js, the viewer's
/// script and style from `web_directory`, the scene's geometry (every state's mesh, deformed
/// vertices per frame, as binary), the poses of every object per frame (recovered and true for
/// tracked objects, with their markers), and the backends' answers, all inline. Errors name a
/// missing front-end file and how to get it.
Result<std::string> renderViewPage(const Scene& scene, const std::vector<ViewBackend>& backends,
                                   const std::string& web_directory);

/// Whether `web_directory` holds every front-end file a view needs (an error naming the first
/// missing one and how to get it): checked before any backend runs.
Status checkViewFrontEnd(const std::string& web_directory);

}  // namespace collido::view
