#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <numeric>
#include <unordered_map>
#include <vector>

#include <Eigen/Core>

namespace collido {

// The manifold rules of docs/DESIGN.md ("Contact geometry"), shared by every backend that makes
// its contacts from intersecting triangle pairs (the OBB tree, Embree), so the merge and the cap
// are the same wherever the pairs come from. ContactT is any contact with an Eigen::Vector3d
// `position` and a double `depth`.

/// Merges contacts within `radius` of a deeper one (only coincident ones when it is 0), deepest
/// first, keeping the pairs' order otherwise; returns how many were merged away.
template <class ContactT>
std::uint64_t mergeNearbyContacts(double radius, std::vector<ContactT>& contacts) {
  std::vector<std::size_t> order(contacts.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) {
    return contacts[i].depth > contacts[j].depth;
  });
  std::vector<bool> keep(contacts.size(), false);
  const double cell = radius > 0.0 ? radius : 1.0;
  const auto key = [&](const Eigen::Vector3d& p, int dx, int dy, int dz) {
    if (radius == 0.0) return std::array<double, 3>{p.x(), p.y(), p.z()};
    return std::array<double, 3>{std::floor(p.x() / cell) + dx, std::floor(p.y() / cell) + dy,
                                 std::floor(p.z() / cell) + dz};
  };
  struct KeyHash {
    std::size_t operator()(const std::array<double, 3>& k) const {
      const std::hash<double> h;
      return h(k[0]) ^ (h(k[1]) * 31) ^ (h(k[2]) * 1009);
    }
  };
  std::unordered_map<std::array<double, 3>, std::vector<std::size_t>, KeyHash> kept;
  std::uint64_t merged = 0;
  const int reach = radius > 0.0 ? 1 : 0;
  for (std::size_t i : order) {
    const Eigen::Vector3d& p = contacts[i].position;
    bool near = false;
    for (int dx = -reach; dx <= reach && !near; ++dx) {
      for (int dy = -reach; dy <= reach && !near; ++dy) {
        for (int dz = -reach; dz <= reach && !near; ++dz) {
          const auto found = kept.find(key(p, dx, dy, dz));
          if (found == kept.end()) continue;
          for (std::size_t j : found->second) {
            if ((contacts[j].position - p).norm() <= radius) near = true;
          }
        }
      }
    }
    if (near) {
      ++merged;
      continue;
    }
    keep[i] = true;
    kept[key(p, 0, 0, 0)].push_back(i);
  }
  std::size_t out = 0;
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    if (keep[i]) contacts[out++] = contacts[i];
  }
  contacts.resize(out);
  return merged;
}

/// Keeps `count` contacts: the deepest, then repeatedly the one farthest from those kept, so a
/// capped manifold still spans the contact region; the kept ones stay in their order.
template <class ContactT>
void keepSpreadContacts(std::size_t count, std::vector<ContactT>& contacts) {
  std::size_t first = 0;
  for (std::size_t i = 1; i < contacts.size(); ++i) {
    if (contacts[i].depth > contacts[first].depth) first = i;
  }
  std::vector<double> gap(contacts.size(), std::numeric_limits<double>::infinity());
  std::vector<std::size_t> chosen;
  std::size_t next = first;
  while (chosen.size() < count) {
    chosen.push_back(next);
    gap[next] = -1.0;
    std::size_t farthest = next;
    for (std::size_t i = 0; i < contacts.size(); ++i) {
      if (gap[i] < 0.0) continue;
      gap[i] = std::min(gap[i], (contacts[i].position - contacts[next].position).norm());
      if (farthest == next || gap[i] > gap[farthest]) farthest = i;
    }
    if (farthest == next) break;
    next = farthest;
  }
  std::sort(chosen.begin(), chosen.end());
  std::vector<ContactT> kept;
  kept.reserve(chosen.size());
  for (std::size_t i : chosen)
    kept.push_back(contacts[i]);
  contacts.swap(kept);
}

}  // namespace collido
