// CGAL as a Collidoscope plugin: the exact peer. Every mesh is a CGAL::Surface_mesh on the
// exact-constructions kernel (EPECK) with an AABB tree of its faces, built once:
//   boolean   -> CGAL::Rigid_triangle_mesh_collision_detection with both trees and each pose as an
//                Aff_transformation_3 (get_all_intersections: surfaces that share a point, no
//                inclusion test), the API CGAL offers for rigid meshes;
//   all_pairs -> A's tree traversed for the faces whose boxes meet the box of each of B's
//                triangles mapped into A's frame (pose_a^-1 * pose_b); CGAL's exact do_intersect
//                then decides each candidate on both triangles placed exactly in the world frame.
// The poses' double entries are taken as exact numbers, as the oracle takes them, so the answers
// should be the oracle's; where they are not, that is a finding (README.md).
#include <algorithm>
#include <cstdint>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Aff_transformation_3.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Rigid_triangle_mesh_collision_detection.h>
#include <CGAL/Surface_mesh.h>

#include <collido/plugin_export.h>

namespace collido::cgal_backend {
namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Detection = CGAL::Rigid_triangle_mesh_collision_detection<Mesh>;
using Tree = Detection::AABB_tree;
using Transformation = CGAL::Aff_transformation_3<Kernel>;
using Interval = CGAL::Interval_nt<false>;

Transformation toTransformation(const Pose& pose) {
  const auto& m = pose.matrix();
  return Transformation(m(0, 0), m(0, 1), m(0, 2), m(0, 3), m(1, 0), m(1, 1), m(1, 2), m(1, 3),
                        m(2, 0), m(2, 1), m(2, 2), m(2, 3), 1.0);
}

/// A traversal of CGAL's AABB tree that collects the faces whose boxes overlap a query box:
/// box tests only, so that exact arithmetic is spent on candidate pairs alone (CGAL's own
/// Bbox_3 query would also test each face's triangle against the box, in exact arithmetic).
struct BoxOverlap {
  const std::vector<CGAL::Bbox_3>* face_boxes = nullptr;
  std::vector<Mesh::Face_index>* found = nullptr;
  bool go_further() const { return true; }
  void intersection(const CGAL::Bbox_3& query, const Tree::Primitive& primitive) {
    if (CGAL::do_overlap(query, (*face_boxes)[primitive.id().idx()]))
      found->push_back(primitive.id());
  }
  template <class Node>
  bool do_intersect(const CGAL::Bbox_3& query, const Node& node) const {
    return CGAL::do_overlap(query, node.bbox());
  }
};

/// One mesh: its Surface_mesh (face i is triangle i) and the AABB tree of its faces.
class CgalModel final : public BackendModel {
 public:
  CgalModel(const MeshView& view, bool keep_triangles) {
    const auto triangle_count = static_cast<std::size_t>(view.triangles.cols());
    // Shared vertices where CGAL's halfedge structure can hold the mesh; a mesh with a repeated
    // corner or a non-manifold edge becomes a soup of triangles with three vertices each
    // (Surface_mesh refuses such faces), which costs memory but keeps every triangle.
    shared_vertices_ = buildShared(view);
    if (!shared_vertices_) buildSoup(view);
    if (mesh_.number_of_faces() != triangle_count) {
      throw std::runtime_error("CGAL's Surface_mesh holds " +
                               std::to_string(mesh_.number_of_faces()) + " faces of " +
                               std::to_string(triangle_count) + " triangles");
    }
    if (keep_triangles) triangles_ = view.triangles;
    tree_ = std::make_unique<Tree>(faces(mesh_).first, faces(mesh_).second, mesh_);
    tree_->build();
    measureFaces();
  }

  const Mesh& mesh() const { return mesh_; }
  const Tree& tree() const { return *tree_; }
  /// The faces of A whose boxes (model frame) overlap `box`, into `found`.
  void facesOverlapping(const CGAL::Bbox_3& box, std::vector<Mesh::Face_index>& found) const {
    BoxOverlap traversal{&face_boxes_, &found};
    tree_->traversal(box, traversal);
  }

