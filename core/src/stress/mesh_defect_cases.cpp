// The mesh_defects category: meshes with cracks, duplicate vertices and non-manifold edges (given
// by the caller, e.g. the shared truck_nonmanifold, teapot_newell and lilium_open_thin) posed
// against generated plates, against each other and against a copy of themselves.
//
// Kinds, cycling with the case index (the mesh advances every four cases):
//   plate_at_extreme  a plate across the mesh's extreme vertex along a seeded axis, at exact
//                     contact or 10^-severity of the mesh's size beyond or short of it;
//   plate_at_defect   a plate through a vertex of a crack or non-manifold edge (the same offsets);
//   pair_overlap      the next mesh, turned at random, its box centre near this one's;
//   patch_copy        a patch of the mesh (its 64 triangles nearest a crack or non-manifold
//                     vertex) against the mesh, coincident or moved 10^-severity of the mesh's
//                     size in a seeded direction: nearly coincident surfaces at a defect (a patch,
//                     not the whole mesh, keeps the oracle's exact coplanar tests to a few
//                     thousand).
// The meshes are shared, never copied: both objects share one exact pose (identity or an exact
// 90°/180° rotation with a dyadic translation) except in pair_overlap and patch_copy.
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>

#include "stress_generators.h"

namespace collido::stress::detail {
namespace {

// The vertices that triangles use, in order.
std::vector<Eigen::Index> referencedVertices(const TriangleMesh& mesh) {
  std::vector<bool> used(static_cast<std::size_t>(mesh.vertices.cols()), false);
  for (Eigen::Index t = 0; t < mesh.triangles.cols(); ++t) {
    for (int k = 0; k < 3; ++k)
      used[static_cast<std::size_t>(mesh.triangles(k, t))] = true;
  }
  std::vector<Eigen::Index> out;
  for (std::size_t v = 0; v < used.size(); ++v) {
    if (used[v]) out.push_back(static_cast<Eigen::Index>(v));
  }
  return out;
}

// Vertices on an edge that one triangle uses (a crack or a border) or more than two use
// (non-manifold), by index: where a mesh's defects are. Empty for a closed manifold mesh.
std::vector<Eigen::Index> defectVertices(const TriangleMesh& mesh) {
  std::map<std::pair<int, int>, int> uses;
  for (Eigen::Index t = 0; t < mesh.triangles.cols(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const int i = mesh.triangles(k, t);
      const int j = mesh.triangles((k + 1) % 3, t);
      if (i != j) ++uses[{std::min(i, j), std::max(i, j)}];
    }
  }
  std::vector<Eigen::Index> out;
  for (const auto& [edge, count] : uses) {
    if (count != 2) out.push_back(edge.first);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

// A square plate normal to coordinate axis `axis` at coordinate `at`, spanning [lo, hi] (widened
// by a tenth) along the other two axes.
TriangleMesh plateAcross(int axis, double at, const Eigen::Vector3d& lo,
                         const Eigen::Vector3d& hi) {
  const int u = (axis + 1) % 3;
  const int v = (axis + 2) % 3;
  const Eigen::Vector3d margin = 0.1 * (hi - lo);
  MeshBuilder builder;
  std::array<int, 4> corner{};
  for (int i = 0; i < 4; ++i) {
    Eigen::Vector3d p;
    p[axis] = at;
    p[u] = (i == 1 || i == 2) ? hi[u] + margin[u] : lo[u] - margin[u];
    p[v] = i >= 2 ? hi[v] + margin[v] : lo[v] - margin[v];
    corner[static_cast<std::size_t>(i)] = builder.vertex(p);
  }
  builder.triangle(corner[0], corner[1], corner[2]);
  builder.triangle(corner[0], corner[2], corner[3]);
  return builder.build();
}

// The `count` triangles whose centroids are nearest `centre` (ties by index), as their own mesh.
TriangleMesh patchAround(const TriangleMesh& mesh, const Eigen::Vector3d& centre,
                         std::size_t count) {
  std::vector<std::pair<double, Eigen::Index>> order;
  for (Eigen::Index t = 0; t < mesh.triangles.cols(); ++t) {
    const Eigen::Vector3d c =
        (mesh.vertices.col(mesh.triangles(0, t)) + mesh.vertices.col(mesh.triangles(1, t)) +
         mesh.vertices.col(mesh.triangles(2, t))) /
        3.0;
    order.emplace_back((c - centre).squaredNorm(), t);
  }
  count = std::min(count, order.size());
  std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(count), order.end());
  order.resize(count);
  std::sort(order.begin(), order.end(),
            [](const auto& x, const auto& y) { return x.second < y.second; });
  MeshBuilder builder;
  std::map<int, int> renumbered;
  for (const auto& [distance, t] : order) {
    int corner[3];
    for (int k = 0; k < 3; ++k) {
      const int v = mesh.triangles(k, t);
      const auto found = renumbered.find(v);
      corner[k] = found != renumbered.end() ? found->second
                                            : renumbered[v] = builder.vertex(mesh.vertices.col(v));
    }
    builder.triangle(corner[0], corner[1], corner[2]);
  }
  return builder.build();
}

Pose sharedExactPose(Rng& rng) {
  if (rng.coin()) return Pose::Identity();
  const Eigen::Matrix3d rotation = signedPermutation(rng.integer(0, 23));
  const Eigen::Vector3d translation = rng.dyadicVector(4.0, 8);
  return makePose(rotation, translation);
}

}  // namespace

StressCase meshDefectsCase(const CaseRequest& request, Rng& rng) {
  const std::vector<NamedMesh>& meshes = request.inputs->defect_meshes;
  const std::size_t kind = request.index % 4;
  const NamedMesh& named = meshes[(request.index / 4) % meshes.size()];
  const TriangleMesh& mesh = *named.mesh;
  const std::vector<Eigen::Index> used = referencedVertices(mesh);
  Eigen::Vector3d lo = mesh.vertices.col(used.front());
  Eigen::Vector3d hi = lo;
  for (const Eigen::Index v : used) {
    lo = lo.cwiseMin(mesh.vertices.col(v));
    hi = hi.cwiseMax(mesh.vertices.col(v));
  }
  const double size = (hi - lo).norm();
  const double offset = size * std::pow(10.0, -request.severity);
  const std::array<double, 3> gaps = {0.0, offset, -offset};
  const double gap =
      gaps[(request.index / 4 + request.index + static_cast<std::size_t>(request.severity)) %
           gaps.size()];
  const char* side = gap == 0.0 ? "_touch" : gap > 0.0 ? "_gap" : "_overlap";

  StressCase out;
  out.a = named.mesh;
  switch (kind) {
    case 0:
    case 1: {
      const int axis = rng.integer(0, 2);
      const double sense = rng.coin() ? 1.0 : -1.0;
      double at = 0.0;
      if (kind == 0) {
        // The extreme referenced vertex along sense · axis; the plate beyond it by `gap`.
        at = sense > 0 ? hi[axis] : lo[axis];
        const double plate = at + sense * gap;
        out.aim = Aim{sense * plate <= sense * at, sense * plate >= sense * at};
        out.b = std::make_shared<const TriangleMesh>(plateAcross(axis, plate, lo, hi));
        out.kind = "plate_at_extreme_" + named.name + side;
      } else {
        std::vector<Eigen::Index> defects = defectVertices(mesh);
        if (defects.empty()) defects = used;
        const Eigen::Index v =
            defects[static_cast<std::size_t>(rng.integer(0, static_cast<int>(defects.size()) - 1))];
        at = mesh.vertices(axis, v);
        const double plate = at + sense * gap;
        // Through the vertex, the plate touches the mesh at least there: exact. Moved off it, it
        // almost surely still cuts the mesh, but only the oracle can say.
        out.aim = Aim{true, plate == at};
        out.b = std::make_shared<const TriangleMesh>(plateAcross(axis, plate, lo, hi));
        out.kind = "plate_at_defect_" + named.name + side;
      }
      out.pose_a = sharedExactPose(rng);
      out.pose_b = out.pose_a;
      break;
    }
    case 2: {
      const NamedMesh& other = meshes[(request.index / 4 + 1) % meshes.size()];
      out.b = other.mesh;
      out.pose_a = sharedExactPose(rng);
      const Eigen::Matrix3d turn = rng.rotation();
      const Eigen::Vector3d direction = rng.direction();
      const double overlap = rng.uniform(0.3, 0.9);
      const Eigen::Vector3d other_lo = other.mesh->vertices.rowwise().minCoeff();
      const Eigen::Vector3d other_hi = other.mesh->vertices.rowwise().maxCoeff();
      const Eigen::Vector3d other_centre = 0.5 * (other_lo + other_hi);
      // B's box centre placed (1 - overlap) of the sum of the two half-diagonals from A's (in A's
      // model frame): the bounding spheres overlap, the surfaces usually cross (a thin or hollow
      // mesh may also hold the other inside it untouched: the oracle decides).
      const double reach = (1.0 - overlap) * 0.5 * (size + (other_hi - other_lo).norm());
      const Eigen::Vector3d target = 0.5 * (lo + hi) + reach * direction;
      out.pose_b = out.pose_a * makePose(turn, target - turn * other_centre);
      out.aim = Aim{true, false};
      out.kind = "pair_overlap_" + named.name + "_" + other.name;
      break;
    }
    default: {
      std::vector<Eigen::Index> defects = defectVertices(mesh);
      if (defects.empty()) defects = used;
      const Eigen::Index v =
          defects[static_cast<std::size_t>(rng.integer(0, static_cast<int>(defects.size()) - 1))];
      out.b = std::make_shared<const TriangleMesh>(patchAround(mesh, mesh.vertices.col(v), 64));
      out.pose_a = sharedExactPose(rng);
      const Eigen::Vector3d direction = rng.direction();
      out.pose_b = out.pose_a;
      out.pose_b.translation() += out.pose_a.linear() * (std::abs(gap) * direction);
      // Coincident, every patch triangle meets its original: exact. Moved, only the oracle knows.
      out.aim = Aim{true, gap == 0.0};
      out.kind = "patch_copy_" + named.name + (gap == 0.0 ? "_coincident" : "_offset");
      break;
    }
  }
  return out;
}

}  // namespace collido::stress::detail
