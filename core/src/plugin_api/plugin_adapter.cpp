// The plugin side of the C boundary: turns a collido::Backend into a CollidoPluginTable.
//
// Everything generic lives here so that every plugin checks its input the same way: handles
// (index + generation, as in Box2D's ids), sizes, finiteness, rigid poses, and that requests and
// needs are within the instance's capabilities. Exceptions never cross: each entry point catches
// and turns them into a status with a message.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <exception>
#include <iterator>
#include <limits>
#include <memory>
#include <new>
#include <string>
#include <tuple>
#include <type_traits>
#include <vector>

#include <collido/motion.h>
#include <collido/plugin_export.h>

struct CollidoInstance {
  struct Slot {
    std::unique_ptr<collido::BackendModel> model;
    std::uint32_t generation = 1;
    std::uint32_t vertex_count = 0;
    std::uint64_t triangle_list_hash = 0;  // to check a state sibling's topology
    collido::BuildNeeds needs;
  };

  std::string label;  // plugin:variant, for messages
  std::unique_ptr<collido::Backend> backend;
  collido::Capabilities capabilities;
  std::vector<Slot> slots;
  std::vector<std::uint32_t> free_slots;
  collido::QueryResult scratch;
  std::vector<CollidoContact> contacts;
};

namespace collido {

Result<std::unique_ptr<BackendModel>> Backend::buildSurface(const SurfaceView& /*surface*/,
                                                            const BuildNeeds& /*needs*/) {
  return Status{StatusCode::kUnsupported, "this backend does not build NURBS surfaces"};
}

Result<std::unique_ptr<BackendModel>> SurfaceBackend::build(const MeshView& /*mesh*/,
                                                            const BuildNeeds& /*needs*/,
                                                            const StateSibling& /*sibling*/) {
  return Status{StatusCode::kUnsupported,
                "this backend builds NURBS surfaces, not triangle meshes"};
}

Status SurfaceBackend::update(BackendModel& /*model*/,
                              const Eigen::Ref<const Eigen::Matrix3Xd>& /*positions*/,
                              UpdateCounters& /*counters*/) {
  return {StatusCode::kUnsupported, "NURBS surfaces do not deform"};
}

}  // namespace collido

