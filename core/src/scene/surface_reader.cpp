// Surface files: NURBS surfaces for the distance seed method, explicit or generated.
#include <collido/scene/surface_file.h>

#include <set>

#include <collido/nurbs/surface_generators.h>

#include "scene_reader.h"

namespace collido {
namespace {

using scene_reading::Json;
using scene_reading::Node;
using scene_reading::Reader;
using scene_reading::SceneError;

std::vector<double> readKnots(const Reader& r, const Node& node) {
  r.expectArray(node);
  std::vector<double> knots;
  for (std::size_t i = 0; i < node.value.size(); ++i)
    knots.push_back(r.number(node.at(i)));
  return knots;
}

nurbs::NurbsSurface readExplicit(const Reader& r, const Node& node) {
  r.expectObject(node, {"name", "degree_u", "degree_v", "knots_u", "knots_v", "control"});
  for (const char* key : {"degree_u", "degree_v", "knots_u", "knots_v", "control"}) {
    if (!node.has(key)) r.fail(node, std::string("missing '") + key + "'");
  }
  nurbs::NurbsSurface s;
  s.degree_u = static_cast<int>(r.integer(node.at("degree_u"), 1, 15));
  s.degree_v = static_cast<int>(r.integer(node.at("degree_v"), 1, 15));
  s.knots_u = readKnots(r, node.at("knots_u"));
  s.knots_v = readKnots(r, node.at("knots_v"));
  const Node rows = node.at("control");
  r.expectArray(rows);
  s.count_u = static_cast<int>(rows.value.size());
  for (std::size_t i = 0; i < rows.value.size(); ++i) {
    const Node row = rows.at(i);
    r.expectArray(row);
    if (i == 0) s.count_v = static_cast<int>(row.value.size());
    if (static_cast<int>(row.value.size()) != s.count_v) {
      r.fail(row, "a row of " + std::to_string(row.value.size()) + " points; row 0 has " +
                      std::to_string(s.count_v));
    }
    for (std::size_t j = 0; j < row.value.size(); ++j) {
      const Node point = row.at(j);
      r.expectArray(point);
      if (point.value.size() != 3 && point.value.size() != 4) {
        r.fail(point, "expected [x, y, z] or [x, y, z, weight], got " +
                          std::to_string(point.value.size()) + " numbers");
      }
      const double w = point.value.size() == 4 ? r.number(point.at(3)) : 1.0;
      if (!(w > 0.0)) r.fail(point.at(3), "weight must be > 0");
      // Read before building: a throw inside Eigen's comma initializer trips its assertion.
      const double x = r.number(point.at(0));
      const double y = r.number(point.at(1));
      const double z = r.number(point.at(2));
      s.control.emplace_back(w * x, w * y, w * z, w);
    }
  }
  if (const Status valid = nurbs::validate(s); !valid.ok()) r.fail(node, valid.message());
  return s;
}

nurbs::NurbsSurface readGenerated(const Reader& r, const Node& node) {
  const std::string generator = r.string(node.at("generator"));
  const auto vector = [&](const char* key, const Eigen::Vector3d& fallback) {
    return node.has(key) ? r.vector3(node.at(key)) : fallback;
  };
  if (generator == "sphere_zone") {
    r.expectObject(node, {"name", "generator", "centre", "radius", "from_degrees"});
    return nurbs::sphereZone(vector("centre", Eigen::Vector3d::Zero()),
                             r.positive(node, "radius", 1.0), r.number(node, "from_degrees", 0.0));
  }
  if (generator == "saddle") {
    r.expectObject(node, {"name", "generator", "centre", "half", "curvature"});
    return nurbs::saddle(vector("centre", Eigen::Vector3d::Zero()), r.positive(node, "half", 1.0),
                         r.number(node, "curvature", 0.5));
  }
  if (generator == "wavy_sheet") {
    r.expectObject(node,
                   {"name", "generator", "origin", "size", "count", "waves", "amplitude", "phase"});
    return nurbs::wavySheet(
        vector("origin", Eigen::Vector3d::Zero()), r.positive(node, "size", 1.0),
        static_cast<int>(r.integer(node, "count", 8, 4, 256)), r.positive(node, "waves", 1.0),
        r.number(node, "amplitude", 0.1), r.number(node, "phase", 0.0));
  }
  if (generator == "swept_blade") {
    r.expectObject(node, {"name", "generator", "root", "chord", "camber", "span", "twist_degrees"});
    return nurbs::sweptBlade(vector("root", Eigen::Vector3d::Zero()),
                             r.positive(node, "chord", 1.0), r.number(node, "camber", 0.1),
                             r.positive(node, "span", 1.0), r.number(node, "twist_degrees", 0.0));
  }
  r.fail(node.at("generator"), "unknown surface generator '" + generator +
                                   "' (known: sphere_zone, saddle, wavy_sheet, swept_blade)");
}

}  // namespace

Result<std::vector<NamedSurface>> parseSurfaces(const std::string& text, const std::string& label) {
  Result<Json> parsed = scene_reading::parseDocument(text, label);
  if (!parsed.ok()) return parsed.status();
  const Json& document = parsed.value();
  try {
    const Reader r(label, 1.0);
    const Node root{document, ""};
    r.expectObject(root, {"surfaces"});
    if (!root.has("surfaces")) r.fail(root, "missing 'surfaces'");
    const Node list = root.at("surfaces");
    r.expectArray(list);
    if (list.value.empty()) r.fail(list, "no surfaces");
    std::vector<NamedSurface> out;
    std::set<std::string> names;
    for (std::size_t i = 0; i < list.value.size(); ++i) {
      const Node node = list.at(i);
      if (!node.value.is_object()) r.fail(node, "expected an object");
      if (!node.has("name")) r.fail(node, "missing 'name'");
      NamedSurface named;
      named.name = r.string(node.at("name"));
      if (!names.insert(named.name).second) {
        r.fail(node.at("name"), "duplicate surface name '" + named.name + "'");
      }
      named.surface = node.has("generator") ? readGenerated(r, node) : readExplicit(r, node);
      out.push_back(std::move(named));
    }
    return out;
  } catch (const SceneError& e) {
    return Status(StatusCode::kInvalidArgument, e.what());
  } catch (const Json::exception& e) {
    return Status(StatusCode::kInvalidArgument, label + ": " + e.what());
  }
}

Result<std::vector<NamedSurface>> loadSurfaces(const std::string& path) {
  Result<std::string> text = scene_reading::readTextFile(path, "surface file");
  if (!text.ok()) return text.status();
  return parseSurfaces(text.value(), path);
}

}  // namespace collido
