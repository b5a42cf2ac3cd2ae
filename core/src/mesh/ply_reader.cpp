// PLY (Stanford polygon file format), ASCII and binary of either byte order, read strictly.
//   header  "ply", "format ascii|binary_little_endian|binary_big_endian VERSION", then
//           "element NAME COUNT" each followed by its "property TYPE NAME" or
//           "property list COUNT_TYPE ITEM_TYPE NAME" lines, "comment" and "obj_info" lines
//           anywhere, and "end_header"; types are char/int8, uchar/uint8, short/int16,
//           ushort/uint16, int/int32, uint/uint32, float/float32, double/float64
//   geometry the 'vertex' element's x, y, z (any numeric type) and the 'face' element's list
//           'vertex_indices' (or 'vertex_index') of 0-based integer indices; every other
//           element and property is read, checked against its type, and not used
//   values  are of their declared type: a float property in ASCII reads as the nearest float,
//           as a binary file would hold it
//   ASCII   one element per line; binary: the elements' bytes back to back, bytes after the last
//           ignored
// Errors name the file, the header line or the data line (ASCII), and the element (0-based)
// with the text as written.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include "reader_support.h"

namespace collido::detail {
namespace {

struct PlyType {
  std::string_view name;  // as written in the header
  int size = 0;           // bytes in binary data; 0 for an unknown type
  bool integral = false;
  bool is_signed = false;
};

PlyType plyType(std::string_view name) {
  static constexpr PlyType kTypes[] = {
      {"char", 1, true, true},    {"int8", 1, true, true},     {"uchar", 1, true, false},
      {"uint8", 1, true, false},  {"short", 2, true, true},    {"int16", 2, true, true},
      {"ushort", 2, true, false}, {"uint16", 2, true, false},  {"int", 4, true, true},
      {"int32", 4, true, true},   {"uint", 4, true, false},    {"uint32", 4, true, false},
      {"float", 4, false, true},  {"float32", 4, false, true}, {"double", 8, false, true},
      {"float64", 8, false, true}};
  for (const PlyType& type : kTypes) {
    if (type.name == name) return type;
  }
  return {name, 0, false, false};
}

struct PlyProperty {
  std::string name;
  PlyType type;        // the scalar, or a list's items
  PlyType count_type;  // a list's count; size 0 for a scalar
  bool isList() const { return count_type.size != 0; }
};

struct PlyElement {
  std::string name;
  unsigned long long count = 0;
  std::vector<PlyProperty> properties;
};

// What the header declares, and where in it the geometry is.
struct PlyHeader {
  std::string format;
  std::vector<PlyElement> elements;
  std::size_t data_start = 0;
  int vertex_element = -1;
  int face_element = -1;
  int coordinate[3] = {-1, -1, -1};  // properties of the vertex element
  int indices = -1;                  // property of the face element
};

// A number as read: an integer type's value exactly, a real type's rounded to its type.
struct PlyNumber {
  long long integer = 0;
  double real = 0;
};

bool fitsType(long long value, const PlyType& type) {
  const int bits = 8 * type.size;
  if (type.is_signed) {
    const long long limit = 1LL << (bits - 1);
    return value >= -limit && value < limit;
  }
  return value >= 0 && (bits >= 63 || value < (1LL << bits));
}

// Parses the header into `header`; "" when it is whole and known, else the problem.
std::string parseHeader(const std::string& content, PlyHeader& header) {
  if (content.compare(0, 3, "ply") != 0 ||
      (content.size() > 3 && content[3] != '\n' && content[3] != '\r')) {
    return "not a PLY file (it does not start with a 'ply' line)";
  }
  TextLines lines(content);
  lines.next();
  while (lines.next()) {
    Tokens tokens(lines.line(), false);
    const std::string_view word = tokens.next();
    const std::string where = "header line " + std::to_string(lines.number()) + ": ";
    if (word.empty() || word == "comment" || word == "obj_info") continue;
    if (word == "end_header") {
      header.data_start = lines.offset();
      if (header.format.empty()) return "the header has no 'format' line";
      return "";
    }
    // A last line without its newline is a header cut short (the file ends inside it).
    if (lines.offset() == content.size() && content.back() != '\n') break;
    if (word == "format") {
      header.format = std::string(tokens.next());
      if (header.format != "ascii" && header.format != "binary_little_endian" &&
          header.format != "binary_big_endian") {
        return where + "unknown format '" + printable(header.format) + "'";
      }
    } else if (word == "element") {
      PlyElement element;
      element.name = std::string(tokens.next());
      const std::string_view count = tokens.next();
      long long value = 0;
      if (!parseInteger(count, value) || value < 0) {
        return where + "element '" + printable(element.name) + "' has no valid count ('" +
               printable(std::string(count)) + "')";
      }
      element.count = static_cast<unsigned long long>(value);
      const int index = static_cast<int>(header.elements.size());
      int* role = element.name == "vertex" ? &header.vertex_element
                  : element.name == "face" ? &header.face_element
                                           : nullptr;
      if (role != nullptr && *role >= 0) return where + "a second '" + element.name + "' element";
      if (role != nullptr) *role = index;
      header.elements.push_back(std::move(element));
    } else if (word == "property") {
      if (header.elements.empty()) return where + "a property before any element";
      PlyProperty property;
      const std::string_view type = tokens.next();
      if (type == "list") {
        const std::string_view count_type = tokens.next();
        property.count_type = plyType(count_type);
        if (property.count_type.size == 0 || !property.count_type.integral) {
          return where + "unknown list count type '" + printable(std::string(count_type)) + "'";
        }
        property.type = plyType(tokens.next());
      } else {
        property.type = plyType(type);
      }
      if (property.type.size == 0) {
        return where + "unknown type '" + printable(std::string(property.type.name)) + "'";
      }
      property.name = std::string(tokens.next());
      if (property.name.empty()) return where + "a property without a name";
      PlyElement& element = header.elements.back();
      const int index = static_cast<int>(element.properties.size());
      const int element_index = static_cast<int>(header.elements.size()) - 1;
      if (element_index == header.vertex_element) {
        for (int k = 0; k < 3; ++k) {
          if (property.name != std::string(1, static_cast<char>('x' + k))) continue;
          if (property.isList())
            return where + "vertex coordinate '" + property.name + "' is a list";
          header.coordinate[k] = index;
        }
      }
      if (element_index == header.face_element &&
          (property.name == "vertex_indices" || property.name == "vertex_index")) {
        if (!property.isList() || !property.type.integral) {
          return where + "'" + property.name + "' must be a list of integers";
        }
        header.indices = index;
      }
      element.properties.push_back(std::move(property));
    } else {
      return where + "unknown header keyword '" + printable(std::string(word)) + "'";
    }
  }
  return "the header has no 'end_header' line (the file is truncated, or not PLY)";
}

// Where the data is read from: ASCII lines or binary bytes, one element instance at a time.
class PlySource {
 public:
  PlySource(const std::string& content, const PlyHeader& header)
      : content_(content),
        lines_(std::string_view(content).substr(header.data_start)),
        tokens_({}, false),
        at_(header.data_start),
        ascii_(header.format == "ascii"),
        big_endian_(header.format == "binary_big_endian"),
        first_line_(countLines(content, header.data_start)) {}

