// The JSON syntax of FRep solids: {"type": "sphere" | ... | "project", ...}. Parameters that
// may change over time (offsets, bump amplitudes, morph and twist parameters, transforms) take
// a number, a sinusoid {"base", "amplitude", "period", "phase_degrees"} or keyframes
// {"keys": [[t, value], ...]} interpolated linearly and held at the ends.
#include "frep_solid_reader.h"

#include <cmath>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace collido::scene_reading {
namespace {

using frep::SolidPtr;

constexpr double kDegree = M_PI / 180.0;

// A keyframed or sinusoidal value of `width` numbers (1 or 3).
std::vector<double> animated(const Reader& r, const Node& node, double time, std::size_t width) {
  const auto numbers = [&](const Node& value) {
    std::vector<double> out;
    if (width == 1) {
      out.push_back(r.number(value));
    } else {
      const Eigen::Vector3d v = r.vector3(value);
      out.assign(v.data(), v.data() + 3);
    }
    return out;
  };
  if (!node.value.is_object()) return numbers(node);
  if (node.has("keys")) {
    r.expectObject(node, {"keys"});
    const Node keys = node.at("keys");
    r.expectArray(keys);
    if (keys.value.empty()) r.fail(keys, "no keys");
    std::vector<double> times;
    std::vector<std::vector<double>> values;
    for (std::size_t i = 0; i < keys.value.size(); ++i) {
      const Node key = keys.at(i);
      r.expectArray(key);
      if (key.value.size() != 2) r.fail(key, "expected [time, value]");
      times.push_back(r.number(key.at(0)));
      if (i > 0 && !(times[i] > times[i - 1])) r.fail(key.at(0), "key times must increase");
      values.push_back(numbers(key.at(1)));
    }
    if (time <= times.front()) return values.front();
    if (time >= times.back()) return values.back();
    std::size_t k = 1;
    while (times[k] < time)
      ++k;
    const double s = (time - times[k - 1]) / (times[k] - times[k - 1]);
    std::vector<double> out(width);
    for (std::size_t i = 0; i < width; ++i)
      out[i] = (1 - s) * values[k - 1][i] + s * values[k][i];
    return out;
  }
  if (width != 1) r.fail(node, "expected [x, y, z] or {\"keys\": [[time, [x, y, z]], ...]}");
  r.expectObject(node, {"base", "amplitude", "period", "phase_degrees"});
  const double base = r.number(node, "base", 0.0);
  const double amplitude = r.number(node, "amplitude", 0.0);
  const double period = r.positive(node, "period", 1.0);
  const double phase = r.number(node, "phase_degrees", 0.0) * kDegree;
  return {base + amplitude * std::sin(2 * M_PI * time / period + phase)};
}

double scalar(const Reader& r, const Node& parent, const std::string& key, double time,
              double fallback) {
  return parent.has(key) ? animated(r, parent.at(key), time, 1)[0] : fallback;
}

Eigen::Vector3d vector(const Reader& r, const Node& parent, const std::string& key, double time,
                       const Eigen::Vector3d& fallback) {
  if (!parent.has(key)) return fallback;
  const std::vector<double> v = animated(r, parent.at(key), time, 3);
  return {v[0], v[1], v[2]};
}

const Node required(const Reader& r, const Node& node, const std::string& key) {
  if (!node.has(key)) r.fail(node, "missing '" + key + "'");
  return node.at(key);
}

double requiredPositive(const Reader& r, const Node& node, const std::string& key) {
  const double v = r.number(required(r, node, key));
  if (!(v > 0)) r.fail(node.at(key), key + " must be > 0");
  return v;
}

Eigen::Vector3d centreOf(const Reader& r, const Node& node, const char* key = "centre") {
  return node.has(key) ? r.vector3(node.at(key)) : Eigen::Vector3d::Zero();
}

frep::SetBlend blendOf(const Reader& r, const Node& node) {
  if (!node.has("blend")) return frep::SetBlend::kMinMax;
  const std::string blend = r.string(node.at("blend"));
  if (blend == "minmax") return frep::SetBlend::kMinMax;
  if (blend == "rfunction") return frep::SetBlend::kRFunction;
  r.fail(node.at("blend"), "unknown blend '" + blend + "' (minmax, rfunction)");
}

int piecesOf(const Reader& r, const Node& node, int fallback) {
  return static_cast<int>(r.integer(node, "pieces", fallback, 1, 4096));
}

SolidPtr readPrimitive(const Reader& r, const Node& node, const std::string& type) {
  const double inf = std::numeric_limits<double>::infinity();
  if (type == "sphere") {
    r.expectObject(node, {"type", "centre", "radius"});
    return frep::sphere(centreOf(r, node), requiredPositive(r, node, "radius"));
  }
  if (type == "ellipsoid") {
    r.expectObject(node, {"type", "centre", "radii"});
    return frep::ellipsoid(centreOf(r, node), r.vector3(required(r, node, "radii")));
  }
  if (type == "cylinder") {
    r.expectObject(node, {"type", "centre", "radius", "height"});
    return frep::cylinder(centreOf(r, node), requiredPositive(r, node, "radius"),
                          node.has("height") ? r.positive(node, "height", 1.0) : inf);
  }
  if (type == "cone") {
    r.expectObject(node, {"type", "apex", "half_angle_degrees", "height"});
    return frep::cone(centreOf(r, node, "apex"),
                      requiredPositive(r, node, "half_angle_degrees") * kDegree,
                      node.has("height") ? r.positive(node, "height", 1.0) : inf);
  }
  if (type == "torus") {
    r.expectObject(node, {"type", "centre", "major_radius", "minor_radius"});
    return frep::torus(centreOf(r, node), requiredPositive(r, node, "major_radius"),
                       requiredPositive(r, node, "minor_radius"));
  }
  if (type == "quadric") {
    r.expectObject(node, {"type", "matrix", "linear", "constant"});
    const Node rows = required(r, node, "matrix");
    r.expectArray(rows);
    if (rows.value.size() != 3) r.fail(rows, "expected 3 rows");
    Eigen::Matrix3d a;
    for (int i = 0; i < 3; ++i)
      a.row(i) = r.vector3(rows.at(static_cast<std::size_t>(i))).transpose();
    return frep::quadric(
        a, node.has("linear") ? r.vector3(node.at("linear")) : Eigen::Vector3d::Zero(),
        r.number(node, "constant", 0.0));
  }
  if (type == "superellipsoid") {
    r.expectObject(node, {"type", "centre", "radii", "east_west", "north_south"});
    return frep::superellipsoid(centreOf(r, node), r.vector3(required(r, node, "radii")),
                                requiredPositive(r, node, "east_west"),
                                requiredPositive(r, node, "north_south"));
  }
  if (type == "block") {
    r.expectObject(node, {"type", "centre", "half_extents"});
    return frep::block(centreOf(r, node), r.vector3(required(r, node, "half_extents")));
  }
  if (type == "half_space") {
    r.expectObject(node, {"type", "normal", "offset"});
    return frep::halfSpace(r.vector3(required(r, node, "normal")), r.number(node, "offset", 0.0));
  }
  return nullptr;
}

Eigen::Affine3d transformOf(const Reader& r, const Node& node, double time) {
  Eigen::Affine3d t = Eigen::Affine3d::Identity();
  t.translate(vector(r, node, "translate", time, Eigen::Vector3d::Zero()));
  if (node.has("rotate")) {
    const Node rotate = node.at("rotate");
    r.expectObject(rotate, {"axis", "degrees"});
    const Eigen::Vector3d axis = r.vector3(required(r, rotate, "axis"));
    if (!(axis.norm() > 0)) r.fail(rotate.at("axis"), "axis must be non-zero");
    t.rotate(
        Eigen::AngleAxisd(scalar(r, rotate, "degrees", time, 0.0) * kDegree, axis.normalized()));
  }
  if (node.has("scale")) {
    const Node scale = node.at("scale");
    const Eigen::Vector3d s =
        scale.value.is_array() ? r.vector3(scale) : Eigen::Vector3d::Constant(r.number(scale));
    if (!(s.minCoeff() > 0)) r.fail(scale, "scale must be > 0");
    t.scale(s);
  }
  return t;
}

SolidPtr readOperation(const Reader& r, const Node& node, const std::string& type, double time) {
  const auto child = [&](const char* key) {
    return readFrepSolid(r, required(r, node, key), time);
  };
  if (type == "perturb") {
    r.expectObject(node, {"type", "solid", "bumps"});
    const Node list = required(r, node, "bumps");
    r.expectArray(list);
    std::vector<frep::Bump> bumps;
    for (std::size_t i = 0; i < list.value.size(); ++i) {
      const Node item = list.at(i);
      r.expectObject(item, {"centre", "radius", "amplitude"});
      bumps.push_back({r.vector3(required(r, item, "centre")), requiredPositive(r, item, "radius"),
                       scalar(r, item, "amplitude", time, 0.0)});
    }
    return frep::perturbed(child("solid"), std::move(bumps));
  }
  if (type == "union" || type == "intersection") {
    r.expectObject(node, {"type", "of", "blend"});
    const Node list = required(r, node, "of");
    r.expectArray(list);
    if (list.value.empty()) r.fail(list, "no operands");
    std::vector<SolidPtr> operands;
    for (std::size_t i = 0; i < list.value.size(); ++i)
      operands.push_back(readFrepSolid(r, list.at(i), time));
    return type == "union" ? frep::unionOf(std::move(operands), blendOf(r, node))
                           : frep::intersectionOf(std::move(operands), blendOf(r, node));
  }
  if (type == "difference") {
    r.expectObject(node, {"type", "from", "subtract", "blend"});
    return frep::differenceOf(child("from"), child("subtract"), blendOf(r, node));
  }
  if (type == "offset") {
    r.expectObject(node, {"type", "solid", "by"});
    required(r, node, "by");
    return frep::offset(child("solid"), scalar(r, node, "by", time, 0.0));
  }
  if (type == "transform") {
    r.expectObject(node, {"type", "solid", "translate", "rotate", "scale"});
    return frep::transformed(child("solid"), transformOf(r, node, time));
  }
  if (type == "twist") {
    r.expectObject(node, {"type", "solid", "degrees_per_unit"});
    required(r, node, "degrees_per_unit");
    return frep::twisted(child("solid"), scalar(r, node, "degrees_per_unit", time, 0.0) * kDegree);
  }
  if (type == "morph") {
    r.expectObject(node, {"type", "from", "to", "t"});
    required(r, node, "t");
    const double t = scalar(r, node, "t", time, 0.0);
    if (!(t >= 0 && t <= 1)) {
      r.fail(node.at("t"), "morph parameter " + std::to_string(t) + " at time " +
                               std::to_string(time) + " is outside [0, 1]");
    }
    return frep::morphed(child("from"), child("to"), t);
  }
  if (type == "sweep") {
    r.expectObject(node, {"type", "solid", "path", "pieces"});
    const Node list = required(r, node, "path");
    r.expectArray(list);
    if (list.value.size() < 2) r.fail(list, "a path needs at least two points");
    std::vector<Eigen::Vector3d> path;
    for (std::size_t i = 0; i < list.value.size(); ++i)
      path.push_back(r.vector3(list.at(i)));
    return frep::swept(child("solid"), std::move(path), piecesOf(r, node, 8));
  }
  if (type == "project") {
    r.expectObject(node, {"type", "solid", "axis", "pieces"});
    const std::string axis = r.string(required(r, node, "axis"));
    if (axis != "x" && axis != "y" && axis != "z")
      r.fail(node.at("axis"), "axis must be x, y or z");
    return frep::projected(child("solid"), axis[0] - 'x', piecesOf(r, node, 16));
  }
  r.fail(node.at("type"),
         "unknown solid type '" + type +
             "' (sphere, ellipsoid, cylinder, cone, torus, quadric, superellipsoid, block, "
             "half_space, perturb, union, intersection, difference, offset, transform, twist, "
             "morph, sweep, project)");
}

// An object holding only keyframes or a sinusoid's keys is an animated value (a bump, which
// also has an amplitude, is not).
bool isAnimatedValue(const Json& value) {
  if (!value.is_object() || value.empty()) return false;
  static const std::set<std::string> kAnimationKeys = {"keys",   "base",          "amplitude",
                                                       "period", "phase_degrees", "comment"};
  for (const auto& item : value.items())
    if (kAnimationKeys.count(item.key()) == 0) return false;
  return true;
}

}  // namespace

