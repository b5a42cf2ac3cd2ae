#include "shape_reader.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <sstream>

#include <collido/frep_mesh/polygonize.h>

#include "frep_solid_reader.h"
#include "generator_reader.h"

namespace collido::scene_reading {
namespace {

// A mesh made by the loader (a generator, a polygonization), described by `text`.
LoadedShape generatedShape(TriangleMesh mesh, const std::string& text) {
  LoadedShape shape;
  shape.report.source = text;
  shape.report.importer = "generator";
  inspectMesh(mesh, shape.report);
  shape.mesh = std::make_shared<const TriangleMesh>(std::move(mesh));
  return shape;
}

}  // namespace

void TriangleBudget::charge(const Node& node, const std::string& what, double triangles) {
  // Parameters the generator will refuse can give a negative count: it must not free budget.
  used_ += std::max(0.0, triangles);
  if (limit_ == 0 || used_ <= static_cast<double>(limit_)) return;
  std::ostringstream text;
  text << std::fixed << std::setprecision(0) << what << " needs " << triangles
       << " triangles, which takes the scene to " << used_ << ", more than this load allows ("
       << limit_ << ", SceneLoadOptions::max_triangles)";
  reader_.fail(node, text.str());
}

LoadedShape ShapeLoader::load(const Node& node) {
  const Reader& r = reader_;
  if (!node.value.is_object())
    r.fail(node, "expected an object with 'mesh', 'generator' or 'frep'");
  const int sources = static_cast<int>(node.has("mesh")) + static_cast<int>(node.has("generator")) +
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

LoadedShape ShapeLoader::loadFile(const Node& node) {
  const Reader& r = reader_;
  r.expectObject(node, {"mesh", "scale"});
  const std::string relative = r.string(node.at("mesh"));
  // One factor, or one per axis (a URDF mesh's scale).
  Eigen::Vector3d scale = Eigen::Vector3d::Ones();
  if (node.has("scale") && node.at("scale").value.is_array()) {
    scale = r.vector3(node.at("scale"));
    if (!(scale.minCoeff() > 0.0)) r.fail(node.at("scale"), "scale factors must be > 0");
  } else {
    scale.setConstant(r.positive(node, "scale", 1.0));
  }
  const std::filesystem::path file = std::filesystem::path(base_) / relative;
  // Every bit of the scale (std::to_string keeps six decimals).
  char factors[80];
  std::snprintf(factors, sizeof factors, "|%.17g|%.17g|%.17g", scale.x(), scale.y(), scale.z());
  const std::string key = file.lexically_normal().string() + factors;
  if (const auto hit = cache_.find(key); hit != cache_.end()) return hit->second;

  MeshReport report;
  Result<TriangleMesh> mesh = loadMesh(file.lexically_normal().string(), &report);
  if (!mesh.ok()) r.fail(node.at("mesh"), mesh.status().message());
  if (scale != Eigen::Vector3d::Ones()) {
    mesh.value().vertices = scale.asDiagonal() * mesh.value().vertices;
    // A large scale can take finite coordinates past the double range.
    if (Status s = validateMesh(mesh.value(), file.lexically_normal().string()); !s.ok()) {
      r.fail(node.at("scale"), "scaled by " + shortNumber(scale.maxCoeff()) + ": " + s.message());
    }
  }
  LoadedShape shape{std::make_shared<const TriangleMesh>(std::move(mesh).value()), report};
  cache_.emplace(key, shape);
  return shape;
}

LoadedShape ShapeLoader::generate(const Node& node) {
  const Reader& r = reader_;
  const PlannedShape planned = readGenerator(r, node);
  budget_.charge(node, planned.description, planned.triangles);
  Result<TriangleMesh> mesh = planned.make();
  if (!mesh.ok()) r.fail(node, mesh.status().message());
  // Finite parameters can still overflow in the shape (a radius near the double maximum).
  if (Status s = validateMesh(mesh.value(), planned.description); !s.ok()) {
    r.fail(node, s.message());
  }
  return generatedShape(std::move(mesh).value(), planned.description);
}

// An FRep solid (docs/frep.md) polygonized at load with OpenVDB: `cells` grid cells along the
// longest side of its bounds (scaled by the load's resolution). Its animated parameters take
// their values at time 0; `collido frep` checks animated solids frame by frame.
LoadedShape ShapeLoader::polygonizeSolid(const Node& node) {
  const Reader& r = reader_;
  r.expectObject(node, {"frep", "cells"});
  const int cells = r.resolved(static_cast<int>(r.integer(node, "cells", 64, 2, 512)), 2);
  const std::string text = "FRep solid polygonized at " + std::to_string(cells) + " cells";
  // Charged before the work: a closed surface over a grid of N cells is about 12 N^2
  // triangles, and a load with a triangle limit also limits the function evaluations.
  budget_.charge(node, text, 12.0 * cells * cells);
  const double evaluations = std::pow(cells + 3.0, 3) * frepEvaluationCost(node.at("frep").value);
  if (budget_.limit() > 0 && evaluations > 100.0 * static_cast<double>(budget_.limit())) {
    r.fail(node, text + " takes about " + shortNumber(evaluations) +
                     " node evaluations, more than this load allows (100 x "
                     "SceneLoadOptions::max_triangles)");
  }
  const frep::SolidPtr solid = readFrepSolid(r, node.at("frep"), 0.0);
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

}  // namespace collido::scene_reading
