#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <type_traits>

namespace collido {

/// A 128-bit digest (xxHash's XXH3-128) of bytes fed in pieces: the same on every run and on
/// every machine of one byte order. Keys of stored oracle answers and fingerprints of a study's
/// inputs use it: with 64 bits, a collision would silently reuse answers of another scene.
class Digest {
 public:
  Digest();
  ~Digest();
  Digest(const Digest&) = delete;
  Digest& operator=(const Digest&) = delete;

  void bytes(const void* data, std::size_t size);
  template <typename T>
  void value(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    bytes(&v, sizeof v);
  }
  /// A string, with its length first, so that ("ab", "c") and ("a", "bc") differ.
  void text(const std::string& s);
  /// 32 lower-case hex digits.
  std::string hex() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace collido
