// A table of what one query decided, by a 64-bit key: open addressing whose slots carry the
// query's stamp, so that a new query clears nothing (begin() only moves the stamp on). The exact
// stages keep in it what many triangle pairs of one query ask again: the sides of vertices
// against planar faces (face_signs.h), the planes of triangles and the determinants of vertices
// against them (contact_signs.h).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace collido::obbtree::detail {

template <typename Value>
class StampedTable {
 public:
  /// Forgets the last query's entries.
  void begin() {
    if (++stamp_ == 0) {  // wrapped: old stamps could collide with new ones
      for (Slot& slot : slots_)
        slot.stamp = 0;
      stamp_ = 1;
    }
    used_ = 0;
  }

  /// The value kept for the key this query, or null.
  const Value* find(std::uint64_t key) const {
    if (slots_.empty()) return nullptr;
    const std::size_t mask = slots_.size() - 1;
    for (std::size_t i = slotOf(key);; i = (i + 1) & mask) {
      const Slot& slot = slots_[i];
      if (slot.stamp != stamp_) return nullptr;  // the table is never full: an empty slot ends it
      if (slot.key == key) return &slot.value;
    }
  }

  /// Keeps the value for the key (a key kept already keeps its first value).
  void store(std::uint64_t key, const Value& value) {
    if (2 * (used_ + 1) > slots_.size()) grow();
    const std::size_t mask = slots_.size() - 1;
    for (std::size_t i = slotOf(key);; i = (i + 1) & mask) {
      Slot& slot = slots_[i];
      if (slot.stamp != stamp_) {
        slot.key = key;
        slot.stamp = stamp_;
        slot.value = value;
        ++used_;
        return;
      }
      if (slot.key == key) return;
    }
  }

  std::size_t bytes() const { return slots_.capacity() * sizeof(Slot); }

 private:
  struct Slot {
    std::uint64_t key = 0;
    std::uint32_t stamp = 0;
    Value value{};
  };

  std::size_t slotOf(std::uint64_t key) const {
    return static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ULL) >> shift_);
  }

  void grow() {
    std::vector<Slot> old;
    old.swap(slots_);
    const std::size_t size = old.empty() ? 256 : 2 * old.size();
    slots_.assign(size, Slot{});
    shift_ = 64 - __builtin_ctzll(size);
    const std::uint32_t stamp = stamp_;
    stamp_ = 1;  // the new table holds no stamp yet
    used_ = 0;
    const std::size_t mask = slots_.size() - 1;
    for (const Slot& slot : old) {
      if (slot.stamp != stamp) continue;
      std::size_t i = slotOf(slot.key);
      while (slots_[i].stamp == stamp_)
        i = (i + 1) & mask;
      slots_[i] = slot;
      slots_[i].stamp = stamp_;
      ++used_;
    }
  }

  std::vector<Slot> slots_;
  std::uint32_t stamp_ = 0;
  std::size_t used_ = 0;
  int shift_ = 64;
};

}  // namespace collido::obbtree::detail
