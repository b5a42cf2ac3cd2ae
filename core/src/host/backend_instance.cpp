#include <collido/host/backend_instance.h>

#include <vector>

namespace collido {
namespace {

static_assert(sizeof(int) == sizeof(std::int32_t), "triangle indices cross the ABI as int32");

Status fromCode(std::int32_t code, const CollidoMessage& message, const std::string& label) {
  if (code == COLLIDO_STATUS_OK) return {};
  if (code < COLLIDO_STATUS_OK || code > COLLIDO_STATUS_INTERNAL) {
    return {StatusCode::kInternal, label + ": unknown status code " + std::to_string(code)};
  }
  std::string text = message.text;
  if (text.empty()) text = label + ": no reason given";
  return {static_cast<StatusCode>(code), text};
}

CollidoPose toCollidoPose(const Pose& pose) {
  CollidoPose out{};
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c)
      out.rotation[3 * r + c] = pose.linear()(r, c);
    out.translation[r] = pose.translation()[r];
  }
  return out;
}

}  // namespace

Result<std::unique_ptr<BackendInstance>> BackendInstance::create(
    const std::shared_ptr<PluginLibrary>& library, const std::string& variant,
    const std::map<std::string, std::string>& options) {
  if (!library->hasVariant(variant)) {
    return Status(StatusCode::kInvalidArgument,
                  "plugin " + library->path() + " has no variant '" + variant + "'");
  }
  std::vector<CollidoOption> c_options;
  c_options.reserve(options.size());
  for (const auto& [key, value] : options)
    c_options.push_back({key.c_str(), value.c_str()});
  CollidoMessage message{};
  CollidoInstance* raw = nullptr;
  const std::int32_t code =
      library->table().create(variant.c_str(), c_options.data(),
                              static_cast<std::uint32_t>(c_options.size()), &raw, &message);
  if (Status s = fromCode(code, message, variant); !s.ok()) return s;
  if (raw == nullptr) return Status(StatusCode::kInternal, variant + ": create returned null");
  std::unique_ptr<BackendInstance> instance(new BackendInstance(library, variant, raw));

  CollidoCapabilities caps{};
  message = CollidoMessage{};
  if (Status s = fromCode(library->table().capabilities(raw, &caps, &message), message, variant);
      !s.ok()) {
    return s;
  }
  Capabilities& out = instance->capabilities_;
  out.shape_kinds = caps.shape_kinds;
  out.queries = QueryKindSet(caps.query_kinds);
  out.update = (caps.features & COLLIDO_FEATURE_UPDATE) != 0;
  out.counts_bv_tests = (caps.features & COLLIDO_FEATURE_COUNTS_BV_TESTS) != 0;
  out.counts_primitive_tests = (caps.features & COLLIDO_FEATURE_COUNTS_PRIMITIVE_TESTS) != 0;
  out.counts_update_work = (caps.features & COLLIDO_FEATURE_COUNTS_UPDATE_WORK) != 0;
  out.max_contacts = caps.max_contacts;
  out.notes = caps.notes != nullptr ? caps.notes : "";
  return Result<std::unique_ptr<BackendInstance>>(std::move(instance));
}

BackendInstance::~BackendInstance() {
  if (instance_ != nullptr) library_->table().destroy(instance_);
}

Result<ModelHandle> BackendInstance::build(const MeshView& mesh, const BuildNeeds& needs,
                                           ModelHandle state_of) {
  CollidoTriangleMeshView c_mesh{};
  c_mesh.positions = mesh.vertices.data();
  c_mesh.vertex_count = static_cast<std::uint32_t>(mesh.vertices.cols());
  c_mesh.triangle_count = static_cast<std::uint32_t>(mesh.triangles.cols());
  c_mesh.triangles = mesh.triangles.data();
  CollidoShapeView shape{};
  shape.kind = COLLIDO_SHAPE_TRIANGLE_MESH;
  shape.mesh = &c_mesh;
  return buildShape(shape, needs, state_of);
}

Result<ModelHandle> BackendInstance::buildShape(const CollidoShapeView& shape,
                                                const BuildNeeds& needs, ModelHandle state_of) {
  CollidoBuildNeeds c_needs{};
  c_needs.query_kinds = needs.queries.bits();
  c_needs.flags = needs.deforms ? std::uint32_t{COLLIDO_NEED_DEFORMS} : 0u;
  c_needs.state_of = state_of;
  c_needs.linked_query_kinds = needs.linked_queries.bits();
  CollidoMessage message{};
  ModelHandle handle = 0;
  if (Status s = fromCode(library_->table().build(instance_, &shape, &c_needs, &handle, &message),
                          message, variant_);
      !s.ok()) {
    return s;
  }
  return handle;
}

Result<ModelHandle> BackendInstance::build(const SurfaceView& surface, const BuildNeeds& needs) {
  CollidoNurbsSurfaceView c_surface{};
  c_surface.degree_u = static_cast<std::uint32_t>(surface.degree_u);
  c_surface.degree_v = static_cast<std::uint32_t>(surface.degree_v);
  c_surface.count_u = static_cast<std::uint32_t>(surface.count_u);
  c_surface.count_v = static_cast<std::uint32_t>(surface.count_v);
  c_surface.knots_u = surface.knots_u.data();
  c_surface.knots_v = surface.knots_v.data();
  c_surface.control = surface.control.data();
  CollidoShapeView shape{};
  shape.kind = COLLIDO_SHAPE_NURBS_SURFACE;
  shape.surface = &c_surface;
  return buildShape(shape, needs, 0);
}

