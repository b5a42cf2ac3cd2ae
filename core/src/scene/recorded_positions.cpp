// Recorded positions: "COLLIPOS", version, reserved, vertex count, frame count, then every
// frame's positions as little-endian doubles (scenes/README.md, "Recorded positions").
#include <collido/scene/deformation.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>

#include <collido/mesh/input_file.h>

namespace collido {
namespace {

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__,
              "recordings are little-endian and read in place");

constexpr char kMagic[8] = {'C', 'O', 'L', 'L', 'I', 'P', 'O', 'S'};
constexpr std::uint32_t kVersion = 1;
constexpr std::size_t kHeaderBytes = 32;

template <typename T>
T readAt(const char* bytes) {
  T value;
  std::memcpy(&value, bytes, sizeof value);
  return value;
}

}  // namespace

Result<RecordedPositions> readRecordedPositions(const std::string& path) {
  const auto fail = [&path](const std::string& problem) -> Result<RecordedPositions> {
    return Status(StatusCode::kInvalidArgument, path + ": recorded positions: " + problem);
  };
  if (Status s = checkInputFile(path, "recorded positions"); !s.ok()) return s;
  std::ifstream in(path, std::ios::binary);
  if (!in)
    return Status(StatusCode::kInvalidArgument, path + ": cannot open the recorded positions");
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  in.seekg(0, std::ios::beg);
  if (size < static_cast<std::streamoff>(kHeaderBytes)) {
    return fail("the file has " + std::to_string(size) + " bytes, fewer than the " +
                std::to_string(kHeaderBytes) + "-byte header");
  }
  char header[kHeaderBytes];
  in.read(header, kHeaderBytes);
  if (std::memcmp(header, kMagic, sizeof kMagic) != 0)
    return fail("not a recording (the file does not start with COLLIPOS)");
  const auto version = readAt<std::uint32_t>(header + 8);
  if (version != kVersion) {
    return fail("version " + std::to_string(version) + ", this build reads version " +
                std::to_string(kVersion));
  }
  RecordedPositions out;
  const auto vertices = readAt<std::uint64_t>(header + 16);
  const auto frames = readAt<std::uint64_t>(header + 24);
  if (vertices == 0 || frames == 0)
    return fail("the header gives " + std::to_string(vertices) + " vertices and " +
                std::to_string(frames) + " frames; both must be at least 1");
  const std::uint64_t payload = static_cast<std::uint64_t>(size) - kHeaderBytes;
  // Checked as a division, so that no product of header counts can overflow.
  if (payload % 24 != 0 || payload / 24 / vertices != frames || (payload / 24) % vertices != 0) {
    return fail("the header gives " + std::to_string(vertices) + " vertices x " +
                std::to_string(frames) + " frames, but the file holds " + std::to_string(payload) +
                " bytes of positions (24 per vertex per frame)");
  }
  out.vertices = static_cast<std::size_t>(vertices);
  out.frames = static_cast<std::size_t>(frames);
  out.values.resize(3 * out.vertices * out.frames);
  in.read(reinterpret_cast<char*>(out.values.data()),
          static_cast<std::streamsize>(out.values.size() * sizeof(double)));
  if (!in) return fail("could not read the positions");
  for (std::size_t i = 0; i < out.values.size(); ++i) {
    if (!std::isfinite(out.values[i])) {
      const std::size_t vertex = (i / 3) % out.vertices;
      const std::size_t frame = i / 3 / out.vertices;
      return fail("frame " + std::to_string(frame) + ", vertex " + std::to_string(vertex) +
                  ": a coordinate is not finite");
    }
  }
  return out;
}

Status writeRecordedPositions(const std::string& path, const RecordedPositions& recording) {
  if (recording.values.size() != 3 * recording.vertices * recording.frames)
    return {StatusCode::kInvalidArgument, path + ": the recording's sizes do not match its values"};
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) return {StatusCode::kInvalidArgument, path + ": cannot write"};
  char header[kHeaderBytes] = {};
  std::memcpy(header, kMagic, sizeof kMagic);
  std::memcpy(header + 8, &kVersion, sizeof kVersion);
  const std::uint64_t vertices = recording.vertices;
  const std::uint64_t frames = recording.frames;
  std::memcpy(header + 16, &vertices, sizeof vertices);
  std::memcpy(header + 24, &frames, sizeof frames);
  out.write(header, kHeaderBytes);
  out.write(reinterpret_cast<const char*>(recording.values.data()),
            static_cast<std::streamsize>(recording.values.size() * sizeof(double)));
  if (!out) return {StatusCode::kInvalidArgument, path + ": writing failed"};
  return {};
}

}  // namespace collido