  bool ascii() const { return ascii_; }
  /// Starts an instance: ASCII moves to its line; false at the end of the data.
  bool begin() {
    if (!ascii_) return true;
    while (lines_.next()) {
      tokens_ = Tokens(lines_.line(), false);
      if (tokens_.remaining() != 0) return true;
    }
    return false;
  }
  /// Reads one value of `type` into `number`; "" when fine, "end" when the data ends, else the
  /// problem (ASCII: the text does not read as the type).
  std::string read(const PlyType& type, PlyNumber& number, std::string_view& text) {
    if (ascii_) {
      text = tokens_.next();
      if (text.empty()) return "end";
      if (type.integral) {
        if (!parseInteger(text, number.integer) || !fitsType(number.integer, type)) {
          return "is " + std::string(type.name) + ", but reads '" + printable(std::string(text)) +
                 "'";
        }
        number.real = static_cast<double>(number.integer);
        return "";
      }
      if (!parseDouble(text, number.real)) {
        return "is " + std::string(type.name) + ", but reads '" + printable(std::string(text)) +
               "'";
      }
      if (type.size == 4) number.real = static_cast<float>(number.real);
      return "";
    }
    const auto size = static_cast<std::size_t>(type.size);
    if (content_.size() - at_ < size) return "end";
    std::uint64_t bits = 0;
    for (std::size_t i = 0; i < size; ++i) {
      const std::size_t byte = big_endian_ ? i : size - 1 - i;
      bits = (bits << 8) | static_cast<unsigned char>(content_[at_ + byte]);
    }
    at_ += size;
    if (type.integral) {
      const int shift = 64 - 8 * type.size;
      number.integer =
          type.is_signed ? static_cast<long long>(static_cast<std::int64_t>(bits << shift) >> shift)
                         : static_cast<long long>(bits);
      number.real = static_cast<double>(number.integer);
    } else if (type.size == 4) {
      const auto narrow = static_cast<std::uint32_t>(bits);
      float value = 0;
      std::memcpy(&value, &narrow, sizeof value);
      number.real = value;
    } else {
      std::memcpy(&number.real, &bits, sizeof number.real);
    }
    return "";
  }
  /// ASCII: the instance's line holds nothing more.
  bool lineDone() const { return !ascii_ || tokens_.remaining() == 0; }
  /// ASCII: whether any data follows the current line.
  bool moreLines() const {
    TextLines rest = lines_;
    while (rest.next()) {
      if (Tokens(rest.line(), false).remaining() != 0) return true;
    }
    return false;
  }
  /// "line N: " in ASCII, "" in binary.
  std::string where() const {
    return ascii_ ? "line " + std::to_string(first_line_ + lines_.number()) + ": " : "";
  }
  std::size_t bytesLeft() const { return content_.size() - at_; }