Status BackendInstance::update(ModelHandle model,
                               const Eigen::Ref<const Eigen::Matrix3Xd>& positions,
                               UpdateCounters* counters) {
  // The C side reads x y z per vertex; copy only when the view is not already laid out so.
  Eigen::Matrix3Xd packed;
  const double* data = positions.data();
  if (positions.outerStride() != 3) {
    packed = positions;
    data = packed.data();
  }
  CollidoMessage message{};
  CollidoUpdateCounters c_counters{};
  Status status = fromCode(
      library_->table().update(instance_, model, data, static_cast<std::uint32_t>(positions.cols()),
                               &c_counters, &message),
      message, variant_);
  if (counters != nullptr) {
    *counters = UpdateCounters{};
    if (status.ok() && c_counters.counted != 0) {
      counters->nodes_refit = c_counters.nodes_refit;
      counters->rebuilds = c_counters.rebuilds;
      counters->nodes_rebuilt = c_counters.nodes_rebuilt;
      counters->counted = true;
    }
  }
  return status;
}

Status BackendInstance::query(ModelHandle a, const Pose& pose_a, ModelHandle b, const Pose& pose_b,
                              const QueryRequest& request, QueryResult& result) {
  result.clear();
  const CollidoPose c_pose_a = toCollidoPose(pose_a);
  const CollidoPose c_pose_b = toCollidoPose(pose_b);
  CollidoQueryRequest c_request{};
  c_request.kind = static_cast<std::uint32_t>(request.kind);
  c_request.max_pairs = request.max_pairs;
  c_request.max_contacts = request.max_contacts;
  c_request.abs_tolerance = request.abs_tolerance;
  c_request.rel_tolerance = request.rel_tolerance;
  const QueryKindInfo& kind = queryKindInfo(request.kind);
  // Without a step, the end poses stay zero: the plugin refuses them (not a rotation) once it
  // has said whether it answers the kind at all.
  if (kind.over_a_step && request.step) {
    c_request.end_a = toCollidoPose(request.step->pose_a);
    c_request.end_b = toCollidoPose(request.step->pose_b);
    c_request.bracket_width = request.step->bracket_width;
  }
  CollidoQueryResult out{};
  CollidoMessage message{};
  if (Status s = fromCode(library_->table().query(instance_, a, &c_pose_a, b, &c_pose_b, &c_request,
                                                  &out, &message),
                          message, variant_);
      !s.ok()) {
    return s;
  }
  result.intersecting = out.intersecting != 0;
  result.truncated = out.truncated != 0;
  if (out.pair_count > 0 && out.pairs != nullptr) {
    result.pairs.resize(out.pair_count);
    for (std::uint64_t i = 0; i < out.pair_count; ++i) {
      result.pairs[i] = TrianglePair{out.pairs[i].a, out.pairs[i].b};
    }
  }
  if (out.contact_count > 0 && out.contacts != nullptr) {
    result.contacts.resize(out.contact_count);
    for (std::uint64_t i = 0; i < out.contact_count; ++i) {
      const CollidoContact& c = out.contacts[i];
      Contact& d = result.contacts[i];
      d.position = Eigen::Vector3d(c.position[0], c.position[1], c.position[2]);
      d.normal = Eigen::Vector3d(c.normal[0], c.normal[1], c.normal[2]);
      d.depth = c.depth;
      d.triangle_a = c.triangle_a;
      d.triangle_b = c.triangle_b;
    }
  }
  if (kind.has(AnswerPart::kFirstContact)) {
    const CollidoFirstContact& c = out.first_contact;
    result.first_contact = {c.touches != 0, c.t_lo, c.t_hi, c.triangle_a, c.triangle_b};
  }
  if (kind.has(AnswerPart::kDistance)) {
    const CollidoDistance& d = out.distance;
    result.distance.distance = d.distance;
    result.distance.point_a = Eigen::Vector3d(d.point_a[0], d.point_a[1], d.point_a[2]);
    result.distance.point_b = Eigen::Vector3d(d.point_b[0], d.point_b[1], d.point_b[2]);
    result.distance.triangle_a = d.triangle_a;
    result.distance.triangle_b = d.triangle_b;
    if (d.has_params != 0) {
      result.distance.params_a = std::array<double, 2>{d.params_a[0], d.params_a[1]};
      result.distance.params_b = std::array<double, 2>{d.params_b[0], d.params_b[1]};
    }
    if (d.has_bounds != 0) {
      result.distance.lower = d.lower;
      result.distance.upper = d.upper;
    }
  }
  result.counters.bv_tests = out.counters.bv_tests;
  result.counters.primitive_tests = out.counters.primitive_tests;
  result.counters.counts_bv_tests = (out.counters.counted & COLLIDO_FEATURE_COUNTS_BV_TESTS) != 0;
  result.counters.counts_primitive_tests =
      (out.counters.counted & COLLIDO_FEATURE_COUNTS_PRIMITIVE_TESTS) != 0;
  return {};
}

Result<std::uint64_t> BackendInstance::memory(ModelHandle model) {
  std::uint64_t bytes = 0;
  CollidoMessage message{};
  if (Status s =
          fromCode(library_->table().memory(instance_, model, &bytes, &message), message, variant_);
      !s.ok()) {
    return s;
  }
  return bytes;
}

Status BackendInstance::release(ModelHandle model) {
  CollidoMessage message{};
  return fromCode(library_->table().release(instance_, model, &message), message, variant_);
}

}  // namespace collido