namespace collido::detail {
namespace {

static_assert(sizeof(TrianglePair) == sizeof(CollidoTrianglePair) &&
                  std::is_standard_layout_v<TrianglePair>,
              "TrianglePair is passed across the boundary without copying");

std::int32_t fail(CollidoMessage* error, StatusCode code, const std::string& text) {
  if (error != nullptr) {
    const std::size_t n = std::min(text.size(), sizeof(error->text) - 1);
    std::memcpy(error->text, text.data(), n);
    error->text[n] = '\0';
  }
  return static_cast<std::int32_t>(code);
}

std::int32_t report(CollidoMessage* error, const Status& status) {
  if (status.ok()) return static_cast<std::int32_t>(StatusCode::kOk);
  return fail(error, status.code(), status.message());
}

// Runs `body` and converts anything it throws into a status; no exception leaves the plugin.
template <typename Body>
std::int32_t guarded(const std::string& label, CollidoMessage* error, Body&& body) {
  try {
    return body();
  } catch (const std::bad_alloc&) {
    return fail(error, StatusCode::kOutOfMemory, label + ": out of memory");
  } catch (const std::exception& e) {
    return fail(error, StatusCode::kEngineFailure, label + ": engine error: " + e.what());
  } catch (...) {
    return fail(error, StatusCode::kInternal, label + ": unknown exception");
  }
}

CollidoInstance::Slot* findSlot(CollidoInstance* instance, CollidoModelHandle handle) {
  const std::uint64_t index_plus_one = handle & 0xffffffffu;
  const auto generation = static_cast<std::uint32_t>(handle >> 32);
  if (index_plus_one == 0 || index_plus_one > instance->slots.size()) return nullptr;
  CollidoInstance::Slot& slot = instance->slots[index_plus_one - 1];
  if (!slot.model || slot.generation != generation) return nullptr;
  return &slot;
}

std::string handleText(CollidoModelHandle handle) {
  return "model handle " + std::to_string(handle & 0xffffffffu) + "/" +
         std::to_string(handle >> 32);
}

// One bit, and one of the table's: the table lists the kinds in the order of their bits
// (checked where queryKindInfo is defined), so this needs no scan on every call.
bool isSingleQueryKind(std::uint32_t kind) {
  return kind != 0 && (kind & (kind - 1)) == 0 && kind < (1u << std::size(kQueryKinds));
}

bool isTolerance(double value) {
  return std::isfinite(value) && value >= 0.0;
}

// A distance answer must be a distance: finite, >= 0, its points finite, its interval ordered.
Status checkDistance(const DistanceResult& d) {
  if (!std::isfinite(d.distance) || d.distance < 0.0) {
    return {StatusCode::kInternal, "distance query answered " + std::to_string(d.distance)};
  }
  if (!d.point_a.allFinite() || !d.point_b.allFinite()) {
    return {StatusCode::kInternal, "distance query answered non-finite closest points"};
  }
  if (d.lower.has_value() != d.upper.has_value() ||
      (d.lower && !(*d.lower >= 0.0 && *d.lower <= *d.upper))) {
    return {StatusCode::kInternal, "distance query answered an empty or half interval"};
  }
  return {};
}

// Poses must be rigid: a backend may invert them by transposition.
Status toPose(const CollidoPose* in, const char* which, Pose& out) {
  if (in == nullptr) return {StatusCode::kInvalidArgument, std::string(which) + ": null pose"};
  Eigen::Matrix3d rotation;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c)
      rotation(r, c) = in->rotation[3 * r + c];
  }
  const Eigen::Vector3d translation(in->translation[0], in->translation[1], in->translation[2]);
  Pose pose = Pose::Identity();
  pose.linear() = rotation;
  pose.translation() = translation;
  if (Status s = checkRigidPose(pose, which); !s.ok()) return s;
  out = pose;
  return {};
}

// A step's end poses and bracket width, for the kinds asked over a step.
Status readStep(const CollidoQueryRequest& in, QueryRequest& out) {
  StepEnd& step = out.step.emplace();
  if (Status s = toPose(&in.end_a, "end pose of A", step.pose_a); !s.ok()) return s;
  if (Status s = toPose(&in.end_b, "end pose of B", step.pose_b); !s.ok()) return s;
  if (!(std::isfinite(in.bracket_width) && in.bracket_width > 0.0)) {
    return {StatusCode::kInvalidArgument,
            "the bracket width must be finite and > 0, not " + std::to_string(in.bracket_width)};
  }
  step.bracket_width = in.bracket_width;
  return {};
}

// A first contact's answer must be a bracket within the step, no wider than asked.
Status checkFirstContact(const FirstContactResult& c, double width) {
  if (!c.touches) {
    if (c.t_lo >= 0.0 && c.t_lo <= 1.0) return {};
    return {StatusCode::kInternal, "first contact answered no contact after t_lo = " +
                                       std::to_string(c.t_lo) + ", not within [0, 1]"};
  }
  if (!(c.t_lo >= 0.0 && c.t_lo <= c.t_hi && c.t_hi <= 1.0)) {
    return {StatusCode::kInternal, "first contact answered the bracket [" + std::to_string(c.t_lo) +
                                       ", " + std::to_string(c.t_hi) + "], not within [0, 1]"};
  }
  if (c.t_hi - c.t_lo > width) {
    return {StatusCode::kInternal, "first contact answered a bracket " +
                                       std::to_string(c.t_hi - c.t_lo) + " wide, wider than the " +
                                       std::to_string(width) + " asked"};
  }
  return {};
}

void copyFirstContact(const FirstContactResult& c, CollidoFirstContact& out) {
  out.touches = c.touches ? 1u : 0u;
  out.t_lo = c.t_lo;
  out.t_hi = c.t_hi;
  out.triangle_a = c.triangle_a;
  out.triangle_b = c.triangle_b;
}