  /// New vertex positions, then a new tree (CGAL's AABB tree has no refit).
  UpdateCounters update(const Eigen::Ref<const Eigen::Matrix3Xd>& positions) {
    if (shared_vertices_) {
      for (Mesh::Vertex_index v : mesh_.vertices()) {
        const auto c = positions.col(static_cast<Eigen::Index>(v.idx()));
        mesh_.point(v) = Point(c.x(), c.y(), c.z());
      }
    } else {
      for (Eigen::Index t = 0; t < triangles_.cols(); ++t) {
        for (int k = 0; k < 3; ++k) {
          const auto c = positions.col(triangles_(k, t));
          mesh_.point(Mesh::Vertex_index(static_cast<std::uint32_t>(3 * t + k))) =
              Point(c.x(), c.y(), c.z());
        }
      }
    }
    tree_->rebuild(faces(mesh_).first, faces(mesh_).second, mesh_);
    measureFaces();
    UpdateCounters counters;
    counters.counted = true;
    counters.rebuilds = 1;
    counters.nodes_rebuilt = mesh_.number_of_faces() - 1;
    return counters;
  }

  std::size_t memoryBytes() const override {
    // Per vertex: the halfedge index and the point, a handle to a lazy exact representation (its
    // interval approximation; the exact rationals are made only where a predicate needs them).
    // Per halfedge: next, previous, target, face indices; per face: a halfedge index. The tree:
    // a primitive (face and mesh pointer) per face and a node per face, as CGAL allocates them.
    constexpr std::size_t kLazyPoint =
        sizeof(Point) + 3 * sizeof(CGAL::Interval_nt<false>) + 2 * sizeof(void*) + sizeof(unsigned);
    const std::size_t vertices = mesh_.number_of_vertices();
    const std::size_t halfedges = mesh_.number_of_halfedges();
    const std::size_t face_count = mesh_.number_of_faces();
    return vertices * (sizeof(std::uint32_t) + kLazyPoint) + halfedges * 4 * sizeof(std::uint32_t) +
           face_count * sizeof(std::uint32_t) +
           face_count * (sizeof(Tree::Primitive) + sizeof(CGAL::AABB_node<Tree::AABB_traits>)) +
           face_boxes_.size() * sizeof(CGAL::Bbox_3) +
           static_cast<std::size_t>(triangles_.size()) * sizeof(int) + sizeof(*this);
  }

 private:
  bool buildShared(const MeshView& view) {
    for (Eigen::Index i = 0; i < view.vertices.cols(); ++i) {
      const auto c = view.vertices.col(i);
      mesh_.add_vertex(Point(c.x(), c.y(), c.z()));
    }
    for (Eigen::Index t = 0; t < view.triangles.cols(); ++t) {
      const auto c = view.triangles.col(t);
      if (c[0] == c[1] || c[1] == c[2] || c[0] == c[2] ||
          mesh_.add_face(Mesh::Vertex_index(static_cast<std::uint32_t>(c[0])),
                         Mesh::Vertex_index(static_cast<std::uint32_t>(c[1])),
                         Mesh::Vertex_index(static_cast<std::uint32_t>(c[2]))) ==
              Mesh::null_face()) {
        mesh_.clear();
        return false;
      }
    }
    return true;
  }

  void measureFaces() {
    face_boxes_.clear();
    face_boxes_.reserve(mesh_.number_of_faces());
    for (Mesh::Face_index f : mesh_.faces()) {
      CGAL::Bbox_3 box;
      for (Mesh::Vertex_index v : CGAL::vertices_around_face(mesh_.halfedge(f), mesh_))
        box += mesh_.point(v).bbox();
      face_boxes_.push_back(box);
    }
  }

  void buildSoup(const MeshView& view) {
    mesh_.reserve(static_cast<Mesh::size_type>(3 * view.triangles.cols()),
                  static_cast<Mesh::size_type>(3 * view.triangles.cols()),
                  static_cast<Mesh::size_type>(view.triangles.cols()));
    for (Eigen::Index t = 0; t < view.triangles.cols(); ++t) {
      Mesh::Vertex_index corners[3];
      for (int k = 0; k < 3; ++k) {
        const auto c = view.vertices.col(view.triangles(k, t));
        corners[k] = mesh_.add_vertex(Point(c.x(), c.y(), c.z()));
      }
      mesh_.add_face(corners[0], corners[1], corners[2]);
    }
  }

