#include <collido/runner/digest.h>

#include <cstdio>
#include <new>

#include <xxhash.h>

namespace collido {

struct Digest::State {
  XXH3_state_t* xxh = nullptr;
};

Digest::Digest() : state_(std::make_unique<State>()) {
  state_->xxh = XXH3_createState();
  if (state_->xxh == nullptr) throw std::bad_alloc();
  XXH3_128bits_reset(state_->xxh);
}

Digest::~Digest() {
  XXH3_freeState(state_->xxh);
}

void Digest::bytes(const void* data, std::size_t size) {
  XXH3_128bits_update(state_->xxh, data, size);
}

void Digest::text(const std::string& s) {
  value(static_cast<std::uint64_t>(s.size()));
  bytes(s.data(), s.size());
}

std::string Digest::hex() const {
  const XXH128_hash_t hash = XXH3_128bits_digest(state_->xxh);
  char text[33];
  std::snprintf(text, sizeof text, "%016llx%016llx", static_cast<unsigned long long>(hash.high64),
                static_cast<unsigned long long>(hash.low64));
  return text;
}

}  // namespace collido
