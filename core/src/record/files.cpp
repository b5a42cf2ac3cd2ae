#include "files.h"

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include <collido/record/recorder.h>

namespace collido::record {
namespace {

// Appends `value`'s bytes in little-endian order, whatever the machine's.
template <typename T>
void appendLittleEndian(std::string& out, T value) {
  static_assert(sizeof(T) == 4 || sizeof(T) == 8);
  using Bits = std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>;
  Bits bits = 0;
  std::memcpy(&bits, &value, sizeof bits);
  for (std::size_t k = 0; k < sizeof bits; ++k)
    out.push_back(static_cast<char>((bits >> (8 * k)) & 0xffu));
}

// FNV-1a and a splitmix-finalised word sum: two unrelated hashes of the same bytes.
struct Digest {
  std::uint64_t fnv = 0xcbf29ce484222325ull;
  std::uint64_t mix = 0x9e3779b97f4a7c15ull;

  void add(const void* data, std::size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) {
      fnv = (fnv ^ bytes[i]) * 0x100000001b3ull;
      std::uint64_t z = (mix += 0x9e3779b97f4a7c15ull + bytes[i]);
      z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
      z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
      mix = z ^ (z >> 31);
    }
  }
};

}  // namespace

void writeFileAtomically(const std::string& path, const std::string& bytes) {
  const std::string temporary = path + ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.flush();
    if (!out) throw RecordError(temporary + ": cannot be written");
  }
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) throw RecordError(path + ": cannot be written (" + error.message() + ")");
}

std::string meshDigest(const Eigen::Matrix3Xd& vertices, const Eigen::Matrix3Xi& triangles) {
  Digest d;
  const std::uint64_t counts[2] = {static_cast<std::uint64_t>(vertices.cols()),
                                   static_cast<std::uint64_t>(triangles.cols())};
  d.add(counts, sizeof counts);
  d.add(vertices.data(), sizeof(double) * static_cast<std::size_t>(vertices.size()));
  d.add(triangles.data(), sizeof(int) * static_cast<std::size_t>(triangles.size()));
  char text[33];
  std::snprintf(text, sizeof text, "%016llx%016llx", static_cast<unsigned long long>(d.fnv),
                static_cast<unsigned long long>(d.mix));
  return text;
}

std::string plyBytes(const Eigen::Matrix3Xd& vertices, const Eigen::Matrix3Xi& triangles) {
  std::string out =
      "ply\nformat binary_little_endian 1.0\ncomment collido::Recorder\nelement vertex " +
      std::to_string(vertices.cols()) +
      "\nproperty double x\nproperty double y\nproperty double z\nelement face " +
      std::to_string(triangles.cols()) + "\nproperty list uchar int vertex_indices\nend_header\n";
  out.reserve(out.size() + 24 * static_cast<std::size_t>(vertices.cols()) +
              13 * static_cast<std::size_t>(triangles.cols()));
  for (Eigen::Index v = 0; v < vertices.cols(); ++v) {
    for (int k = 0; k < 3; ++k)
      appendLittleEndian(out, vertices(k, v));
  }
  for (Eigen::Index t = 0; t < triangles.cols(); ++t) {
    out.push_back(3);
    for (int k = 0; k < 3; ++k)
      appendLittleEndian(out, static_cast<std::int32_t>(triangles(k, t)));
  }
  return out;
}

}  // namespace collido::record