  Mesh mesh_;
  bool shared_vertices_ = true;
  Eigen::Matrix3Xi triangles_;  // kept for update() where the mesh is a soup
  std::unique_ptr<Tree> tree_;
  std::vector<CGAL::Bbox_3> face_boxes_;  // per face, in the model frame
};

class CgalBackend final : public Backend {
 public:
  Capabilities capabilities() const override {
    Capabilities caps;
    caps.shape_kinds = static_cast<std::uint32_t>(ShapeKind::kTriangleMesh);
    caps.queries = QueryKindSet(QueryKind::kBoolean) | QueryKind::kAllPairs;
    caps.update = true;
    caps.counts_update_work = true;
    caps.notes =
        "CGAL 5 on the exact-constructions kernel: boolean by "
        "Rigid_triangle_mesh_collision_detection (surface intersection, no inclusion test), "
        "all pairs by the AABB tree of A's faces queried with B's triangles mapped exactly "
        "into A's frame; update rebuilds the tree (CGAL's has no refit). No work counters.";
    return caps;
  }

  Result<std::unique_ptr<BackendModel>> build(const MeshView& mesh, const BuildNeeds& needs,
                                              const StateSibling& /*sibling*/) override {
    return std::unique_ptr<BackendModel>(std::make_unique<CgalModel>(mesh, needs.deforms));
  }

  Status update(BackendModel& model, const Eigen::Ref<const Eigen::Matrix3Xd>& positions,
                UpdateCounters& counters) override {
    counters = static_cast<CgalModel&>(model).update(positions);
    return {};
  }

  Status query(BackendModel& a_model, const Pose& pose_a, BackendModel& b_model, const Pose& pose_b,
               const QueryRequest& request, QueryResult& result) override {
    const auto& a = static_cast<const CgalModel&>(a_model);
    const auto& b = static_cast<const CgalModel&>(b_model);
    if (request.kind == QueryKind::kBoolean) {
      Detection detection;
      // The trees are the models' own (not copied); one point per mesh would serve the inclusion
      // test, which this question does not ask.
      const auto one_component = CGAL::parameters::apply_per_connected_component(false);
      detection.add_mesh(a.tree(), a.mesh(), one_component);
      detection.add_mesh(b.tree(), b.mesh(), one_component);
      detection.set_transformation(0, toTransformation(pose_a));
      detection.set_transformation(1, toTransformation(pose_b));
      result.intersecting = !detection.get_all_intersections(0).empty();
      return {};
    }
    allPairs(a, pose_a, b, pose_b, request.max_pairs, result);
    return {};
  }

