// Example plugin: the simplest honest backend. Each query poses both meshes in the world frame,
// sweeps their triangles' boxes along x, and tests each overlapping pair with a floating-point
// separating-axis test (two face normals, nine edge cross products, and the six in-plane edge
// normals for coplanar pairs). It has no precomputed structure, so update() just copies the new
// positions. Run the conformance kit on it:
//   collido conformance build/release/examples/libbrute_force.so
#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <vector>

#include <collido/plugin_export.h>

namespace example {
namespace {

using collido::QueryKind;
using Vec = Eigen::Vector3d;
using Triangle = std::array<Vec, 3>;

class MeshModel final : public collido::BackendModel {
 public:
  explicit MeshModel(const collido::MeshView& mesh)
      : vertices(mesh.vertices), triangles(mesh.triangles) {}
  std::size_t memoryBytes() const override {
    return sizeof(*this) + static_cast<std::size_t>(vertices.size()) * sizeof(double) +
           static_cast<std::size_t>(triangles.size()) * sizeof(int);
  }
  Eigen::Matrix3Xd vertices;
  Eigen::Matrix3Xi triangles;
};

struct Box {
  Vec lo;
  Vec hi;
  int index;
};

std::vector<Triangle> posed(const MeshModel& m, const collido::Pose& pose) {
  std::vector<Triangle> out(static_cast<std::size_t>(m.triangles.cols()));
  for (Eigen::Index t = 0; t < m.triangles.cols(); ++t) {
    for (int k = 0; k < 3; ++k)
      out[static_cast<std::size_t>(t)][k] = pose * m.vertices.col(m.triangles(k, t));
  }
  return out;
}

std::vector<Box> boxes(const std::vector<Triangle>& triangles) {
  std::vector<Box> out;
  out.reserve(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const Triangle& tri = triangles[t];
    out.push_back(Box{tri[0].cwiseMin(tri[1]).cwiseMin(tri[2]),
                      tri[0].cwiseMax(tri[1]).cwiseMax(tri[2]), static_cast<int>(t)});
  }
  std::sort(out.begin(), out.end(), [](const Box& a, const Box& b) { return a.lo.x() < b.lo.x(); });
  return out;
}

bool separatedAlong(const Vec& axis, const Triangle& a, const Triangle& b) {
  if (axis.squaredNorm() == 0.0) return false;  // not an axis
  double a_lo = axis.dot(a[0]), a_hi = a_lo, b_lo = axis.dot(b[0]), b_hi = b_lo;
  for (int k = 1; k < 3; ++k) {
    a_lo = std::min(a_lo, axis.dot(a[k]));
    a_hi = std::max(a_hi, axis.dot(a[k]));
    b_lo = std::min(b_lo, axis.dot(b[k]));
    b_hi = std::max(b_hi, axis.dot(b[k]));
  }
  return a_hi < b_lo || b_hi < a_lo;
}

bool trianglesOverlap(const Triangle& a, const Triangle& b) {
  const Vec na = (a[1] - a[0]).cross(a[2] - a[0]);
  const Vec nb = (b[1] - b[0]).cross(b[2] - b[0]);
  if (separatedAlong(na, a, b) || separatedAlong(nb, a, b)) return false;
  for (int i = 0; i < 3; ++i) {
    const Vec ea = a[(i + 1) % 3] - a[i];
    const Vec eb = b[(i + 1) % 3] - b[i];
    for (int j = 0; j < 3; ++j) {
      if (separatedAlong(ea.cross(b[(j + 1) % 3] - b[j]), a, b)) return false;
    }
    // In-plane edge normals: they separate coplanar pairs, where the cross products vanish.
    if (separatedAlong(na.cross(ea), a, b) || separatedAlong(nb.cross(eb), a, b)) return false;
  }
  return true;
}

class BruteForceBackend final : public collido::Backend {
 public:
  collido::Capabilities capabilities() const override {
    collido::Capabilities caps;
    caps.shape_kinds = static_cast<std::uint32_t>(collido::ShapeKind::kTriangleMesh);
    caps.queries = collido::QueryKindSet(QueryKind::kBoolean) | QueryKind::kAllPairs;
    caps.update = true;
    caps.counts_primitive_tests = true;
    caps.notes = "example: sweep and prune over world-frame boxes, floating-point triangle SAT";
    return caps;
  }