std::int32_t capabilitiesEntry(CollidoInstance* instance, CollidoCapabilities* out,
                               CollidoMessage* error) {
  if (instance == nullptr || out == nullptr) {
    return fail(error, StatusCode::kInvalidArgument, "capabilities: null argument");
  }
  const Capabilities& caps = instance->capabilities;
  *out = CollidoCapabilities{};
  out->shape_kinds = caps.shape_kinds;
  out->query_kinds = caps.queries.bits();
  out->features =
      (caps.update ? std::uint32_t{COLLIDO_FEATURE_UPDATE} : 0u) |
      (caps.counts_bv_tests ? std::uint32_t{COLLIDO_FEATURE_COUNTS_BV_TESTS} : 0u) |
      (caps.counts_primitive_tests ? std::uint32_t{COLLIDO_FEATURE_COUNTS_PRIMITIVE_TESTS} : 0u) |
      (caps.counts_update_work ? std::uint32_t{COLLIDO_FEATURE_COUNTS_UPDATE_WORK} : 0u);
  out->max_contacts = caps.max_contacts;
  out->notes = caps.notes.c_str();
  return COLLIDO_STATUS_OK;
}

Status checkMesh(const CollidoTriangleMeshView& mesh) {
  if (mesh.triangle_count == 0 || mesh.vertex_count == 0) {
    return {StatusCode::kInvalidArgument, "mesh is empty (" + std::to_string(mesh.vertex_count) +
                                              " vertices, " + std::to_string(mesh.triangle_count) +
                                              " triangles)"};
  }
  if (mesh.positions == nullptr || mesh.triangles == nullptr) {
    return {StatusCode::kInvalidArgument, "mesh arrays are null"};
  }
  for (std::uint64_t i = 0; i < 3ull * mesh.vertex_count; ++i) {
    if (!std::isfinite(mesh.positions[i])) {
      return {StatusCode::kInvalidArgument,
              "vertex " + std::to_string(i / 3) + " has a non-finite coordinate"};
    }
  }
  for (std::uint64_t i = 0; i < 3ull * mesh.triangle_count; ++i) {
    const std::int32_t v = mesh.triangles[i];
    if (v < 0 || static_cast<std::uint32_t>(v) >= mesh.vertex_count) {
      return {StatusCode::kInvalidArgument, "triangle " + std::to_string(i / 3) +
                                                " references vertex " + std::to_string(v) + " of " +
                                                std::to_string(mesh.vertex_count)};
    }
  }
  return {};
}

// FNV-1a over the triangle indices and the vertex count: a state sibling must match both.
std::uint64_t triangleListHash(const CollidoTriangleMeshView& mesh) {
  std::uint64_t hash = 14695981039346656037ull ^ mesh.vertex_count;
  for (std::uint64_t i = 0; i < 3ull * mesh.triangle_count; ++i) {
    hash ^= static_cast<std::uint32_t>(mesh.triangles[i]);
    hash *= 1099511628211ull;
  }
  return hash;
}

