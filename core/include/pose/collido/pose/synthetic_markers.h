#pragma once

#include <vector>

#include <collido/geometry.h>
#include <collido/pose/marker_fit.h>
#include <collido/random/portable_random.h>

namespace collido::pose {

/// How synthetic marker observations deviate from the truth.
struct MarkerNoise {
  double noise = 0.0;            ///< per-axis standard deviation of each position (Gaussian)
  double dropout = 0.0;          ///< chance a marker is not seen
  double outliers = 0.0;         ///< chance a seen marker is mis-identified
  double outlier_offset = 0.05;  ///< how far a mis-identified marker lands from its true place
};

/// One frame's observations of `layout` on an object at `truth`, drawn from `random`. Every
/// draw is made whatever the outcome, so one marker's dropout does not shift the numbers later
/// markers get (a change to one rate keeps the rest of the tracks).
std::vector<MarkerObservation> observeMarkers(const MarkerLayout& layout, const Pose& truth,
                                              const MarkerNoise& noise, PortableRandom& random);

}  // namespace collido::pose