SolidPtr readFrepSolid(const Reader& r, const Node& node, double time) {
  if (!node.value.is_object())
    r.fail(node, std::string("expected a solid object, got ") + typeName(node.value));
  const std::string type = r.string(required(r, node, "type"));
  try {
    if (SolidPtr primitive = readPrimitive(r, node, type)) return primitive;
    return readOperation(r, node, type, time);
  } catch (const std::invalid_argument& error) {
    r.fail(node, error.what());
  }
}

double frepEvaluationCost(const Json& node) {
  if (!node.is_object() && !node.is_array()) return 0.0;
  double cost = node.is_object() && node.contains("type") ? 1.0 : 0.0;
  for (const auto& item : node.items())
    cost += frepEvaluationCost(item.value());
  if (node.is_object() && node.contains("type") && node["type"].is_string()) {
    const std::string type = node["type"].get<std::string>();
    const double pieces = node.contains("pieces") && node["pieces"].is_number()
                              ? std::max(1.0, node["pieces"].get<double>())
                              : 16.0;
    const double segments = node.contains("path") && node["path"].is_array()
                                ? std::max(1.0, static_cast<double>(node["path"].size()))
                                : 1.0;
    if (type == "sweep" || type == "project") cost *= 2.0 * pieces * segments;
  }
  return cost;
}

bool frepIsAnimated(const Node& node) {
  const Json& value = node.value;
  if (value.is_object()) {
    for (const auto& item : value.items()) {
      if (item.key() == "comment") continue;
      if (isAnimatedValue(item.value())) return true;
      if (frepIsAnimated(Node{item.value(), node.pointer + "/" + item.key()})) return true;
    }
  } else if (value.is_array()) {
    for (std::size_t i = 0; i < value.size(); ++i)
      if (frepIsAnimated(node.at(i))) return true;
  }
  return false;
}

}  // namespace collido::scene_reading
