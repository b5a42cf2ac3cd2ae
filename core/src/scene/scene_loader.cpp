// Scene files: JSON in, a fully validated Scene out.
//
// The reader walks the document with its JSON pointer in hand, so every complaint names the
// file, the place and the problem. Errors are thrown as SceneError inside this file only and
// returned as a Status; unknown keys are errors (a misspelt "minor_raduis" must not silently
// become the default), except "comment", allowed anywhere for notes.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <stdexcept>
#include <vector>

#include <nlohmann/json.hpp>

#include <collido/frep/polygonize.h>
#include <collido/mesh/input_file.h>
#include <collido/mesh/mesh_io.h>
#include <collido/mesh/procedural.h>
#include <collido/scene/scene.h>
#include <collido/stress/stress_cases.h>

#include "constraint_reader.h"
#include "deformation_reader.h"
#include "frep_solid_reader.h"
#include "hierarchy_reader.h"
#include "marker_reader.h"
#include "motion_reader.h"
#include "scene_reader.h"

namespace collido {
namespace {

using scene_reading::Json;
using scene_reading::Node;
using scene_reading::Reader;
using scene_reading::SceneError;

// The scene's triangle limit (SceneLoadOptions::max_triangles), charged shape by shape: a
// generated shape before it is generated (from its parameters), a mesh file once read.
class TriangleBudget {
 public:
  TriangleBudget(const Reader& reader, std::size_t limit) : reader_(reader), limit_(limit) {}

  /// Adds `triangles` (computed in double, so huge counts cannot overflow) for the shape at
  /// `node`, described by `what`; fails naming the shape when the scene goes past the limit.
  void charge(const Node& node, const std::string& what, double triangles) {
    used_ += triangles;
    if (limit_ == 0 || used_ <= static_cast<double>(limit_)) return;
    std::ostringstream text;
    text << std::fixed << std::setprecision(0) << what << " needs " << triangles
         << " triangles, which takes the scene to " << used_ << ", more than this load allows ("
         << limit_ << ", SceneLoadOptions::max_triangles)";
    reader_.fail(node, text.str());
  }

  /// The scene-wide triangle limit (0: none).
  std::size_t limit() const { return limit_; }

