#include "frame_ranges_reader.h"

#include <algorithm>
#include <cstdint>
#include <string>

namespace collido {

bool FrameRanges::contains(std::size_t frame) const {
  if (ranges.empty()) return true;
  // The first range ending at or after `frame` is the only one that can hold it.
  const auto found = std::lower_bound(ranges.begin(), ranges.end(), frame,
                                      [](const std::pair<std::size_t, std::size_t>& range,
                                         std::size_t f) { return range.second < f; });
  return found != ranges.end() && found->first <= frame;
}

std::size_t FrameRanges::countIn(std::size_t frames) const {
  if (ranges.empty()) return frames;
  std::size_t count = 0;
  for (const auto& [first, last] : ranges) {
    if (first >= frames) break;
    count += std::min(last, frames - 1) - first + 1;
  }
  return count;
}

std::string FrameRanges::text() const {
  if (ranges.empty()) return "every frame";
  std::string out =
      ranges.size() == 1 && ranges[0].first == ranges[0].second ? "frame " : "frames ";
  for (const auto& [first, last] : ranges) {
    if (&first != &ranges.front().first) out += ", ";
    out += std::to_string(first) + (last == first ? "" : "-" + std::to_string(last));
  }
  return out;
}

namespace scene_reading {

FrameRanges readFrameRanges(const Reader& r, const Node& node, std::size_t frames) {
  r.expectArray(node);
  if (node.value.empty()) r.fail(node, "expected at least one [first, last] range of frames");
  FrameRanges read;
  const auto last_frame = static_cast<std::int64_t>(frames) - 1;
  for (std::size_t i = 0; i < node.value.size(); ++i) {
    const Node range = node.at(i);
    r.expectArray(range);
    if (range.value.size() != 2) {
      r.fail(range, "expected [first, last] (two frames), got " +
                        std::to_string(range.value.size()) + " items");
    }
    std::size_t ends[2] = {0, 0};
    for (std::size_t k = 0; k < 2; ++k) {
      const std::int64_t frame = r.integer(range.at(k), 0, INT64_MAX);
      if (frame > last_frame) {
        r.fail(range.at(k), "frame " + std::to_string(frame) + " is past the scene's last (" +
                                std::to_string(last_frame) + ": it has " + std::to_string(frames) +
                                " frames)");
      }
      ends[k] = static_cast<std::size_t>(frame);
    }
    const std::size_t first = ends[0];
    const std::size_t last = ends[1];
    if (last < first) r.fail(range, "the last frame comes before the first");
    // Ranges in order and apart, so that one list of frames has one way to be written.
    if (!read.ranges.empty() && first <= read.ranges.back().second + 1) {
      r.fail(range, "ranges must be ascending and apart: this one starts at frame " +
                        std::to_string(first) + ", the one before ends at " +
                        std::to_string(read.ranges.back().second));
    }
    read.ranges.emplace_back(first, last);
  }
  return read;
}

void checkQueryFrames(const Reader& r, const Node& queries, const Scene& scene) {
  for (std::size_t i = 0; i < scene.queries.size(); ++i) {
    const SceneQuery& query = scene.queries[i];
    const Node node = queries.at(i);
    const Node& where = node.has("frames") ? node.at("frames") : node;
    // A step from frame k needs both objects in k and in k + 1.
    const bool over_a_step = queryKindInfo(query.request.kind).over_a_step;
    if (over_a_step && scene.frames > 0 && query.asked.contains(scene.frames - 1)) {
      r.fail(where, "query '" + query.name + "' is asked over a step from frame " +
                        std::to_string(scene.frames - 1) +
                        ", the last: a step needs the frame after it");
    }
    if (query.isGroup()) continue;  // the broad phase passes only pairs of present objects
    for (const std::size_t object : {query.a, query.b}) {
      const FrameRanges& present = scene.objects[object].present;
      if (present.everyFrame()) continue;
      for (std::size_t frame = 0; frame < scene.frames; ++frame) {
        if (!query.asked.contains(frame)) continue;
        for (const std::size_t needed : {frame, frame + 1}) {
          if (needed == frame + 1 && !over_a_step) break;
          if (present.contains(needed)) continue;
          r.fail(where, "query '" + query.name + "' is asked " +
                            (over_a_step ? "over the step from frame " : "in frame ") +
                            std::to_string(frame) + ", but object '" + scene.objects[object].name +
                            "' does not exist in frame " + std::to_string(needed));
        }
      }
    }
  }
}

}  // namespace scene_reading
}  // namespace collido