// Sizes, finiteness and positive weights: what every backend reading the net relies on. Knot
// semantics (clamping, multiplicities) are left to the backend, which knows what it needs.
Status checkSurface(const CollidoNurbsSurfaceView& s) {
  if (s.degree_u < 1 || s.degree_v < 1 || s.degree_u > 64 || s.degree_v > 64) {
    return {StatusCode::kInvalidArgument, "surface degrees " + std::to_string(s.degree_u) + " x " +
                                              std::to_string(s.degree_v) +
                                              " (each must be 1 to 64)"};
  }
  if (s.count_u <= s.degree_u || s.count_v <= s.degree_v || s.count_u > (1u << 16) ||
      s.count_v > (1u << 16)) {
    return {StatusCode::kInvalidArgument,
            "surface has " + std::to_string(s.count_u) + " x " + std::to_string(s.count_v) +
                " control points for degrees " + std::to_string(s.degree_u) + " x " +
                std::to_string(s.degree_v) + " (need more than the degree, at most 65536)"};
  }
  if (s.knots_u == nullptr || s.knots_v == nullptr || s.control == nullptr) {
    return {StatusCode::kInvalidArgument, "surface arrays are null"};
  }
  for (const auto& [knots, count, name] :
       {std::tuple{s.knots_u, s.count_u + s.degree_u + 1, "knots_u"},
        std::tuple{s.knots_v, s.count_v + s.degree_v + 1, "knots_v"}}) {
    for (std::uint32_t i = 0; i < count; ++i) {
      if (!std::isfinite(knots[i]) || (i > 0 && knots[i] < knots[i - 1])) {
        return {StatusCode::kInvalidArgument, std::string(name) + "[" + std::to_string(i) +
                                                  "] is not finite or not non-decreasing"};
      }
    }
  }
  const std::uint64_t points = std::uint64_t{s.count_u} * s.count_v;
  for (std::uint64_t k = 0; k < points; ++k) {
    const double* c = s.control + 4 * k;
    if (!(std::isfinite(c[0]) && std::isfinite(c[1]) && std::isfinite(c[2]) &&
          std::isfinite(c[3]) && c[3] > 0.0)) {
      return {StatusCode::kInvalidArgument, "control point (" + std::to_string(k / s.count_v) +
                                                ", " + std::to_string(k % s.count_v) +
                                                ") is not finite or its weight is not > 0"};
    }
  }
  return {};
}

std::int32_t storeModel(CollidoInstance* instance, std::unique_ptr<BackendModel> model,
                        std::uint32_t vertex_count, std::uint64_t hash, const BuildNeeds& needs,
                        CollidoModelHandle* out, CollidoMessage* error) {
  std::uint32_t index;
  if (!instance->free_slots.empty()) {
    index = instance->free_slots.back();
    instance->free_slots.pop_back();
  } else {
    if (instance->slots.size() >= std::numeric_limits<std::uint32_t>::max() - 1) {
      return fail(error, StatusCode::kOutOfMemory, instance->label + ": too many models");
    }
    index = static_cast<std::uint32_t>(instance->slots.size());
    instance->slots.emplace_back();
  }
  CollidoInstance::Slot& slot = instance->slots[index];
  slot.model = std::move(model);
  slot.vertex_count = vertex_count;
  slot.triangle_list_hash = hash;
  slot.needs = needs;
  *out = (static_cast<std::uint64_t>(slot.generation) << 32) | (index + 1ull);
  return COLLIDO_STATUS_OK;
}

std::int32_t buildSurfaceModel(CollidoInstance* instance, const CollidoNurbsSurfaceView& surface,
                               const BuildNeeds& needs, CollidoModelHandle* out,
                               CollidoMessage* error) {
  const std::string& label = instance->label;
  if (!instance->capabilities.buildsShape(ShapeKind::kNurbsSurface)) {
    return fail(error, StatusCode::kUnsupported, label + ": does not build NURBS surfaces");
  }
  if (needs.deforms) {
    return fail(error, StatusCode::kUnsupported, label + ": NURBS surfaces cannot deform");
  }
  if (Status s = checkSurface(surface); !s.ok()) {
    return fail(error, s.code(), label + ": build: " + s.message());
  }
  const auto p = static_cast<Eigen::Index>(surface.degree_u);
  const auto q = static_cast<Eigen::Index>(surface.degree_v);
  const auto nu = static_cast<Eigen::Index>(surface.count_u);
  const auto nv = static_cast<Eigen::Index>(surface.count_v);
  const SurfaceView view{static_cast<int>(p),
                         static_cast<int>(q),
                         static_cast<int>(nu),
                         static_cast<int>(nv),
                         Eigen::Map<const Eigen::VectorXd>(surface.knots_u, nu + p + 1),
                         Eigen::Map<const Eigen::VectorXd>(surface.knots_v, nv + q + 1),
                         Eigen::Map<const Eigen::Matrix4Xd>(surface.control, 4, nu * nv)};
  Result<std::unique_ptr<BackendModel>> built = instance->backend->buildSurface(view, needs);
  if (!built.ok()) return report(error, built.status());
  if (!built.value()) return fail(error, StatusCode::kInternal, label + ": build returned null");
  return storeModel(instance, std::move(built).value(), 0, 0, needs, out, error);
}