 private:
  const Reader& reader_;
  std::size_t limit_;
  double used_ = 0.0;
};

// --- shapes ----------------------------------------------------------------------------------

struct LoadedShape {
  std::shared_ptr<const TriangleMesh> mesh;
  MeshReport report;
};

// A number as people write it: "0.25", not "0.250000".
std::string shortNumber(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

// Reads a generator's parameters, describes the shape in `text`, charges its triangle count
// (the formulas of collido/mesh/procedural.h) to the budget, then generates it.
using Generator = Result<TriangleMesh> (*)(const Reader&, const Node&, std::string&,
                                           TriangleBudget&);

TorusParams readTorusParams(const Reader& r, const Node& n) {
  TorusParams p;
  p.major_radius = r.positive(n, "major_radius", p.major_radius);
  p.minor_radius = r.positive(n, "minor_radius", p.minor_radius);
  p.major_segments =
      r.resolved(static_cast<int>(r.integer(n, "major_segments", p.major_segments, 3, 1 << 20)), 3);
  p.minor_segments =
      r.resolved(static_cast<int>(r.integer(n, "minor_segments", p.minor_segments, 3, 1 << 20)), 3);
  return p;
}

Result<TriangleMesh> generateTorus(const Reader& r, const Node& n, std::string& text,
                                   TriangleBudget& budget) {
  r.expectObject(n,
                 {"generator", "major_radius", "minor_radius", "major_segments", "minor_segments"});
  const TorusParams p = readTorusParams(r, n);
  text = "torus R=" + shortNumber(p.major_radius) + " r=" + shortNumber(p.minor_radius) + " " +
         std::to_string(p.major_segments) + "x" + std::to_string(p.minor_segments);
  budget.charge(n, text, 2.0 * p.major_segments * p.minor_segments);
  return makeTorus(p);
}

Result<TriangleMesh> generateChain(const Reader& r, const Node& n, std::string& text,
                                   TriangleBudget& budget) {
  r.expectObject(n, {"generator", "links", "clearance", "major_radius", "minor_radius",
                     "major_segments", "minor_segments"});
  ChainParams p;
  p.links = static_cast<int>(r.integer(n, "links", p.links, 1, 100000));
  p.clearance = r.number(n, "clearance", p.clearance);
  p.link = readTorusParams(r, n);
  text = "chain of " + std::to_string(p.links) + " tori R=" + shortNumber(p.link.major_radius) +
         " r=" + shortNumber(p.link.minor_radius) + " clearance=" + shortNumber(p.clearance);
  budget.charge(n, text, 2.0 * p.links * p.link.major_segments * p.link.minor_segments);
  return makeChain(p);
}

Result<TriangleMesh> generateSphere(const Reader& r, const Node& n, std::string& text,
                                    TriangleBudget& budget) {
  r.expectObject(n, {"generator", "radius", "slices", "stacks"});
  SphereParams p;
  p.radius = r.positive(n, "radius", p.radius);
  p.slices = r.resolved(static_cast<int>(r.integer(n, "slices", p.slices, 3, 1 << 20)), 3);
  p.stacks = r.resolved(static_cast<int>(r.integer(n, "stacks", p.stacks, 2, 1 << 20)), 2);
  text = "sphere r=" + shortNumber(p.radius) + " " + std::to_string(p.slices) + "x" +
         std::to_string(p.stacks);
  budget.charge(n, text, 2.0 * p.slices * (p.stacks - 1.0));
  return makeSphere(p);
}

Result<TriangleMesh> generateBox(const Reader& r, const Node& n, std::string& text,
                                 TriangleBudget& budget) {
  r.expectObject(n, {"generator", "size"});
  BoxParams p;
  if (n.has("size")) p.size = r.vector3(n.at("size"));
  for (int k = 0; k < 3; ++k) {
    if (!(p.size[k] > 0.0)) r.fail(n.at("size"), "every side of a box must be > 0");
  }
  text = "box " + shortNumber(p.size.x()) + "x" + shortNumber(p.size.y()) + "x" +
         shortNumber(p.size.z());
  budget.charge(n, text, 12.0);
  return makeBox(p);
}

Result<TriangleMesh> generateGridSheet(const Reader& r, const Node& n, std::string& text,
                                       TriangleBudget& budget) {
  r.expectObject(n, {"generator", "width", "depth", "cells_x", "cells_y", "amplitude", "waves"});
  GridSheetParams p;
  p.width = r.positive(n, "width", p.width);
  p.depth = r.positive(n, "depth", p.depth);
  p.cells_x = r.resolved(static_cast<int>(r.integer(n, "cells_x", p.cells_x, 1, 1 << 20)), 1);
  p.cells_y = r.resolved(static_cast<int>(r.integer(n, "cells_y", p.cells_y, 1, 1 << 20)), 1);
  p.amplitude = r.number(n, "amplitude", p.amplitude);
  p.waves = r.number(n, "waves", p.waves);
  text = "grid sheet " + std::to_string(p.cells_x) + "x" + std::to_string(p.cells_y);
  budget.charge(n, text, 2.0 * p.cells_x * p.cells_y);
  return makeGridSheet(p);
}

Result<TriangleMesh> generateGear(const Reader& r, const Node& n, std::string& text,
                                  TriangleBudget& budget) {
  r.expectObject(n, {"generator", "teeth", "module", "face_width", "pressure_angle_deg",
                     "flank_samples", "root_samples"});
  GearParams p;
  p.teeth = static_cast<int>(r.integer(n, "teeth", p.teeth, 6, 100000));
  p.module = r.positive(n, "module", p.module);
  p.face_width = r.positive(n, "face_width", p.face_width);
  p.pressure_angle_deg = r.positive(n, "pressure_angle_deg", p.pressure_angle_deg);
  p.flank_samples =
      r.resolved(static_cast<int>(r.integer(n, "flank_samples", p.flank_samples, 2, 1 << 16)), 2);
  p.root_samples =
      r.resolved(static_cast<int>(r.integer(n, "root_samples", p.root_samples, 1, 1 << 16)), 1);
  text = "gear z=" + std::to_string(p.teeth) + " m=" + shortNumber(p.module);
  // Counted with both root feet, as makeGear's own limit does: at most 2 more points a tooth.
  budget.charge(n, text, 4.0 * p.teeth * (2.0 * p.flank_samples + 1.0 + p.root_samples + 2.0));
  return makeGear(p);
}

Result<TriangleMesh> generateStationModule(const Reader& r, const Node& n, std::string& text,
                                           TriangleBudget& budget) {
  r.expectObject(n, {"generator", "radius", "length", "segments", "rings", "port_radius",
                     "port_length", "truss_bays", "panel_span", "panel_width"});
  StationModuleParams p;
  p.radius = r.positive(n, "radius", p.radius);
  p.length = r.positive(n, "length", p.length);
  p.segments = r.resolved(static_cast<int>(r.integer(n, "segments", p.segments, 3, 1 << 20)), 3);
  p.rings = r.resolved(static_cast<int>(r.integer(n, "rings", p.rings, 1, 1 << 20)), 1);
  p.port_radius = r.positive(n, "port_radius", p.port_radius);
  p.port_length = r.positive(n, "port_length", p.port_length);
  // Bays are structure, not sampling: the resolution option leaves them alone.
  p.truss_bays = static_cast<int>(r.integer(n, "truss_bays", p.truss_bays, 1, 100000));
  p.panel_span = r.positive(n, "panel_span", p.panel_span);
  p.panel_width = r.positive(n, "panel_width", p.panel_width);
  text = "station module R=" + shortNumber(p.radius) + " L=" + shortNumber(p.length) + " " +
         std::to_string(p.segments) + "x" + std::to_string(p.rings) + ", " +
         std::to_string(p.truss_bays) + " truss bays";
  budget.charge(n, text, 4.0 * p.segments * (p.rings + 1.0) + 12.0 * (8.0 * p.truss_bays + 11.0));
  return makeStationModule(p);
}

Result<TriangleMesh> generateCylinder(const Reader& r, const Node& n, std::string& text,
                                      TriangleBudget& budget) {
  r.expectObject(n, {"generator", "radius", "height", "segments", "inner_radius"});
  CylinderParams p;
  p.radius = r.positive(n, "radius", p.radius);
  p.height = r.positive(n, "height", p.height);
  p.segments = r.resolved(static_cast<int>(r.integer(n, "segments", p.segments, 3, 1 << 20)), 3);
  p.inner_radius = r.number(n, "inner_radius", p.inner_radius);
  text = (p.inner_radius > 0.0
              ? "tube R=" + shortNumber(p.radius) + " r=" + shortNumber(p.inner_radius)
              : "cylinder r=" + shortNumber(p.radius)) +
         " h=" + shortNumber(p.height) + " " + std::to_string(p.segments) + " segments";
  budget.charge(n, text, (p.inner_radius > 0.0 ? 8.0 : 4.0) * p.segments);
  return makeCylinder(p);
}

Result<TriangleMesh> generateFlange(const Reader& r, const Node& n, std::string& text,
                                    TriangleBudget& budget) {
  r.expectObject(n, {"generator", "outer_radius", "bore_radius", "thickness", "bolt_holes",
                     "bolt_circle_radius", "hole_radius", "arc_segments", "radial_segments"});
  FlangeParams p;
  p.outer_radius = r.positive(n, "outer_radius", p.outer_radius);
  p.bore_radius = r.positive(n, "bore_radius", p.bore_radius);
  p.thickness = r.positive(n, "thickness", p.thickness);
  // Holes are structure, not sampling: the resolution option leaves them alone.
  p.bolt_holes = static_cast<int>(r.integer(n, "bolt_holes", p.bolt_holes, 3, 100000));
  p.bolt_circle_radius = r.positive(n, "bolt_circle_radius", p.bolt_circle_radius);
  p.hole_radius = r.positive(n, "hole_radius", p.hole_radius);
  p.arc_segments =
      r.resolved(static_cast<int>(r.integer(n, "arc_segments", p.arc_segments, 1, 1 << 16)), 1);
  p.radial_segments = r.resolved(
      static_cast<int>(r.integer(n, "radial_segments", p.radial_segments, 1, 1 << 16)), 1);
  text = "flange R=" + shortNumber(p.outer_radius) + " bore=" + shortNumber(p.bore_radius) + ", " +
         std::to_string(p.bolt_holes) + " bolt holes r=" + shortNumber(p.hole_radius);
  const double outline = 2.0 * (p.arc_segments + p.radial_segments);
  budget.charge(n, text, 6.0 * p.bolt_holes * outline + 4.0 * p.bolt_holes * p.arc_segments);
  return makeFlange(p);
}

const std::map<std::string, Generator>& generators() {
  static const std::map<std::string, Generator> table = {
      {"torus", &generateTorus},   {"chain", &generateChain},
      {"sphere", &generateSphere}, {"grid_sheet", &generateGridSheet},
      {"gear", &generateGear},     {"station_module", &generateStationModule},
      {"box", &generateBox},       {"cylinder", &generateCylinder},
      {"flange", &generateFlange}};
  return table;
}

class ShapeLoader {
 public:
  ShapeLoader(const Reader& reader, std::string base_directory, std::size_t max_triangles)
      : reader_(reader), base_(std::move(base_directory)), budget_(reader, max_triangles) {}

  LoadedShape load(const Node& node) {
    const Reader& r = reader_;
    if (!node.value.is_object())
      r.fail(node, "expected an object with 'mesh', 'generator' or 'frep'");
    const int sources = static_cast<int>(node.has("mesh")) +
                        static_cast<int>(node.has("generator")) +
                        static_cast<int>(node.has("frep"));
    if (sources != 1) {
      r.fail(node, "give exactly one of 'mesh' (a file), 'generator' or 'frep' (a solid)");
    }
    if (node.has("generator")) return generate(node);
    if (node.has("frep")) return polygonizeSolid(node);
    LoadedShape shape = loadFile(node);
    budget_.charge(node, shape.report.source, static_cast<double>(shape.mesh->triangleCount()));
    return shape;
  }

 private:
  LoadedShape loadFile(const Node& node) {
    const Reader& r = reader_;
    r.expectObject(node, {"mesh", "scale"});
    const std::string relative = r.string(node.at("mesh"));
    const double scale = r.positive(node, "scale", 1.0);
    const std::filesystem::path file = std::filesystem::path(base_) / relative;
    const std::string key = file.lexically_normal().string() + "|" + std::to_string(scale);
    if (const auto hit = cache_.find(key); hit != cache_.end()) return hit->second;

    MeshReport report;
    Result<TriangleMesh> mesh = loadMesh(file.lexically_normal().string(), &report);
    if (!mesh.ok()) r.fail(node.at("mesh"), mesh.status().message());
    if (scale != 1.0) {
      mesh.value().vertices *= scale;
      // A large scale can take finite coordinates past the double range.
      if (Status s = validateMesh(mesh.value(), file.lexically_normal().string()); !s.ok()) {
        r.fail(node.at("scale"), "scaled by " + shortNumber(scale) + ": " + s.message());
      }
    }
    LoadedShape shape{std::make_shared<const TriangleMesh>(std::move(mesh).value()), report};
    cache_.emplace(key, shape);
    return shape;
  }

  LoadedShape generate(const Node& node) {
    const Reader& r = reader_;
    const std::string name = r.string(node.at("generator"));
    const auto found = generators().find(name);
    if (found == generators().end()) {
      std::string list;
      for (const auto& [known, fn] : generators())
        list += (list.empty() ? "" : ", ") + known;
      r.fail(node.at("generator"), "unknown generator '" + name + "' (known: " + list + ")");
    }
    std::string text;
    Result<TriangleMesh> mesh = found->second(r, node, text, budget_);
    if (!mesh.ok()) r.fail(node, mesh.status().message());
    // Finite parameters can still overflow in the shape (a radius near the double maximum).
    if (Status s = validateMesh(mesh.value(), text); !s.ok()) r.fail(node, s.message());
    return generatedShape(std::move(mesh).value(), text);
  }

  // A mesh made by the loader (a generator, a polygonization), described by `text`.
  static LoadedShape generatedShape(TriangleMesh mesh, const std::string& text) {
    LoadedShape shape;
    shape.report.source = text;
    shape.report.importer = "generator";
    inspectMesh(mesh, shape.report);
    shape.mesh = std::make_shared<const TriangleMesh>(std::move(mesh));
    return shape;
  }

  // An FRep solid (docs/frep.md) polygonized at load with OpenVDB: `cells` grid cells along the
  // longest side of its bounds (scaled by the load's resolution). Its animated parameters take
  // their values at time 0; `collido frep` checks animated solids frame by frame.
  LoadedShape polygonizeSolid(const Node& node) {
    const Reader& r = reader_;
    r.expectObject(node, {"frep", "cells"});
    const int cells = r.resolved(static_cast<int>(r.integer(node, "cells", 64, 2, 512)), 2);
    const std::string text = "FRep solid polygonized at " + std::to_string(cells) + " cells";
    // Charged before the work: a closed surface over a grid of N cells is about 12 N^2
    // triangles, and a load with a triangle limit also limits the function evaluations.
    budget_.charge(node, text, 12.0 * cells * cells);
    const double evaluations =
        std::pow(cells + 3.0, 3) * scene_reading::frepEvaluationCost(node.at("frep").value);
    if (budget_.limit() > 0 && evaluations > 100.0 * static_cast<double>(budget_.limit())) {
      r.fail(node, text + " takes about " + shortNumber(evaluations) +
                       " node evaluations, more than this load allows (100 x "
                       "SceneLoadOptions::max_triangles)");
    }
    const frep::SolidPtr solid = scene_reading::readFrepSolid(r, node.at("frep"), 0.0);
    const Eigen::AlignedBox3d bounds = solid->bounds();
    if (bounds.isEmpty()) r.fail(node.at("frep"), "the solid is empty");
    if (!bounds.min().allFinite() || !bounds.max().allFinite()) {
      r.fail(node.at("frep"),
             "the solid is unbounded: intersect it with a bounded one to polygonize it");
    }
    Result<TriangleMesh> mesh = frep::polygonize(*solid, bounds, std::min(cells, 1024));
    if (!mesh.ok()) r.fail(node, mesh.status().message());
    if (Status s = validateMesh(mesh.value(), text); !s.ok()) r.fail(node, s.message());
    const double surplus = static_cast<double>(mesh.value().triangleCount()) - 12.0 * cells * cells;
    if (surplus > 0) budget_.charge(node, text, surplus);
    return generatedShape(std::move(mesh).value(), text);
  }

  const Reader& reader_;
  std::string base_;
  TriangleBudget budget_;
  std::map<std::string, LoadedShape> cache_;
};

// --- queries ---------------------------------------------------------------------------------

QueryKind readQueryKind(const Reader& r, const Node& node) {
  const std::string text = r.string(node);
  if (const std::optional<QueryKind> kind = parseQueryKind(text)) return *kind;
  r.fail(node, "unknown query kind '" + text + "' (known: boolean, all_pairs, contacts, distance)");
}

// The objects a query entry names: "name" (that object) or {"subtree": "name"} (it and every
// object mounted on it), with a label for the query's default name.
struct Selection {
  std::vector<std::size_t> objects;  // ascending
  std::string label;
};

Selection readSelection(const Reader& r, const Node& node, const Scene& scene,
                        const std::map<std::string, std::size_t>& index_of) {
  const auto index = [&](const Node& name_node) {
    const std::string name = r.string(name_node);
    const auto found = index_of.find(name);
    if (found == index_of.end()) r.fail(name_node, "no object named '" + name + "'");
    return found->second;
  };
  if (node.value.is_object()) {
    r.expectObject(node, {"subtree"});
    if (!node.has("subtree")) r.fail(node, "expected {\"subtree\": an object's name}");
    const std::size_t root = index(node.at("subtree"));
    return Selection{scene.subtree(root), scene.objects[root].name + "/*"};
  }
  if (!node.value.is_string()) {
    r.fail(node, std::string("expected an object's name or {\"subtree\": name}, got ") +
                     scene_reading::typeName(node.value));
  }
  const std::size_t object = index(node);
  return Selection{{object}, scene.objects[object].name};
}

// "among": "*" (every object) or an array of object names and subtrees, at least two objects,
// none named twice.
std::vector<std::size_t> readGroup(const Reader& r, const Node& node, const Scene& scene,
                                   const std::map<std::string, std::size_t>& index_of) {
  std::vector<std::size_t> group;
  if (node.value.is_string()) {
    if (r.string(node) != "*") {
      r.fail(node, "'among' is \"*\" or an array of object names and {\"subtree\": name}");
    }
    for (std::size_t i = 0; i < scene.objects.size(); ++i)
      group.push_back(i);
  } else {
    r.expectArray(node);
    for (std::size_t i = 0; i < node.value.size(); ++i) {
      for (const std::size_t index : readSelection(r, node.at(i), scene, index_of).objects) {
        if (std::find(group.begin(), group.end(), index) != group.end()) {
          r.fail(node.at(i), "object '" + scene.objects[index].name + "' named twice");
        }
        group.push_back(index);
      }
    }
    std::sort(group.begin(), group.end());
  }
  if (group.size() < 2) r.fail(node, "a group query needs at least two objects");
  return group;
}

// "a" and "b": two objects, or sets (subtrees) of them, asked against each other: a query of
// two objects, or a group query of every pair across the two sets.
void readSides(const Reader& r, const Node& node, const Scene& scene,
               const std::map<std::string, std::size_t>& index_of, SceneQuery& query,
               std::string& label) {
  Selection sides[2];
  for (int k = 0; k < 2; ++k) {
    const char* side = k == 0 ? "a" : "b";
    if (!node.has(side)) r.fail(node, std::string("missing '") + side + "' (or 'among')");
    sides[k] = readSelection(r, node.at(side), scene, index_of);
  }
  label = sides[0].label + "-" + sides[1].label;
  const std::vector<std::size_t>& a = sides[0].objects;
  const std::vector<std::size_t>& b = sides[1].objects;
  if (a.size() == 1 && b.size() == 1) {
    if (a[0] == b[0]) r.fail(node, "a query needs two different objects");
    query.a = a[0];
    query.b = b[0];
    return;
  }
  std::vector<std::size_t> shared;
  std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(shared));
  if (!shared.empty()) {
    r.fail(node.at("b"), "object '" + scene.objects[shared.front()].name +
                             "' is on both sides: 'a' and 'b' must not share objects");
  }
  std::set_union(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(query.among));
  query.side_b = b;
}

// --- the document ----------------------------------------------------------------------------

// --- stress scenes ---------------------------------------------------------------------------

// A top-level "stress" block stands for every object and query: the cases of one robustness
// category (collido/stress/stress_cases.h) at the listed severities, each case two objects at
// fixed poses, asked all_pairs and boolean, in one frame. The scene holds exactly what
// generateStressCases gives, so a study and the stress tests see the same cases.
void readStress(const Reader& r, const Node& root, const std::string& base_directory,
                const SceneLoadOptions& options, Scene& scene) {
  for (const char* key : {"objects", "queries", "frames", "constraints"}) {
    if (root.has(key)) {
      r.fail(root.at(key), std::string("'") + key +
                               "' is not allowed beside 'stress', which makes a stress scene's "
                               "objects, queries and its one frame, placed as its cases say");
    }
  }
  const Node node = root.at("stress");
  r.expectObject(node, {"category", "severities", "cases_per_severity", "seed", "meshes"});
  if (!node.has("category")) r.fail(node, "missing 'category'");
  const std::string name = r.string(node.at("category"));
  const std::optional<stress::Category> category = stress::parseCategory(name);
  if (!category) {
    std::string known;
    for (const stress::Category c : stress::allCategories())
      known += (known.empty() ? "" : ", ") + std::string(stress::categoryName(c));
    r.fail(node.at("category"), "unknown stress category '" + name + "' (known: " + known + ")");
  }
  const stress::SeverityRange range = stress::severityRange(*category);
  std::vector<int> severities;
  if (node.has("severities")) {
    const Node list = node.at("severities");
    r.expectArray(list);
    if (list.value.empty()) r.fail(list, "give at least one severity");
    for (std::size_t i = 0; i < list.value.size(); ++i) {
      const auto severity = static_cast<int>(
          r.integer(list.at(i), std::numeric_limits<int>::min(), std::numeric_limits<int>::max()));
      if (severity < range.min || severity > range.max) {
        r.fail(list.at(i), "severity " + std::to_string(severity) + " is outside [" +
                               std::to_string(range.min) + ", " + std::to_string(range.max) +
                               "] for " + name + " (" + range.meaning + ")");
      }
      if (std::find(severities.begin(), severities.end(), severity) != severities.end()) {
        r.fail(list.at(i), "severity " + std::to_string(severity) + " is listed twice");
      }
      severities.push_back(severity);
    }
  } else {
    severities = stress::defaultSeverities(*category);
  }
  const auto per_severity =
      static_cast<std::size_t>(r.integer(node, "cases_per_severity", 4, 1, 1000));
  const auto seed = static_cast<std::uint64_t>(r.integer(node, "seed", 1, 0, INT64_MAX));

  stress::StressInputs inputs;
  if (*category == stress::Category::kMeshDefects) {
    if (!node.has("meshes")) {
      r.fail(node, "mesh_defects needs 'meshes': the mesh files to pose (relative to the scene)");
    }
    const Node meshes = node.at("meshes");
    r.expectArray(meshes);
    if (meshes.value.empty()) r.fail(meshes, "give at least one mesh file");
    for (std::size_t i = 0; i < meshes.value.size(); ++i) {
      const std::filesystem::path file =
          (std::filesystem::path(base_directory) / r.string(meshes.at(i))).lexically_normal();
      Result<TriangleMesh> mesh = loadMesh(file.string());
      if (!mesh.ok()) r.fail(meshes.at(i), mesh.status().message());
      inputs.defect_meshes.push_back(
          {file.stem().string(), std::make_shared<const TriangleMesh>(std::move(mesh).value())});
    }
  } else if (node.has("meshes")) {
    r.fail(node.at("meshes"), "only the mesh_defects category takes 'meshes'");
  }

  scene.category = name;
  TriangleBudget budget(r, options.max_triangles);
  // The defect meshes are shared by many cases: inspect each mesh once.
  std::map<const TriangleMesh*, MeshReport> inspected;
  const auto add_object = [&](const std::string& object_name, const char* side,
                              const std::shared_ptr<const TriangleMesh>& mesh, const Pose& pose) {
    SceneObject object;
    object.name = object_name + "/" + side;
    object.mesh = mesh;
    auto found = inspected.find(mesh.get());
    if (found == inspected.end()) {
      MeshReport report;
      report.importer = "stress";
      inspectMesh(*mesh, report);
      found = inspected.emplace(mesh.get(), report).first;
    }
    object.report = found->second;
    object.report.source = name + " stress case, object " + side;
    object.poses = {pose};
    scene.objects.push_back(std::move(object));
    return scene.objects.size() - 1;
  };
  for (const int severity : severities) {
    Result<std::vector<stress::StressCase>> cases =
        stress::generateStressCases(*category, severity, per_severity, seed, inputs);
    if (!cases.ok()) r.fail(node, cases.status().message());
    for (const stress::StressCase& c : cases.value()) {
      budget.charge(node, "stress case " + c.name,
                    static_cast<double>(c.a->triangleCount() + c.b->triangleCount()));
      const std::size_t a = add_object(c.name, "a", c.a, c.pose_a);
      const std::size_t b = add_object(c.name, "b", c.b, c.pose_b);
      // The distance category asks for the distance where the others ask for the pairs.
      const QueryKind detailed =
          *category == stress::Category::kDistance ? QueryKind::kDistance : QueryKind::kAllPairs;
      for (const QueryKind kind : {detailed, QueryKind::kBoolean}) {
        SceneQuery query;
        query.name = c.name + " " + queryKindName(kind);
        query.a = a;
        query.b = b;
        query.request.kind = kind;
        scene.queries.push_back(query);
      }
    }
  }
}

// --- the scene -------------------------------------------------------------------------------

// The object's shape: one ("shape"), or active states ("states", with a "schedule").
void readShapes(const Reader& r, const Node& node, std::size_t frames, ShapeLoader& shapes,
                SceneObject& object) {
  if (!node.has("shape") && !node.has("states"))
    r.fail(node, "missing 'shape' (or 'states', a list of shapes)");
  if (node.has("shape") && node.has("states"))
    r.fail(node, "give only one of 'shape' or 'states' (a list of shapes)");
  if (node.has("shape")) {
    if (node.has("schedule")) r.fail(node.at("schedule"), "a schedule needs 'states'");
    LoadedShape shape = shapes.load(node.at("shape"));
    object.mesh = shape.mesh;
    object.report = shape.report;
  } else {
    const Node list = node.at("states");
    r.expectArray(list);
    if (list.value.empty()) r.fail(list, "an object with states needs at least one");
    for (std::size_t k = 0; k < list.value.size(); ++k) {
      LoadedShape shape = shapes.load(list.at(k));
      object.states.push_back(ObjectState{shape.mesh, shape.report});
    }
    object.mesh = object.states.front().mesh;
    object.report = object.states.front().report;
    const Node schedule = node.has("schedule") ? node.at("schedule") : list;
    object.schedule = scene_reading::readSchedule(r, node.has("schedule") ? &schedule : nullptr,
                                                  object.states.size(), frames);
  }
}

// The object's movable nodes ("deform"), read once its shapes and poses are: a drape casts from
// its first pose onto an earlier object. Every deformed frame is computed once here, so a scene
// that loads holds finite shapes within the coordinate limit in every frame.
void readDeform(const Reader& r, const Node& node, const std::string& base_directory,
                const Scene& scene, const std::map<std::string, std::size_t>& index_of,
                SceneObject& object) {
  if (!node.has("deform")) return;
  const Node deform = node.at("deform");
  scene_reading::DeformContext context;
  context.object = &object;
  context.earlier = [&](const std::string& name) -> const SceneObject* {
    const auto found = index_of.find(name);
    return found == index_of.end() ? nullptr : &scene.objects[found->second];
  };
  object.deformation =
      scene_reading::readDeformation(r, deform, base_directory, scene.frames, context);
  for (std::size_t state = 0; state < object.stateCount(); ++state) {
    const std::size_t vertices = object.stateMesh(state)->vertexCount();
    if (object.deformation->recorded && object.deformation->recorded->vertices != vertices) {
      r.fail(deform.at("recorded"), "records " +
                                        std::to_string(object.deformation->recorded->vertices) +
                                        " vertices but state " + std::to_string(state) + " has " +
                                        std::to_string(vertices));
    }
  }
  for (std::size_t f = 0; f < scene.frames; ++f) {
    const std::shared_ptr<const TriangleMesh> shape = object.shapeAt(f);
    const double largest = shape->vertices.cwiseAbs().maxCoeff();
    if (!std::isfinite(largest) || largest > kMaxCoordinate) {
      std::ostringstream text;
      text << "frame " << f << ": the deformation takes a vertex to " << largest
           << ", beyond the coordinate limit " << kMaxCoordinate << " (scenes/README.md)";
      r.fail(deform, text.str());
    }
  }
}

/// A drape casts its stop distances against both objects' frame-0 poses when it is read: a
/// constraint solve may then move neither (the sheet would float or cut in).
void markDrapes(const Node& node, const std::map<std::string, std::size_t>& index_of,
                std::vector<scene_reading::ObjectMotionSource>& sources, std::size_t object) {
  if (!node.has("deform") || !node.value["deform"].is_object()) return;
  const Json& rules = node.value["deform"].value("rules", Json::array());
  for (const Json& rule : rules) {
    if (!rule.is_object() || !rule.contains("drape")) continue;
    sources[object].draped = true;
    const Json& onto = rule["drape"].value("onto", Json());
    if (!onto.is_string()) continue;
    const auto found = index_of.find(onto.get<std::string>());
    if (found != index_of.end()) sources[found->second].drape_target = true;
  }
}

Scene readScene(const Reader& r, const Json& document, const std::string& base_directory,
                const SceneLoadOptions& options) {
  const Node root{document, ""};
  r.expectObject(root,
                 {"name", "description", "frames", "objects", "constraints", "queries", "stress"});
  Scene scene;
  scene.name = root.has("name") ? r.string(root.at("name")) : "";
  scene.description = root.has("description") ? r.string(root.at("description")) : "";
  if (root.has("stress")) {
    readStress(r, root, base_directory, options, scene);
    return scene;
  }
  const bool frames_given = root.has("frames");
  const auto max_frames = static_cast<std::int64_t>(
      std::min<std::size_t>(options.max_frames, std::numeric_limits<std::int64_t>::max()));
  if (frames_given)
    scene.frames = static_cast<std::size_t>(r.integer(root.at("frames"), 1, max_frames));

  if (!root.has("objects")) r.fail(root, "missing 'objects'");
  const Node objects = root.at("objects");
  r.expectArray(objects);
  if (objects.value.empty()) r.fail(objects, "a scene needs at least one object");

  // Frame count from explicit pose lists when the scene does not state it.
  if (!frames_given) {
    for (std::size_t i = 0; i < objects.value.size(); ++i) {
      const Json& o = objects.value[i];
      if (o.is_object() && o.contains("motion") && o["motion"].is_object() &&
          o["motion"].contains("poses") && o["motion"]["poses"].is_array()) {
        const std::size_t count = o["motion"]["poses"].size();
        if (count > options.max_frames) {
          r.fail(objects.at(i).at("motion").at("poses"),
                 "has " + std::to_string(count) + " poses, more frames than this load allows (" +
                     std::to_string(options.max_frames) + ", SceneLoadOptions::max_frames)");
        }
        scene.frames = std::max<std::size_t>(scene.frames, count);
      }
    }
  }

  ShapeLoader shapes(r, base_directory, options.max_triangles);
  const scene_reading::Hierarchy hierarchy = scene_reading::readHierarchy(
      r, objects,
      {"name", "parent", "shape", "states", "schedule", "deform", "pose", "motion", "markers"});
  // Objects are read parents first (a child's poses compose with its parent's) but keep their
  // file order in the scene; `index_of` holds the objects read so far.
  std::map<std::string, std::size_t> index_of;
  std::vector<scene_reading::ObjectMotionSource> sources(objects.value.size());
  scene.objects.resize(objects.value.size());
  for (std::size_t i = 0; i < scene.objects.size(); ++i)
    scene.objects[i].name = hierarchy.names[i];
  for (const std::size_t i : hierarchy.order) {
    const Node node = objects.at(i);
    SceneObject& object = scene.objects[i];
    readShapes(r, node, scene.frames, shapes, object);
    scene_reading::readMotion(r, node, scene, index_of, sources, i, object);
    sources[i].tracked = node.has("markers");
    if (const std::optional<std::size_t> parent = hierarchy.parents[i]) {
      object.parent = parent;
      sources[i].has_parent = true;
      sources[*parent].has_children = true;
      // A random motion places the object in the world, against another object.
      if (sources[i].kind == "random") {
        scene_reading::expressRelativeToParent(scene.objects[*parent], object);
      }
      scene_reading::composeWithParent(r, node.at("parent"), scene.objects[*parent], scene.frames,
                                       sources[i].tracked, object);
      const SceneObject& mount = scene.objects[*parent];
      if (!sources[i].tracked)
        object.tracked_ancestor = mount.tracking ? parent : mount.tracked_ancestor;
    }
    if (node.has("markers"))
      scene_reading::readMarkers(r, node.at("markers"), base_directory, scene.frames, object);
    readDeform(r, node, base_directory, scene, index_of, object);
    markDrapes(node, index_of, sources, i);
    index_of.emplace(object.name, i);
  }

  if (root.has("constraints")) {
    scene_reading::solveSceneConstraints(r, root.at("constraints"), sources,
                                         options.placement_store, scene);
  }

  if (!root.has("queries")) r.fail(root, "missing 'queries'");
  const Node queries = root.at("queries");
  r.expectArray(queries);
  if (queries.value.empty()) r.fail(queries, "a scene needs at least one query");
  std::set<std::string> query_names;
  for (std::size_t i = 0; i < queries.value.size(); ++i) {
    const Node node = queries.at(i);
    r.expectObject(node, {"name", "a", "b", "among", "kind", "max_pairs", "max_contacts",
                          "abs_tolerance", "rel_tolerance"});
    SceneQuery query;
    std::string label;
    if (node.has("among")) {
      if (node.has("a") || node.has("b")) {
        r.fail(node, "a query names either 'a' and 'b' or 'among', not both");
      }
      query.among = readGroup(r, node.at("among"), scene, index_of);
    } else {
      readSides(r, node, scene, index_of, query, label);
    }
    if (!node.has("kind")) r.fail(node, "missing 'kind'");
    query.request.kind = readQueryKind(r, node.at("kind"));
    // A group's answer is the union over its object pairs: pairs and contacts add up, a
    // boolean or a distance over a group would need a definition of its own.
    if (query.isGroup() && query.request.kind != QueryKind::kAllPairs &&
        query.request.kind != QueryKind::kContacts) {
      r.fail(node.at("kind"),
             "a group query ('among', or a subtree of more than one object) asks "
             "all_pairs or contacts only, not " +
                 std::string(queryKindName(query.request.kind)));
    }
    query.request.max_pairs =
        static_cast<std::uint64_t>(r.integer(node, "max_pairs", 0, 0, INT64_MAX));
    query.request.max_contacts =
        static_cast<std::uint64_t>(r.integer(node, "max_contacts", 0, 0, INT64_MAX));
    for (const char* key : {"abs_tolerance", "rel_tolerance"}) {
      if (!node.has(key)) continue;
      if (query.request.kind != QueryKind::kDistance) {
        r.fail(node.at(key), std::string(key) + " applies to distance queries only");
      }
      const double value = r.number(node.at(key));
      if (value < 0.0) r.fail(node.at(key), std::string(key) + " must be >= 0");
      (key[0] == 'a' ? query.request.abs_tolerance : query.request.rel_tolerance) = value;
    }
    if (node.has("name")) {
      query.name = r.string(node.at("name"));
    } else if (label.empty()) {
      query.name =
          std::to_string(query.among.size()) + " objects " + queryKindName(query.request.kind);
    } else {
      query.name = label + " " + queryKindName(query.request.kind);
    }
    if (!query_names.insert(query.name).second) {
      r.fail(node, "duplicate query name '" + query.name + "'");
    }
    scene.queries.push_back(query);
  }
  return scene;
}

}  // namespace

bool SceneQuery::asksPair(std::size_t i, std::size_t j) const {
  if (!isGroup()) return (i == a && j == b) || (i == b && j == a);
  if (i == j || !names(i) || !names(j)) return false;
  return side_b.empty() || std::binary_search(side_b.begin(), side_b.end(), i) !=
                               std::binary_search(side_b.begin(), side_b.end(), j);
}

std::vector<std::size_t> Scene::subtree(std::size_t root) const {
  // Parents may come after their children in the file: follow each object up to a root.
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    for (std::optional<std::size_t> at = i; at; at = objects[*at].parent) {
      if (*at == root) {
        out.push_back(i);
        break;
      }
    }
  }
  return out;
}

