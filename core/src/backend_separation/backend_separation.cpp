#include <collido/constraints/backend_separation.h>

namespace collido {

Result<std::unique_ptr<BackendSeparation>> BackendSeparation::create(
    BackendInstance& backend, const std::vector<std::shared_ptr<const TriangleMesh>>& meshes) {
  if (!backend.capabilities().queries.contains(QueryKind::kDistance)) {
    return Status(StatusCode::kUnsupported,
                  backend.name() + " does not answer distance queries, which clearances need");
  }
  std::unique_ptr<BackendSeparation> separation(new BackendSeparation(backend));
  BuildNeeds needs;
  needs.queries = QueryKind::kDistance;
  for (const auto& mesh : meshes) {
    if (mesh == nullptr) {
      separation->models_.push_back(0);
      continue;
    }
    Result<ModelHandle> model = backend.build(mesh->view(), needs);
    if (!model.ok()) return model.status();
    separation->models_.push_back(model.value());
  }
  return separation;
}

BackendSeparation::~BackendSeparation() {
  for (ModelHandle model : models_) {
    if (model != 0) (void)backend_.release(model);
  }
}

Result<constraints::Separation> BackendSeparation::measure(int body_a, const Pose& pose_a,
                                                           int body_b, const Pose& pose_b) {
  const auto count = static_cast<int>(models_.size());
  if (body_a < 0 || body_a >= count || body_b < 0 || body_b >= count) {
    return Status(StatusCode::kInvalidArgument, "a clearance names a body beyond the meshes given");
  }
  const ModelHandle a = models_[body_a];
  const ModelHandle b = models_[body_b];
  if (a == 0 || b == 0) {
    return Status(StatusCode::kInvalidArgument, "a clearance names a body without a mesh");
  }
  QueryRequest request;
  request.kind = QueryKind::kDistance;
  if (Status status = backend_.query(a, pose_a, b, pose_b, request, result_); !status.ok()) {
    return status;
  }
  constraints::Separation separation;
  separation.distance = result_.distance.distance;
  separation.point_a = result_.distance.point_a;
  separation.point_b = result_.distance.point_b;
  return separation;
}

}  // namespace collido