std::int32_t buildEntry(CollidoInstance* instance, const CollidoShapeView* shape,
                        const CollidoBuildNeeds* needs, CollidoModelHandle* out,
                        CollidoMessage* error) {
  if (instance == nullptr || shape == nullptr || needs == nullptr || out == nullptr) {
    return fail(error, StatusCode::kInvalidArgument, "build: null argument");
  }
  const std::string& label = instance->label;
  return guarded(label, error, [&]() -> std::int32_t {
    const Capabilities& caps = instance->capabilities;
    const bool is_mesh = shape->kind == COLLIDO_SHAPE_TRIANGLE_MESH && shape->mesh != nullptr;
    const bool is_surface = shape->kind == COLLIDO_SHAPE_NURBS_SURFACE && shape->surface != nullptr;
    if (!is_mesh && !is_surface) {
      return fail(error, StatusCode::kInvalidArgument, label + ": build: unknown shape kind");
    }
    const QueryKindSet wanted(needs->query_kinds);
    if (!caps.queries.containsAll(wanted)) {
      return fail(error, StatusCode::kUnsupported,
                  label + ": the scene needs " + queryKindsText(wanted) +
                      " but the backend answers " + queryKindsText(caps.queries));
    }
    const bool deforms = (needs->flags & COLLIDO_NEED_DEFORMS) != 0;
    if (deforms && !caps.update) {
      return fail(error, StatusCode::kUnsupported, label + ": cannot update deforming models");
    }
    if (is_surface) {
      if (needs->state_of != 0) {
        return fail(error, StatusCode::kInvalidArgument,
                    label + ": build: state_of is for triangle meshes, not surfaces");
      }
      return buildSurfaceModel(instance, *shape->surface, BuildNeeds{wanted, deforms}, out, error);
    }
    if (!caps.buildsShape(ShapeKind::kTriangleMesh)) {
      return fail(error, StatusCode::kUnsupported, label + ": does not build triangle meshes");
    }
    const CollidoTriangleMeshView& mesh = *shape->mesh;
    if (Status s = checkMesh(mesh); !s.ok()) {
      return fail(error, s.code(), label + ": build: " + s.message());
    }
    const MeshView view{Eigen::Map<const Eigen::Matrix3Xd>(mesh.positions, 3, mesh.vertex_count),
                        Eigen::Map<const Eigen::Matrix3Xi>(mesh.triangles, 3, mesh.triangle_count)};
    const std::uint64_t hash = triangleListHash(mesh);
    StateSibling sibling;
    if (needs->state_of != 0) {
      const CollidoInstance::Slot* other = findSlot(instance, needs->state_of);
      if (other == nullptr) {
        return fail(
            error, StatusCode::kInvalidHandle,
            label + ": build: state_of " + handleText(needs->state_of) + " is not a live model");
      }
      if (other->triangle_list_hash != hash) {
        return fail(error, StatusCode::kInvalidArgument,
                    label + ": build: state_of " + handleText(needs->state_of) +
                        " was built from another triangle list or vertex count");
      }
      sibling.model = other->model.get();
    }
    BuildNeeds build_needs{wanted, deforms};
    // A host's linked kinds include the model's own; kinds the backend does not answer are
    // dropped, as a model is never asked them.
    if (needs->linked_query_kinds != 0) {
      build_needs.linked_queries =
          QueryKindSet((needs->linked_query_kinds | wanted.bits()) & caps.queries.bits());
    }
    Result<std::unique_ptr<BackendModel>> built =
        instance->backend->build(view, build_needs, sibling);
    if (!built.ok()) return report(error, built.status());
    if (!built.value()) return fail(error, StatusCode::kInternal, label + ": build returned null");
    return storeModel(instance, std::move(built).value(), mesh.vertex_count, hash, build_needs, out,
                      error);
  });
}

