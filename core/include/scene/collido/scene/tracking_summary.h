#pragma once

#include <cstddef>
#include <string>

#include <collido/scene/scene.h>

namespace collido {

/// How well an object's poses were recovered from its tracked markers, over all frames: the
/// recovered poses against the true ones (pose::poseError over the rest mesh's vertices).
struct TrackingSummary {
  std::size_t frames = 0;
  std::size_t lost = 0;       ///< frames whose fit failed (previous pose held)
  std::size_t outliers = 0;   ///< markers rejected, summed over frames
  double markers_seen = 0.0;  ///< mean per frame
  double rotation_deg_median = 0.0;
  double rotation_deg_max = 0.0;
  double translation_median = 0.0;
  double translation_max = 0.0;
  double worst_vertex_median = 0.0;  ///< per frame the largest vertex displacement
  double worst_vertex_max = 0.0;
  double sigma_median = 0.0;  ///< TrackedFrame::sigma over frames that have one; NaN if none

  /// One line for people: "6 markers (generated: ...), rigid fit: worst vertex median 1.2 mm ..."
  std::string text(const MarkerTracking& tracking) const;
};

/// The summary of a tracked object (object.tracking must be set).
TrackingSummary summarizeTracking(const SceneObject& object);

}  // namespace collido
