// Object shapes in scene files: a mesh file, a generator's parameters or an FRep solid, each
// charged to the load's triangle limit before it is made (scenes/README.md, "Shapes").
#pragma once

#include <cstddef>
#include <map>
#include <memory>
#include <string>

#include <collido/mesh/mesh_io.h>
#include <collido/mesh/triangle_mesh.h>

#include "scene_reader.h"

namespace collido::scene_reading {

/// The scene's triangle limit (SceneLoadOptions::max_triangles), charged shape by shape: a
/// generated shape before it is generated (from its parameters), a mesh file once read.
class TriangleBudget {
 public:
  TriangleBudget(const Reader& reader, std::size_t limit) : reader_(reader), limit_(limit) {}

  /// Adds `triangles` (computed in double, so huge counts cannot overflow) for the shape at
  /// `node`, described by `what`; fails naming the shape when the scene goes past the limit.
  void charge(const Node& node, const std::string& what, double triangles);

  /// The scene-wide triangle limit (0: none).
  std::size_t limit() const { return limit_; }

 private:
  const Reader& reader_;
  std::size_t limit_;
  double used_ = 0.0;
};

/// A shape as an object holds it: the mesh and what the report says of it.
struct LoadedShape {
  std::shared_ptr<const TriangleMesh> mesh;
  MeshReport report;
};

/// Reads the shapes of one scene, loading each mesh file once per scale.
class ShapeLoader {
 public:
  ShapeLoader(const Reader& reader, std::string base_directory, std::size_t max_triangles)
      : reader_(reader), base_(std::move(base_directory)), budget_(reader, max_triangles) {}

  /// The shape at `node`: {"mesh": file, "scale"}, {"generator": name, ...} or {"frep": solid,
  /// "cells"}. Fails at the node, naming the problem.
  LoadedShape load(const Node& node);

 private:
  LoadedShape loadFile(const Node& node);
  LoadedShape generate(const Node& node);
  LoadedShape polygonizeSolid(const Node& node);

  const Reader& reader_;
  std::string base_;
  TriangleBudget budget_;
  std::map<std::string, LoadedShape> cache_;
};

}  // namespace collido::scene_reading
