#pragma once

// Private to core/src/mesh: what the strict readers (OBJ, OFF, PLY, STL) share.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include <collido/status.h>

#include "mesh_import.h"

namespace collido::detail {

/// The whole file, or an error naming it.
Result<std::string> readFileBytes(const std::string& path);

/// A whole token as a double, correctly rounded (std::from_chars: no locale). A leading '+' is
/// allowed (writers emit it); a number beyond the double range reads as an infinity of its sign,
/// so that it is named as non-finite rather than as malformed.
bool parseDouble(std::string_view token, double& value);

/// A whole token as an integer (a leading '+' allowed); false when malformed or out of range.
bool parseInteger(std::string_view token, long long& value);

/// The lines of a text with their 1-based numbers ('\n' ends a line; a '\r' before it is
/// dropped).
class TextLines {
 public:
  explicit TextLines(std::string_view text) : text_(text) {}
  /// Moves to the next line; false after the last.
  bool next();
  std::string_view line() const { return line_; }
  std::size_t number() const { return number_; }
  /// The offset of the first character after the current line (the next line's start).
  std::size_t offset() const { return at_ < text_.size() ? at_ : text_.size(); }
  /// "line N: ", the prefix of a message about the current line.
  std::string where() const { return "line " + std::to_string(number_) + ": "; }

 private:
  std::string_view text_;
  std::size_t at_ = 0;
  std::string_view line_;
  std::size_t number_ = 0;
};

/// The blank-separated tokens of one line. With `comments`, a token that starts with '#' ends
/// the line (OBJ, OFF).
class Tokens {
 public:
  Tokens(std::string_view line, bool comments) : line_(line), comments_(comments) {}
  /// The next token, or "" at the end of the line.
  std::string_view next();
  /// The tokens left, counted without consuming them.
  std::size_t remaining() const;

 private:
  std::string_view line_;
  bool comments_;
  std::size_t at_ = 0;
};

/// Polygons as lists of 0-based vertex indices, each already checked against the vertex count,
/// turned into the triangles of a mesh: faces of three or more corners are fan-triangulated
/// from their first (counted when more than three), shorter ones are not surfaces and are
/// counted as skipped.
class PolygonSoup {
 public:
  void beginFace() { starts_.push_back(corners_.size()); }
  void addCorner(int vertex) { corners_.push_back(vertex); }
  std::size_t faceCount() const { return starts_.size(); }
  /// The mesh of `coordinates` (x, y, z per vertex) and these faces, with what was counted.
  Imported toMesh(const std::vector<double>& coordinates) const;

 private:
  std::vector<int> corners_;
  std::vector<std::size_t> starts_;
};

/// "more vertices than a mesh can index (N)" when `count` exceeds what an int indexes, else "".
std::string vertexCountProblem(unsigned long long count);

}  // namespace collido::detail