std::int32_t updateEntry(CollidoInstance* instance, CollidoModelHandle model,
                         const double* positions, std::uint32_t vertex_count,
                         CollidoUpdateCounters* out, CollidoMessage* error) {
  if (instance == nullptr || positions == nullptr || out == nullptr) {
    return fail(error, StatusCode::kInvalidArgument, "update: null argument");
  }
  const std::string& label = instance->label;
  return guarded(label, error, [&]() -> std::int32_t {
    CollidoInstance::Slot* slot = findSlot(instance, model);
    if (slot == nullptr) {
      return fail(error, StatusCode::kInvalidHandle,
                  label + ": update: " + handleText(model) + " is not a live model");
    }
    if (!slot->needs.deforms) {
      return fail(error, StatusCode::kInvalidArgument,
                  label + ": update: the model was built rigid (needs did not say it deforms)");
    }
    if (vertex_count != slot->vertex_count) {
      return fail(error, StatusCode::kInvalidArgument,
                  label + ": update: " + std::to_string(vertex_count) +
                      " positions for a model with " + std::to_string(slot->vertex_count) +
                      " vertices");
    }
    for (std::uint64_t i = 0; i < 3ull * vertex_count; ++i) {
      if (!std::isfinite(positions[i])) {
        return fail(
            error, StatusCode::kInvalidArgument,
            label + ": update: vertex " + std::to_string(i / 3) + " has a non-finite coordinate");
      }
    }
    const Eigen::Map<const Eigen::Matrix3Xd> view(positions, 3, vertex_count);
    UpdateCounters counters;
    const Status status = instance->backend->update(*slot->model, view, counters);
    *out = CollidoUpdateCounters{};
    if (status.ok() && counters.counted) {
      out->nodes_refit = counters.nodes_refit;
      out->rebuilds = counters.rebuilds;
      out->nodes_rebuilt = counters.nodes_rebuilt;
      out->counted = 1;
    }
    return report(error, status);
  });
}