 private:
  // B's triangles are looked up in A's tree by their boxes in A's frame, computed in interval
  // arithmetic (conservative, and without exact arithmetic);
  // each candidate pair is then decided by CGAL's exact do_intersect on both triangles placed in
  // the world frame. The world corners use the poses as given, with no inverse: exact values
  // with small denominators, which the degenerate (touching) cases need.
  void allPairs(const CgalModel& a, const Pose& pose_a, const CgalModel& b, const Pose& pose_b,
                std::uint64_t limit, QueryResult& result) {
    const Transformation a_to_world = toTransformation(pose_a);
    const Transformation b_to_world = toTransformation(pose_b);
    const Transformation b_to_a = a_to_world.inverse() * b_to_world;
    const Mesh& mesh_a = a.mesh();
    const Mesh& mesh_b = b.mesh();
    // B's corners in A's frame as intervals, from the interval enclosures of the exact map's
    // entries: boxes that hold the exact corners, with no exact number made.
    boxes_b_.clear();
    {
      const CGAL::Protect_FPU_rounding<true> rounding_upward;
      Interval entries[3][4];
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 4; ++j)
          entries[i][j] = Interval(CGAL::to_interval(b_to_a.m(i, j)));
      }
      for (Mesh::Vertex_index v : mesh_b.vertices()) {
        const Point& p = mesh_b.point(v);
        const Interval x(CGAL::to_interval(p.x()));
        const Interval y(CGAL::to_interval(p.y()));
        const Interval z(CGAL::to_interval(p.z()));
        Interval mapped[3];
        for (int i = 0; i < 3; ++i)
          mapped[i] = entries[i][0] * x + entries[i][1] * y + entries[i][2] * z + entries[i][3];
        boxes_b_.emplace_back(mapped[0].inf(), mapped[1].inf(), mapped[2].inf(), mapped[0].sup(),
                              mapped[1].sup(), mapped[2].sup());
      }
    }
    // World corners are made for the candidates' corners only; the caches keep their size across
    // queries, and only the entries this query touched are reset at its end.
    for (auto* cache : {&world_a_cache_, &world_b_cache_}) {
      const std::size_t n =
          cache == &world_a_cache_ ? mesh_a.number_of_vertices() : mesh_b.number_of_vertices();
      if (cache->points.size() < n) {
        cache->points.resize(n);
        cache->placed.resize(n, 0);
      }
    }
    const auto world = [](const Mesh& mesh, const Transformation& to_world, WorldCache& cache,
                          Mesh::Vertex_index v) -> const Point& {
      if (cache.placed[v.idx()] == 0) {
        cache.points[v.idx()] = to_world.transform(mesh.point(v));
        cache.placed[v.idx()] = 1;
        cache.touched.push_back(v.idx());
      }
      return cache.points[v.idx()];
    };
    const auto worldA = [&](Mesh::Vertex_index v) -> const Point& {
      return world(mesh_a, a_to_world, world_a_cache_, v);
    };
    const auto worldB = [&](Mesh::Vertex_index v) -> const Point& {
      return world(mesh_b, b_to_world, world_b_cache_, v);
    };
    for (Mesh::Face_index f : mesh_b.faces()) {
      Mesh::Vertex_index corners_b[3];
      int k = 0;
      for (Mesh::Vertex_index v : CGAL::vertices_around_face(mesh_b.halfedge(f), mesh_b))
        corners_b[k++] = v;
      const CGAL::Bbox_3 box = boxes_b_[corners_b[0].idx()] + boxes_b_[corners_b[1].idx()] +
                               boxes_b_[corners_b[2].idx()];
      hits_.clear();
      a.facesOverlapping(box, hits_);
      if (hits_.empty()) continue;
      const Kernel::Triangle_3 triangle_b(worldB(corners_b[0]), worldB(corners_b[1]),
                                          worldB(corners_b[2]));
      for (const Tree::Primitive_id& hit : hits_) {
        Mesh::Vertex_index corners_a[3];
        int j = 0;
        for (Mesh::Vertex_index v : CGAL::vertices_around_face(mesh_a.halfedge(hit), mesh_a))
          corners_a[j++] = v;
        const Kernel::Triangle_3 triangle_a(worldA(corners_a[0]), worldA(corners_a[1]),
                                            worldA(corners_a[2]));
        if (!CGAL::do_intersect(triangle_a, triangle_b)) continue;
        result.pairs.push_back(
            TrianglePair{static_cast<std::int32_t>(hit.idx()), static_cast<std::int32_t>(f.idx())});
      }
      if (limit != 0 && result.pairs.size() > limit) {
        result.pairs.resize(limit);
        result.truncated = true;
        break;
      }
    }
    result.intersecting = !result.pairs.empty();
    for (auto* cache : {&world_a_cache_, &world_b_cache_}) {
      for (std::uint32_t v : cache->touched)
        cache->placed[v] = 0;
      cache->touched.clear();
    }
  }

  /// World corners of one mesh made during a query, by vertex index.
  struct WorldCache {
    std::vector<Point> points;
    std::vector<char> placed;
    std::vector<std::uint32_t> touched;
  };

  std::vector<CGAL::Bbox_3> boxes_b_;
  WorldCache world_a_cache_;
  WorldCache world_b_cache_;
  std::vector<Tree::Primitive_id> hits_;
};

Result<std::unique_ptr<Backend>> create(const std::string& variant, BackendOptions& /*options*/) {
  if (variant == "cgal") return std::unique_ptr<Backend>(std::make_unique<CgalBackend>());
  return Status(StatusCode::kInvalidArgument, "cgal has no variant '" + variant + "'");
}

const PluginInfo& describe() {
  static const PluginInfo info{
      "cgal",
      "0.1.0",
      "CGAL",
      COLLIDO_CGAL_VERSION,
      {{"cgal",
        "CGAL's Rigid_triangle_mesh_collision_detection and AABB tree, exact constructions"}},
      &create};
  return info;
}

}  // namespace
}  // namespace collido::cgal_backend

COLLIDO_DEFINE_PLUGIN(cgal, collido::cgal_backend::describe)
