// The scene reader's parts shared by the files that read scene JSON: a JSON value with its
// place (for messages) and the checks every reader makes. Errors are thrown as SceneError and
// turned into a Status at the loader's edge (parseScene).
#pragma once

#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include <collido/mesh/input_file.h>
#include <collido/status.h>

namespace collido::scene_reading {

using Json = nlohmann::json;

class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A JSON value and where it is, for messages.
struct Node {
  const Json& value;
  std::string pointer;  // JSON pointer, "" for the root

  Node at(const std::string& key) const { return Node{value.at(key), pointer + "/" + key}; }
  Node at(std::size_t index) const {
    return Node{value.at(index), pointer + "/" + std::to_string(index)};
  }
  bool has(const std::string& key) const { return value.contains(key); }
  std::string where() const { return pointer.empty() ? "/" : pointer; }
};

/// A parser callback that throws SceneError naming the file (`label`) and the JSON pointer of a
/// key repeated in one object: nlohmann::json would keep the last silently.
Json::parser_callback_t duplicateKeyCheck(const std::string& label);

/// The JSON text of a scene or surface file, parsed with duplicateKeyCheck; an error names the
/// file and, for a syntax error, the byte.
Result<Json> parseDocument(const std::string& text, const std::string& label);

/// The whole of a text input file, checked by readInputFile (kind, size limit); an error names
/// the file and calls it `what`.
inline Result<std::string> readTextFile(const std::string& path, const std::string& what) {
  return readInputFile(path, what);
}

/// A number as people write it: "0.25", not "0.250000".
inline std::string shortNumber(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

inline const char* typeName(const Json& v) {
  return v.type_name();
}

class Reader {
 public:
  Reader(std::string label, double resolution)
      : label_(std::move(label)), resolution_(resolution) {}

  /// A generator's sample count at the load's resolution, never below the generator's minimum
  /// and never past the int range (a huge resolution then meets the generator's own limit). A
  /// count already below the minimum is returned as given, for the generator to refuse.
  int resolved(int count, int minimum) const {
    if (count < minimum) return count;
    const double scaled = std::round(static_cast<double>(count) * resolution_);
    const double largest = static_cast<double>(std::numeric_limits<int>::max());
    return static_cast<int>(std::min(largest, std::max(static_cast<double>(minimum), scaled)));
  }

  [[noreturn]] void fail(const Node& node, const std::string& problem) const {
    throw SceneError(label_ + ": " + node.where() + ": " + problem);
  }

  void expectObject(const Node& node, const std::set<std::string>& allowed) const {
    if (!node.value.is_object())
      fail(node, std::string("expected an object, got ") + typeName(node.value));
    for (const auto& item : node.value.items()) {
      if (item.key() == "comment" || allowed.count(item.key()) != 0) continue;
      std::string list;
      for (const std::string& key : allowed)
        list += (list.empty() ? "" : ", ") + key;
      fail(node, "unknown key '" + item.key() + "' (allowed: " + list + ")");
    }
  }

  void expectArray(const Node& node) const {
    if (!node.value.is_array())
      fail(node, std::string("expected an array, got ") + typeName(node.value));
  }

  std::string string(const Node& node) const {
    if (!node.value.is_string())
      fail(node, std::string("expected a string, got ") + typeName(node.value));
    return node.value.get<std::string>();
  }

  double number(const Node& node) const {
    if (!node.value.is_number())
      fail(node, std::string("expected a number, got ") + typeName(node.value));
    const double v = node.value.get<double>();
    if (!std::isfinite(v)) fail(node, "expected a finite number");
    return v;
  }

  double number(const Node& parent, const std::string& key, double fallback) const {
    return parent.has(key) ? number(parent.at(key)) : fallback;
  }

  double positive(const Node& parent, const std::string& key, double fallback) const {
    const double v = number(parent, key, fallback);
    if (!(v > 0.0)) fail(parent.has(key) ? parent.at(key) : parent, key + " must be > 0");
    return v;
  }

  std::int64_t integer(const Node& node, std::int64_t min_value, std::int64_t max_value) const {
    if (!node.value.is_number_integer()) {
      fail(node, std::string("expected an integer, got ") +
                     (node.value.is_number() ? "a fractional number" : typeName(node.value)));
    }
    const auto v = node.value.get<std::int64_t>();
    if (node.value.is_number_unsigned() &&
        node.value.get<std::uint64_t>() > 9000000000000000000ull) {
      fail(node, "integer out of range");
    }
    if (v < min_value || v > max_value) {
      fail(node, "expected an integer in [" + std::to_string(min_value) + ", " +
                     std::to_string(max_value) + "], got " + std::to_string(v));
    }
    return v;
  }

  std::int64_t integer(const Node& parent, const std::string& key, std::int64_t fallback,
                       std::int64_t min_value, std::int64_t max_value) const {
    return parent.has(key) ? integer(parent.at(key), min_value, max_value) : fallback;
  }

  Eigen::Vector3d vector3(const Node& node) const {
    expectArray(node);
    if (node.value.size() != 3)
      fail(node, "expected 3 numbers, got " + std::to_string(node.value.size()));
    return {number(node.at(0)), number(node.at(1)), number(node.at(2))};
  }

  const std::string& label() const { return label_; }

 private:
  std::string label_;
  double resolution_;
};

}  // namespace collido::scene_reading