std::int32_t queryEntry(CollidoInstance* instance, CollidoModelHandle a, const CollidoPose* pose_a,
                        CollidoModelHandle b, const CollidoPose* pose_b,
                        const CollidoQueryRequest* request, CollidoQueryResult* out,
                        CollidoMessage* error) {
  if (instance == nullptr || request == nullptr || out == nullptr) {
    return fail(error, StatusCode::kInvalidArgument, "query: null argument");
  }
  const std::string& label = instance->label;
  return guarded(label, error, [&]() -> std::int32_t {
    *out = CollidoQueryResult{};
    if (!isSingleQueryKind(request->kind)) {
      return fail(error, StatusCode::kInvalidArgument,
                  label + ": query: kind " + std::to_string(request->kind) + " is not one kind");
    }
    const auto kind = static_cast<QueryKind>(request->kind);
    const QueryKindInfo& info = queryKindInfo(kind);
    if (!instance->capabilities.queries.contains(kind)) {
      return fail(error, StatusCode::kUnsupported,
                  label + ": does not answer " + info.name + " queries");
    }
    CollidoInstance::Slot* slot_a = findSlot(instance, a);
    CollidoInstance::Slot* slot_b = findSlot(instance, b);
    for (auto [slot, handle] : {std::pair{slot_a, a}, std::pair{slot_b, b}}) {
      if (slot == nullptr) {
        return fail(error, StatusCode::kInvalidHandle,
                    label + ": query: " + handleText(handle) + " is not a live model");
      }
      if (!slot->needs.queries.contains(kind)) {
        return fail(error, StatusCode::kInvalidArgument,
                    label + ": query: " + handleText(handle) + " was built for " +
                        queryKindsText(slot->needs.queries) + ", not " + info.name);
      }
    }
    Pose world_a;
    Pose world_b;
    if (Status s = toPose(pose_a, "pose of A", world_a); !s.ok()) {
      return fail(error, s.code(), label + ": query: " + s.message());
    }
    if (Status s = toPose(pose_b, "pose of B", world_b); !s.ok()) {
      return fail(error, s.code(), label + ": query: " + s.message());
    }
    if (info.tolerances &&
        !(isTolerance(request->abs_tolerance) && isTolerance(request->rel_tolerance))) {
      return fail(error, StatusCode::kInvalidArgument,
                  label + ": query: distance tolerances must be finite and >= 0 (absolute " +
                      std::to_string(request->abs_tolerance) + ", relative " +
                      std::to_string(request->rel_tolerance) + ")");
    }
    QueryRequest req{kind, request->max_pairs, request->max_contacts, request->abs_tolerance,
                     request->rel_tolerance};
    if (info.over_a_step) {
      if (Status s = readStep(*request, req); !s.ok()) {
        return fail(error, s.code(), label + ": query: " + s.message());
      }
    }
    QueryResult& result = instance->scratch;
    result.clear();
    if (Status s =
            instance->backend->query(*slot_a->model, world_a, *slot_b->model, world_b, req, result);
        !s.ok()) {
      return report(error, s);
    }
    if (info.has(AnswerPart::kDistance)) {
      if (Status s = checkDistance(result.distance); !s.ok()) {
        return fail(error, s.code(), label + ": " + s.message());
      }
      const DistanceResult& d = result.distance;
      out->distance.distance = d.distance;
      for (int k = 0; k < 3; ++k) {
        out->distance.point_a[k] = d.point_a[k];
        out->distance.point_b[k] = d.point_b[k];
      }
      out->distance.triangle_a = d.triangle_a;
      out->distance.triangle_b = d.triangle_b;
      if (d.params_a && d.params_b) {
        out->distance.has_params = 1;
        for (int k = 0; k < 2; ++k) {
          out->distance.params_a[k] = (*d.params_a)[static_cast<std::size_t>(k)];
          out->distance.params_b[k] = (*d.params_b)[static_cast<std::size_t>(k)];
        }
      }
      out->distance.has_bounds = d.lower ? 1u : 0u;
      out->distance.lower = d.lower.value_or(0.0);
      out->distance.upper = d.upper.value_or(0.0);
    }
    if (info.has(AnswerPart::kFirstContact)) {
      if (Status s = checkFirstContact(result.first_contact, req.step->bracket_width); !s.ok()) {
        return fail(error, s.code(), label + ": " + s.message());
      }
      copyFirstContact(result.first_contact, out->first_contact);
    }
    out->intersecting = result.intersecting ? 1u : 0u;
    out->truncated = result.truncated ? 1u : 0u;
    out->pairs = reinterpret_cast<const CollidoTrianglePair*>(result.pairs.data());
    out->pair_count = result.pairs.size();
    instance->contacts.resize(result.contacts.size());
    for (std::size_t i = 0; i < result.contacts.size(); ++i) {
      const Contact& c = result.contacts[i];
      CollidoContact& d = instance->contacts[i];
      for (int k = 0; k < 3; ++k) {
        d.position[k] = c.position[k];
        d.normal[k] = c.normal[k];
      }
      d.depth = c.depth;
      d.triangle_a = c.triangle_a;
      d.triangle_b = c.triangle_b;
    }
    out->contacts = instance->contacts.data();
    out->contact_count = instance->contacts.size();
    out->counters.bv_tests = result.counters.bv_tests;
    out->counters.primitive_tests = result.counters.primitive_tests;
    out->counters.counted =
        (result.counters.counts_bv_tests ? std::uint32_t{COLLIDO_FEATURE_COUNTS_BV_TESTS} : 0u) |
        (result.counters.counts_primitive_tests
             ? std::uint32_t{COLLIDO_FEATURE_COUNTS_PRIMITIVE_TESTS}
             : 0u);
    return COLLIDO_STATUS_OK;
  });
}

std::int32_t memoryEntry(CollidoInstance* instance, CollidoModelHandle model, std::uint64_t* bytes,
                         CollidoMessage* error) {
  if (instance == nullptr || bytes == nullptr) {
    return fail(error, StatusCode::kInvalidArgument, "memory: null argument");
  }
  return guarded(instance->label, error, [&]() -> std::int32_t {
    CollidoInstance::Slot* slot = findSlot(instance, model);
    if (slot == nullptr) {
      return fail(error, StatusCode::kInvalidHandle,
                  instance->label + ": memory: " + handleText(model) + " is not a live model");
    }
    *bytes = slot->model->memoryBytes();
    return COLLIDO_STATUS_OK;
  });
}

