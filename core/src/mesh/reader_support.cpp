// What the strict mesh readers share: whole-file reading, exact number parsing, line and token
// scanning, and turning polygons into triangles.
#include "reader_support.h"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <limits>
#include <system_error>

namespace collido::detail {
namespace {

constexpr std::string_view kBlank = " \t\r\f\v";

}  // namespace

Result<std::string> readFileBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return readError(path, "cannot be opened");
  std::string content((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) return readError(path, "cannot be read");
  return content;
}

std::string printable(const std::string& token) {
  constexpr std::size_t kMaxLength = 40;
  std::string out = token.substr(0, kMaxLength);
  for (char& c : out) {
    if (c < ' ' || c > '~') c = '?';
  }
  return token.size() > kMaxLength ? out + "..." : out;
}

std::string coordinateProblem(long long vertex, int axis, double value, const std::string& token) {
  static_assert(kMaxCoordinate == 1e18, "the message below says 1e18");
  if (std::isfinite(value) && std::abs(value) <= kMaxCoordinate) return "";
  static const char* const kAxis[] = {"x", "y", "z"};
  const std::string name = kAxis[axis];
  if (!std::isfinite(value)) {
    return "vertex " + std::to_string(vertex) + " has a non-finite " + name + " coordinate ('" +
           printable(token) + "')";
  }
  return "vertex " + std::to_string(vertex) + " has " + name + " coordinate '" + printable(token) +
         "', beyond the coordinate limit |" + name + "| <= 1e18 (scenes/README.md)";
}

bool parseDouble(std::string_view token, double& value) {
  if (token.size() > 1 && token.front() == '+' && token[1] != '-') token.remove_prefix(1);
  const char* const end = token.data() + token.size();
  const auto [stop, error] = std::from_chars(token.data(), end, value);
  if (error == std::errc::result_out_of_range && stop == end) {
    // Beyond the double range (an infinity of its sign, named later as non-finite) or below it
    // (zero or a subnormal): from_chars leaves `value` alone, strtod gives both. The text is
    // known to be a plain number, so strtod reads all of it.
    value = std::strtod(std::string(token).c_str(), nullptr);
    return true;
  }
  return error == std::errc() && stop == end && !token.empty();
}

bool parseInteger(std::string_view token, long long& value) {
  if (token.size() > 1 && token.front() == '+' && token[1] != '-') token.remove_prefix(1);
  const char* const end = token.data() + token.size();
  const auto [stop, error] = std::from_chars(token.data(), end, value);
  return error == std::errc() && stop == end && !token.empty();
}

bool TextLines::next() {
  if (at_ >= text_.size()) return false;
  std::size_t end = text_.find('\n', at_);
  if (end == std::string_view::npos) end = text_.size();
  line_ = text_.substr(at_, end - at_);
  if (!line_.empty() && line_.back() == '\r') line_.remove_suffix(1);
  at_ = end + 1;
  ++number_;
  return true;
}

std::string_view Tokens::next() {
  const std::size_t begin = line_.find_first_not_of(kBlank, at_);
  if (begin == std::string_view::npos || (comments_ && line_[begin] == '#')) {
    at_ = line_.size();
    return {};
  }
  std::size_t end = line_.find_first_of(kBlank, begin);
  if (end == std::string_view::npos) end = line_.size();
  at_ = end;
  return line_.substr(begin, end - begin);
}

std::size_t Tokens::remaining() const {
  Tokens copy = *this;
  std::size_t count = 0;
  while (!copy.next().empty())
    ++count;
  return count;
}

Imported PolygonSoup::toMesh(const std::vector<double>& coordinates) const {
  Imported out;
  const auto vertex_count = static_cast<Eigen::Index>(coordinates.size() / 3);
  out.mesh.vertices = Eigen::Map<const Eigen::Matrix3Xd>(coordinates.data(), 3, vertex_count);
  std::size_t triangle_total = 0;
  for (std::size_t f = 0; f < starts_.size(); ++f) {
    const std::size_t end = f + 1 < starts_.size() ? starts_[f + 1] : corners_.size();
    if (end - starts_[f] >= 3) triangle_total += end - starts_[f] - 2;
  }
  out.mesh.triangles.resize(3, static_cast<Eigen::Index>(triangle_total));
  Eigen::Index next = 0;
  for (std::size_t f = 0; f < starts_.size(); ++f) {
    const std::size_t first = starts_[f];
    const std::size_t size = (f + 1 < starts_.size() ? starts_[f + 1] : corners_.size()) - first;
    if (size < 3) {
      ++out.report.skipped_primitives;
      continue;
    }
    if (size > 3) ++out.report.polygons_triangulated;
    for (std::size_t k = 1; k + 1 < size; ++k) {
      out.mesh.triangles.col(next++) << corners_[first], corners_[first + k],
          corners_[first + k + 1];
    }
  }
  return out;
}

std::string vertexCountProblem(unsigned long long count) {
  if (count <= static_cast<unsigned long long>(std::numeric_limits<int>::max())) return "";
  return "more vertices than a mesh can index (" + std::to_string(count) + ")";
}

}  // namespace collido::detail
