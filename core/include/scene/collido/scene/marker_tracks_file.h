#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include <collido/pose/marker_fit.h>
#include <collido/status.h>

namespace collido {

/// Per frame, the markers seen.
using MarkerTracks = std::vector<std::vector<pose::MarkerObservation>>;

/// Reads the rows of `object` from a marker tracks file: CSV with the header
/// `frame,object,marker,x,y,z` and optionally `weight` (tracking confidence, default 1), lines
/// starting with '#' ignored. A marker missing from a frame was not seen in it. Rows of other
/// objects are skipped. Errors name the file, the line and the problem: a frame outside
/// [0, frames), a marker not in `layout`, one seen twice in a frame, a non-finite coordinate, a
/// weight <= 0, a malformed line, and a file with no row for `object`.
Result<MarkerTracks> readMarkerTracks(const std::string& path, const std::string& object,
                                      std::size_t frames, const pose::MarkerLayout& layout);

/// Writes a tracks file readable by readMarkerTracks: every object's rows, frame by frame,
/// coordinates with 17 significant digits (they read back exactly).
Status writeMarkerTracks(const std::string& path,
                         const std::vector<std::pair<std::string, MarkerTracks>>& objects);

}  // namespace collido
