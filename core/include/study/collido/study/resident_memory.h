#pragma once

#include <cstddef>
#include <optional>

namespace collido::study {

/// The resident memory a part of a worker adds at its peak, apart from what the worker held
/// before (the scene, the oracle's answers): how a study charges memory to the backend alone.
class ResidentPeak {
 public:
  /// Returns freed heap to the system (malloc_trim), notes the resident set, and resets the
  /// kernel's peak (writing 5 to /proc/self/clear_refs). available() is false where that fails.
  ResidentPeak();

  bool available() const { return baseline_.has_value(); }
  /// The peak resident set since construction over the resident set at construction (0 when it
  /// never grew); nullopt when not available.
  std::optional<std::size_t> addedBytes() const;

 private:
  std::optional<std::size_t> baseline_;
};

}  // namespace collido::study