std::int32_t releaseEntry(CollidoInstance* instance, CollidoModelHandle model,
                          CollidoMessage* error) {
  if (instance == nullptr) return fail(error, StatusCode::kInvalidArgument, "release: null");
  return guarded(instance->label, error, [&]() -> std::int32_t {
    CollidoInstance::Slot* slot = findSlot(instance, model);
    if (slot == nullptr) {
      return fail(error, StatusCode::kInvalidHandle,
                  instance->label + ": release: " + handleText(model) + " is not a live model");
    }
    slot->model.reset();
    ++slot->generation;  // so the released handle is stale from now on
    if (slot->generation == 0) slot->generation = 1;
    instance->free_slots.push_back(static_cast<std::uint32_t>(slot - instance->slots.data()));
    return COLLIDO_STATUS_OK;
  });
}

void destroyEntry(CollidoInstance* instance) {
  try {
    delete instance;
  } catch (...) {  // NOLINT(bugprone-empty-catch): a destructor that throws must not escape
  }
}

}  // namespace

std::int32_t createInstance(const PluginInfo& info, const char* variant,
                            const CollidoOption* options, std::uint32_t option_count,
                            CollidoInstance** out, CollidoMessage* error) {
  if (out == nullptr) return fail(error, StatusCode::kInvalidArgument, "create: null out");
  *out = nullptr;
  const std::string name = variant != nullptr && *variant != '\0' ? variant : info.name;
  return guarded(name, error, [&]() -> std::int32_t {
    const bool known = std::any_of(info.variants.begin(), info.variants.end(),
                                   [&](const VariantInfo& v) { return v.name == name; });
    if (!known) {
      return fail(error, StatusCode::kInvalidArgument,
                  "plugin " + info.name + " has no variant '" + name + "'");
    }
    BackendOptions parsed;
    for (std::uint32_t i = 0; i < option_count; ++i) {
      if (options == nullptr || options[i].key == nullptr || options[i].value == nullptr) {
        return fail(error, StatusCode::kInvalidArgument, name + ": null option");
      }
      parsed.set(options[i].key, options[i].value);
    }
    Result<std::unique_ptr<Backend>> backend = info.create(name, parsed);
    if (!backend.ok()) {
      // Option getters do not know the backend's name; the message must say whose option it is.
      const Status& s = backend.status();
      if (s.message().rfind(name + ":", 0) == 0) return report(error, s);
      return fail(error, s.code(), name + ": " + s.message());
    }
    if (Status s = parsed.rejectUnknown(name); !s.ok()) return report(error, s);
    auto instance = std::make_unique<CollidoInstance>();
    instance->label = name;
    instance->backend = std::move(backend).value();
    instance->capabilities = instance->backend->capabilities();
    *out = instance.release();
    return COLLIDO_STATUS_OK;
  });
}

PluginTableStorage::PluginTableStorage(const PluginInfo& info,
                                       decltype(CollidoPluginTable::create) create) {
  // `info` is the plugin's function-local static, so the strings outlive the table.
  for (const VariantInfo& v : info.variants) {
    variants.push_back(CollidoVariantInfo{v.name.c_str(), v.summary.c_str()});
  }
  table.abi_version = COLLIDO_PLUGIN_ABI_VERSION;
  table.struct_size = sizeof(CollidoPluginTable);
  table.plugin_name = info.name.c_str();
  table.plugin_version = info.version.c_str();
  table.engine_name = info.engine_name.c_str();
  table.engine_version = info.engine_version.c_str();
  table.variant_count = static_cast<std::uint32_t>(variants.size());
  table.variants = variants.data();
  table.create = create;
  table.destroy = &destroyEntry;
  table.capabilities = &capabilitiesEntry;
  table.build = &buildEntry;
  table.update = &updateEntry;
  table.query = &queryEntry;
  table.memory = &memoryEntry;
  table.release = &releaseEntry;
}

}  // namespace collido::detail