bool SceneQuery::names(std::size_t object) const {
  if (isGroup()) return std::binary_search(among.begin(), among.end(), object);
  return object == a || object == b;
}

std::vector<std::size_t> SceneQuery::objects() const {
  if (isGroup()) return among;
  return {a, b};
}

BuildNeeds Scene::needsOf(std::size_t object) const {
  BuildNeeds needs;
  for (const SceneQuery& q : queries) {
    if (q.names(object)) needs.queries |= q.request.kind;
  }
  needs.deforms = objects[object].deformation != nullptr;
  // The objects linked to this one through queries, directly or through others: grown until no
  // query adds one, so every object of a linked set gets the same kinds.
  std::vector<bool> linked(objects.size(), false);
  linked[object] = true;
  for (bool grew = true; grew;) {
    grew = false;
    for (const SceneQuery& q : queries) {
      const std::vector<std::size_t> named = q.objects();
      if (std::none_of(named.begin(), named.end(), [&](std::size_t i) { return linked[i]; })) {
        continue;
      }
      needs.linked_queries |= q.request.kind;
      for (std::size_t i : named) {
        grew = grew || !linked[i];
        linked[i] = true;
      }
    }
  }
  return needs;
}

std::vector<std::size_t> Scene::queriedObjects() const {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    if (!needsOf(i).queries.empty()) out.push_back(i);
  }
  return out;
}

