// STL, binary and ASCII, read strictly. A file that starts with "solid" and holds only text is
// ASCII; anything else is binary (some exporters write "solid" into a binary header, and binary
// STL has no magic number).
//   binary: an 80-byte header, a little-endian uint32 triangle count, then 50 bytes per
//           triangle: the normal and the three corners as little-endian float32, and a 16-bit
//           attribute; bytes after the declared triangles are ignored, as every reader does
//   ASCII:  solid NAME, then per triangle "facet normal nx ny nz / outer loop / vertex x y z
//           (three times) / endloop / endfacet", then endsolid NAME; several solids may follow
//           each other; keywords in any case
// STL repeats each corner per triangle; corners at exactly the same position become one vertex,
// numbered in order of first appearance. The normals are not geometry and are not used.
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "reader_support.h"

namespace collido::detail {
namespace {

constexpr std::size_t kBinaryHeader = 84;
constexpr std::size_t kBinaryTriangle = 50;

// Joins corners at exactly the same position (0 and -0 alike); non-finite corners are never
// joined, so that validateMesh names each.
class CornerIndex {
 public:
  int add(double x, double y, double z) {
    const Position position{x, y, z};
    const bool finite = std::isfinite(x) && std::isfinite(y) && std::isfinite(z);
    if (finite) {
      const auto found = index_.find(position);
      if (found != index_.end()) return found->second;
    }
    const int index = static_cast<int>(coordinates_.size() / 3);
    coordinates_.insert(coordinates_.end(), {x, y, z});
    if (finite) index_.emplace(position, index);
    return index;
  }
  std::size_t size() const { return coordinates_.size() / 3; }
  const std::vector<double>& coordinates() const { return coordinates_; }

 private:
  struct Position {
    double x, y, z;
    bool operator==(const Position& o) const { return x == o.x && y == o.y && z == o.z; }
  };
  struct PositionHash {
    std::size_t operator()(const Position& p) const {
      std::size_t h = 0;
      for (double v : {p.x, p.y, p.z}) {
        const double value = v == 0 ? 0.0 : v;  // -0 and 0 are one position
        std::uint64_t bits = 0;
        std::memcpy(&bits, &value, sizeof bits);
        h = (h ^ bits) * 0x100000001b3ull;
      }
      return h ^ (h >> 29);
    }
  };
  std::unordered_map<Position, int, PositionHash> index_;
  std::vector<double> coordinates_;
};

std::uint32_t littleEndian32(const char* data) {
  std::uint32_t value = 0;
  for (int i = 3; i >= 0; --i)
    value = (value << 8) | static_cast<unsigned char>(data[i]);
  return value;
}

Result<Imported> readBinaryStl(const std::string& path, const std::string& content) {
  if (content.size() < kBinaryHeader) {
    return readError(path, "too short for a binary STL: " + std::to_string(content.size()) +
                               " bytes, but its header and triangle count alone take 84");
  }
  const std::uint32_t count = littleEndian32(content.data() + 80);
  const std::size_t whole = (content.size() - kBinaryHeader) / kBinaryTriangle;
  if (whole < count) {
    return readError(path, "binary STL cut short: its header declares " + std::to_string(count) +
                               " triangles (" +
                               std::to_string(kBinaryHeader + kBinaryTriangle * count) +
                               " bytes), but the file has " + std::to_string(content.size()) +
                               " bytes, room for " + std::to_string(whole));
  }
  CornerIndex corners;
  Imported out;
  out.mesh.triangles.resize(3, static_cast<Eigen::Index>(count));
  for (std::uint32_t t = 0; t < count; ++t) {
    // Skip the normal (12 bytes): the corners follow it.
    const char* triangle = content.data() + kBinaryHeader + kBinaryTriangle * t + 12;
    for (int c = 0; c < 3; ++c) {
      double xyz[3];
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t bits = littleEndian32(triangle + 12 * c + 4 * k);
        float value = 0;
        std::memcpy(&value, &bits, sizeof value);
        xyz[k] = value;
      }
      out.mesh.triangles(c, t) = corners.add(xyz[0], xyz[1], xyz[2]);
    }
  }
  out.mesh.vertices = Eigen::Map<const Eigen::Matrix3Xd>(corners.coordinates().data(), 3,
                                                         static_cast<Eigen::Index>(corners.size()));
  return out;
}

// The tokens of an ASCII STL file across its lines, with the line of the last one read.
class StlTokens {
 public:
  explicit StlTokens(std::string_view text) : lines_(text), tokens_({}, false) {}
  /// The next token, "" at the end of the file.
  std::string_view next() {
    for (;;) {
      const std::string_view token = tokens_.next();
      if (!token.empty()) return token;
      if (!lines_.next()) return {};
      tokens_ = Tokens(lines_.line(), false);
    }
  }
  /// Drops the rest of the current line (a solid's name).
  void skipLine() { tokens_ = Tokens({}, false); }
  std::string where() const { return lines_.where(); }

