// Sort and sweep over two sets of boxes along one axis, shared by the oracle's proximity and
// distance searches.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

namespace collido::detail {

/// Calls visit(i, j) for every box i of A and j of B whose extents along the sweep axis come
/// within `reach` of each other ([lo, hi] given by lo_a(i), hi_a(i), lo_b(j), hi_b(j)), in sweep
/// order; the caller checks the other axes. Stops, returning false, when visit returns false.
template <typename LoA, typename HiA, typename LoB, typename HiB, typename Visit>
bool sweepPairs(std::size_t count_a, LoA lo_a, HiA hi_a, std::size_t count_b, LoB lo_b, HiB hi_b,
                double reach, Visit&& visit) {
  struct Entry {
    double start;
    bool from_a;
    std::size_t index;
  };
  std::vector<Entry> entries;
  entries.reserve(count_a + count_b);
  for (std::size_t i = 0; i < count_a; ++i)
    entries.push_back({lo_a(i) - reach, true, i});  // A's boxes enter early by the reach
  for (std::size_t j = 0; j < count_b; ++j)
    entries.push_back({lo_b(j), false, j});
  std::sort(entries.begin(), entries.end(),
            [](const Entry& l, const Entry& r) { return l.start < r.start; });
  std::vector<std::size_t> open_a;
  std::vector<std::size_t> open_b;
  for (const Entry& e : entries) {
    // What ends before this one starts leaves the active lists for good.
    const auto ended_a = [&](std::size_t i) { return hi_a(i) + reach < e.start; };
    const auto ended_b = [&](std::size_t j) { return hi_b(j) < e.start; };
    open_a.erase(std::remove_if(open_a.begin(), open_a.end(), ended_a), open_a.end());
    open_b.erase(std::remove_if(open_b.begin(), open_b.end(), ended_b), open_b.end());
    if (e.from_a) {
      for (std::size_t j : open_b) {
        if (!visit(e.index, j)) return false;
      }
      open_a.push_back(e.index);
    } else {
      for (std::size_t i : open_a) {
        if (!visit(i, e.index)) return false;
      }
      open_b.push_back(e.index);
    }
  }
  return true;
}

}  // namespace collido::detail