Result<Scene> parseScene(const std::string& text, const std::string& label,
                         const std::string& base_directory, const SceneLoadOptions& options) {
  if (!(options.resolution > 0.0) || !std::isfinite(options.resolution)) {
    return Status(StatusCode::kInvalidArgument,
                  label + ": resolution must be a positive finite number");
  }
  Result<Json> parsed = scene_reading::parseDocument(text, label);
  if (!parsed.ok()) return parsed.status();
  const Json& document = parsed.value();
  try {
    const Reader reader(label, options.resolution);
    Scene scene = readScene(reader, document, base_directory, options);
    scene.resolution = options.resolution;
    if (scene.name.empty()) scene.name = std::filesystem::path(label).stem().string();
    return scene;
  } catch (const SceneError& e) {
    return Status(StatusCode::kInvalidArgument, e.what());
  } catch (const Json::exception& e) {
    return Status(StatusCode::kInvalidArgument, label + ": " + e.what());
  }
}

bool Scene::hasTrackedObjects() const {
  return std::any_of(objects.begin(), objects.end(),
                     [](const SceneObject& o) { return o.tracking != nullptr; });
}

Scene Scene::withTruePoses() const {
  Scene truth = *this;
  for (SceneObject& object : truth.objects) {
    if (object.tracking) {
      object.poses = object.tracking->true_poses;
      object.tracking.reset();
    } else if (!object.inherited_true_poses.empty()) {
      object.poses = std::move(object.inherited_true_poses);
      object.inherited_true_poses.clear();
    }
    object.tracked_ancestor.reset();
  }
  return truth;
}

bool Scene::hasGeneratedShapes() const {
  return std::any_of(objects.begin(), objects.end(), [](const SceneObject& o) {
    return o.report.importer == "generator" ||
           std::any_of(o.states.begin(), o.states.end(), [](const ObjectState& state) {
             return state.report.importer == "generator";
           });
  });
}

Result<Scene> loadScene(const std::string& path, const SceneLoadOptions& options) {
  const InputFileRecorder inputs;
  Result<std::string> text = readInputFile(path, "scene file");
  if (!text.ok()) return text.status();
  Result<Scene> scene =
      parseScene(text.value(), path, std::filesystem::path(path).parent_path().string(), options);
  if (scene.ok()) {
    scene.value().path = path;
    scene.value().input_files = inputs.files();
  }
  return scene;
}

}  // namespace collido