  collido::Result<std::unique_ptr<collido::BackendModel>> build(
      const collido::MeshView& mesh, const collido::BuildNeeds& /*needs*/,
      const collido::StateSibling& /*sibling*/) override {
    return std::unique_ptr<collido::BackendModel>(std::make_unique<MeshModel>(mesh));
  }

  collido::Status update(collido::BackendModel& model,
                         const Eigen::Ref<const Eigen::Matrix3Xd>& positions,
                         collido::UpdateCounters& /*counters*/) override {
    static_cast<MeshModel&>(model).vertices = positions;
    return {};
  }

  collido::Status query(collido::BackendModel& a, const collido::Pose& pose_a,
                        collido::BackendModel& b, const collido::Pose& pose_b,
                        const collido::QueryRequest& request,
                        collido::QueryResult& result) override {
    const std::vector<Triangle> ta = posed(static_cast<MeshModel&>(a), pose_a);
    const std::vector<Triangle> tb = posed(static_cast<MeshModel&>(b), pose_b);
    const std::vector<Box> ba = boxes(ta);
    const std::vector<Box> bb = boxes(tb);
    result.counters.counts_primitive_tests = true;
    // Sweep along x over both lists merged by their lower ends; each side keeps the boxes that
    // are still open. A box entering is tested against the other side's open boxes.
    std::vector<const Box*> open_a;
    std::vector<const Box*> open_b;
    std::size_t i = 0;
    std::size_t j = 0;
    while (i < ba.size() || j < bb.size()) {
      const bool from_a = j == bb.size() || (i < ba.size() && ba[i].lo.x() <= bb[j].lo.x());
      const Box& entering = from_a ? ba[i++] : bb[j++];
      std::vector<const Box*>& others = from_a ? open_b : open_a;
      others.erase(std::remove_if(others.begin(), others.end(),
                                  [&](const Box* o) { return o->hi.x() < entering.lo.x(); }),
                   others.end());
      for (const Box* other : others) {
        const Box& x = from_a ? entering : *other;
        const Box& y = from_a ? *other : entering;
        if ((x.hi.array() < y.lo.array()).any() || (y.hi.array() < x.lo.array()).any()) continue;
        ++result.counters.primitive_tests;
        if (!trianglesOverlap(ta[static_cast<std::size_t>(x.index)],
                              tb[static_cast<std::size_t>(y.index)])) {
          continue;
        }
        result.intersecting = true;
        if (request.kind == QueryKind::kAllPairs && request.max_pairs != 0 &&
            result.pairs.size() >= request.max_pairs) {
          result.truncated = true;
          return {};
        }
        result.pairs.push_back(collido::TrianglePair{x.index, y.index});
        if (request.kind == QueryKind::kBoolean) return {};
      }
      (from_a ? open_a : open_b).push_back(&entering);
    }
    return {};
  }
};

collido::Result<std::unique_ptr<collido::Backend>> create(const std::string& /*variant*/,
                                                          collido::BackendOptions& /*options*/) {
  return std::unique_ptr<collido::Backend>(std::make_unique<BruteForceBackend>());
}

const collido::PluginInfo& describe() {
  static const collido::PluginInfo info{
      "example_brute_force",
      "1.0.0",
      "none (example)",
      "1.0.0",
      {{"example:brute_force", "example plugin: sweep and prune, floating-point triangle test"}},
      &create};
  return info;
}

}  // namespace
}  // namespace example

COLLIDO_EXPORT_PLUGIN(example_brute_force, example::describe)