 private:
  static std::size_t countLines(const std::string& content, std::size_t at) {
    std::size_t count = 0;
    for (std::size_t i = 0; i < at; ++i)
      count += content[i] == '\n' ? 1 : 0;
    return count;
  }

  const std::string& content_;
  TextLines lines_;
  Tokens tokens_;
  std::size_t at_;
  bool ascii_;
  bool big_endian_;
  std::size_t first_line_;
};

Result<Imported> readData(const std::string& path, const std::string& content,
                          const PlyHeader& header) {
  PlySource source(content, header);
  const long long vertex_count =
      header.vertex_element < 0
          ? 0
          : static_cast<long long>(
                header.elements[static_cast<std::size_t>(header.vertex_element)].count);
  std::vector<double> coordinates;
  PolygonSoup soup;
  for (std::size_t e = 0; e < header.elements.size(); ++e) {
    const PlyElement& element = header.elements[e];
    const bool vertex = static_cast<int>(e) == header.vertex_element;
    const bool face = static_cast<int>(e) == header.face_element;
    if (element.properties.empty()) continue;  // no data, however many it declares
    if (vertex) coordinates.reserve(3 * std::min<std::size_t>(element.count, content.size()));
    for (unsigned long long i = 0; i < element.count; ++i) {
      const auto instance = [&] {
        return "'" + printable(element.name) + "' " + std::to_string(i);
      };
      const auto truncated = [&]() {
        return readError(path, "the file ends early: the data stops in " + instance() +
                                   " (0-based) of the " + std::to_string(element.count) +
                                   " that the header declares");
      };
      if (!source.begin()) return truncated();
      // A value that is missing: the end of the file, or (ASCII) a line cut short.
      const auto missing = [&](const PlyProperty& p) {
        if (!source.ascii() || !source.moreLines()) return truncated();
        return readError(path, source.where() + instance() + " ends before its property '" +
                                   printable(p.name) + "'");
      };
      double xyz[3] = {};
      for (std::size_t p = 0; p < element.properties.size(); ++p) {
        const PlyProperty& property = element.properties[p];
        PlyNumber number;
        std::string_view text;
        if (!property.isList()) {
          const std::string problem = source.read(property.type, number, text);
          if (problem == "end") return missing(property);
          if (!problem.empty()) {
            return readError(path, source.where() + instance() + ": property '" +
                                       printable(property.name) + "' " + problem);
          }
          for (int k = 0; k < 3 && vertex; ++k) {
            if (header.coordinate[k] != static_cast<int>(p)) continue;
            xyz[k] = number.real;
            // ASCII names a bad coordinate with its text; binary ones are named by validateMesh.
            if (!source.ascii()) continue;
            const std::string bad =
                coordinateProblem(static_cast<long long>(i), k, number.real, std::string(text));
            if (!bad.empty()) return readError(path, source.where() + bad);
          }
          continue;
        }
        const std::string problem = source.read(property.count_type, number, text);
        if (problem == "end") return missing(property);
        const auto list = [&] {
          return source.where() + instance() + ": the list '" + printable(property.name) + "'";
        };
        if (!problem.empty()) {
          return readError(
              path, list() + " has no valid length ('" + printable(std::string(text)) + "')");
        }
        if (number.integer < 0) {
          return readError(
              path, list() + " has a negative length (" + std::to_string(number.integer) + ")");
        }
        const long long length = number.integer;
        if (!source.ascii() &&
            static_cast<unsigned long long>(length) >
                source.bytesLeft() / static_cast<std::size_t>(property.type.size)) {
          return truncated();
        }
        const bool indices = face && header.indices == static_cast<int>(p);
        if (indices) soup.beginFace();
        for (long long k = 0; k < length; ++k) {
          const std::string item = source.read(property.type, number, text);
          if (item == "end") return missing(property);
          if (!item.empty())
            return readError(path, list() + ": item " + std::to_string(k) + " " + item);
          if (!indices) continue;
          if (number.integer < 0 || number.integer >= vertex_count) {
            return readError(path, source.where() + "face " + std::to_string(i) +
                                       " references vertex " + std::to_string(number.integer) +
                                       " (0-based), but the file has " +
                                       std::to_string(vertex_count) + " vertices");
          }
          soup.addCorner(static_cast<int>(number.integer));
        }
      }
      if (!source.lineDone()) {
        return readError(path,
                         source.where() + instance() + " has more values than its properties");
      }
      if (vertex) coordinates.insert(coordinates.end(), xyz, xyz + 3);
    }
  }
  if (source.ascii() && source.begin()) {
    return readError(path, source.where() + "data after the last element the header declares");
  }
  return soup.toMesh(coordinates);
}

}  // namespace

Result<Imported> readPly(const std::string& path) {
  Result<std::string> bytes = readFileBytes(path);
  if (!bytes.ok()) return bytes.status();
  const std::string& content = bytes.value();
  PlyHeader header;
  if (std::string problem = parseHeader(content, header); !problem.empty()) {
    return readError(path, problem);
  }
  if (header.vertex_element >= 0) {
    const PlyElement& vertex = header.elements[static_cast<std::size_t>(header.vertex_element)];
    for (int k = 0; k < 3; ++k) {
      if (header.coordinate[k] < 0) {
        return readError(path, "the 'vertex' element has no '" +
                                   std::string(1, static_cast<char>('x' + k)) + "' property");
      }
    }
    if (std::string problem = vertexCountProblem(vertex.count); !problem.empty()) {
      return readError(path, problem);
    }
  }
  if (header.face_element >= 0 && header.indices < 0) {
    return readError(path, "the 'face' element has no 'vertex_indices' list");
  }
  Result<Imported> out = readData(path, content, header);
  if (out.ok()) out.value().report.importer = "PLY reader (" + header.format + ")";
  return out;
}

}  // namespace collido::detail