 private:
  TextLines lines_;
  Tokens tokens_;
};

bool keywordIs(std::string_view token, std::string_view keyword) {
  if (token.size() != keyword.size()) return false;
  for (std::size_t i = 0; i < token.size(); ++i) {
    if (std::tolower(static_cast<unsigned char>(token[i])) != keyword[i]) return false;
  }
  return true;
}

Result<Imported> readAsciiStl(const std::string& path, const std::string& content) {
  StlTokens tokens(content);
  CornerIndex corners;
  std::vector<int> triangles;
  const auto truncated = [&](std::size_t facet) {
    return readError(path, "ASCII STL ends inside facet " + std::to_string(facet) +
                               ", without an 'endsolid' line: the file is truncated");
  };
  // One expected keyword; "" when it is there, else the error.
  const auto expect = [&](std::string_view keyword, std::size_t facet) -> Status {
    const std::string_view token = tokens.next();
    if (token.empty()) return truncated(facet);
    if (keywordIs(token, keyword)) return {};
    return readError(path, tokens.where() + "facet " + std::to_string(facet) + ": expected '" +
                               std::string(keyword) + "', found '" + printable(std::string(token)) +
                               "'");
  };
  for (std::string_view token = tokens.next(); !token.empty(); token = tokens.next()) {
    if (!keywordIs(token, "solid")) {
      return readError(
          path, tokens.where() + "expected 'solid', found '" + printable(std::string(token)) + "'");
    }
    tokens.skipLine();
    for (;;) {
      const std::size_t facet = triangles.size() / 3;
      token = tokens.next();
      if (token.empty()) {
        return readError(path, "ASCII STL without an 'endsolid' line: the file is truncated");
      }
      if (keywordIs(token, "endsolid")) break;
      if (!keywordIs(token, "facet")) {
        return readError(path, tokens.where() + "expected 'facet' or 'endsolid', found '" +
                                   printable(std::string(token)) + "'");
      }
      if (Status s = expect("normal", facet); !s.ok()) return s;
      for (int k = 0; k < 3; ++k) {
        token = tokens.next();
        double ignored = 0;
        if (token.empty()) return truncated(facet);
        if (!parseDouble(token, ignored)) {
          return readError(path, tokens.where() + "facet " + std::to_string(facet) +
                                     " has a malformed normal '" + printable(std::string(token)) +
                                     "'");
        }
      }
      if (Status s = expect("outer", facet); !s.ok()) return s;
      if (Status s = expect("loop", facet); !s.ok()) return s;
      for (int c = 0; c < 3; ++c) {
        if (Status s = expect("vertex", facet); !s.ok()) return s;
        double xyz[3] = {};
        const auto vertex = static_cast<long long>(corners.size());
        std::string out_of_range;
        for (int k = 0; k < 3; ++k) {
          static const char* const kAxis[] = {"x", "y", "z"};
          token = tokens.next();
          if (token.empty()) return truncated(facet);
          if (!parseDouble(token, xyz[k])) {
            return readError(path, tokens.where() + "facet " + std::to_string(facet) +
                                       " has a malformed " + kAxis[k] + " coordinate '" +
                                       printable(std::string(token)) + "'");
          }
          const std::string problem = coordinateProblem(vertex, k, xyz[k], std::string(token));
          if (!problem.empty() && !std::isfinite(xyz[k])) {
            return readError(path, tokens.where() + problem);
          }
          if (out_of_range.empty()) out_of_range = problem;
        }
        if (!out_of_range.empty()) return readError(path, tokens.where() + out_of_range);
        triangles.push_back(corners.add(xyz[0], xyz[1], xyz[2]));
      }
      if (Status s = expect("endloop", facet); !s.ok()) return s;
      if (Status s = expect("endfacet", facet); !s.ok()) return s;
    }
    tokens.skipLine();
  }
  if (std::string problem = vertexCountProblem(corners.size()); !problem.empty()) {
    return readError(path, problem);
  }
  Imported out;
  out.mesh.vertices = Eigen::Map<const Eigen::Matrix3Xd>(corners.coordinates().data(), 3,
                                                         static_cast<Eigen::Index>(corners.size()));
  out.mesh.triangles = Eigen::Map<const Eigen::Matrix3Xi>(
      triangles.data(), 3, static_cast<Eigen::Index>(triangles.size() / 3));
  return out;
}

bool isText(const std::string& content) {
  for (const char c : content) {
    const auto u = static_cast<unsigned char>(c);
    if (!(u == '\n' || u == '\r' || u == '\t' || (u >= ' ' && u < 0x7f))) return false;
  }
  return true;
}

}  // namespace

Result<Imported> readStl(const std::string& path) {
  Result<std::string> bytes = readFileBytes(path);
  if (!bytes.ok()) return bytes.status();
  const std::string& content = bytes.value();
  const std::size_t first = content.find_first_not_of(" \t\r\n");
  const bool ascii =
      first != std::string::npos && content.compare(first, 5, "solid") == 0 && isText(content);
  Result<Imported> out = ascii ? readAsciiStl(path, content) : readBinaryStl(path, content);
  if (out.ok()) out.value().report.importer = ascii ? "STL reader (ASCII)" : "STL reader (binary)";
  return out;
}

}  // namespace collido::detail
