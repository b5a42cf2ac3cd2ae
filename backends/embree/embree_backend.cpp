// Embree as a Collidoscope plugin: Embree's SIMD BVHs proposing triangle pairs, core's exact
// triangle test deciding them.
//   model   an Embree scene of one user geometry in the model frame: each triangle's box, from its
//           double corners rounded outward to floats, so that no box loses its triangle;
//   query   rtcCollide knows no transform, so the mesh with fewer triangles is mapped into the
//           other's frame (pose_static^-1 * pose_moving, in double) and a scene of it is built for
//           the query (low build quality, as Embree advises for per-frame rebuilds); that build
//           is part of the query's time. rtcCollide then reports the pairs of triangles whose
//           boxes overlap, and exact::trianglesIntersect (core's, the test the floor times)
//           decides each on the static mesh's corners and the moving one's mapped corners;
//   boolean the same, deciding no candidate after the first hit (rtcCollide cannot be stopped);
//   contacts the all-pairs answer, then per pair core's exact intersection set of the world
//           triangles (rationals, each point rounded once) and the contact frame, merged and
//           capped by core's manifold rules (docs/DESIGN.md, "Contact geometry"): Embree has
//           no contact generation of its own, so this is the reference construction on its pairs;
//   update  new corners, then a refit of the model's scene (RTC_BUILD_QUALITY_REFIT).
// The device runs one thread unless the option threads=N asks for more. Embree's device errors
// become errors naming the backend and Embree's message.
#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include <embree3/rtcore.h>

#include <collido/oracle/contact_manifold.h>
#include <collido/oracle/contact_reference.h>
#include <collido/oracle/double_triangle_test.h>
#include <collido/oracle/exact_oracle.h>
#include <collido/plugin_export.h>

namespace collido::embree_backend {
namespace {

/// An Embree device with its last error and the bytes it holds (Embree's memory monitor).
class Device {
 public:
  explicit Device(int threads) {
    const std::string config = "threads=" + std::to_string(threads);
    device_ = rtcNewDevice(config.c_str());
    if (device_ == nullptr) {
      throw std::runtime_error("Embree could not create a device (" +
                               errorName(rtcGetDeviceError(nullptr)) + ")");
    }
    rtcSetDeviceErrorFunction(device_, &Device::onError, this);
    rtcSetDeviceMemoryMonitorFunction(device_, &Device::onMemory, this);
  }
  ~Device() { rtcReleaseDevice(device_); }
  Device(const Device&) = delete;
  Device& operator=(const Device&) = delete;

  RTCDevice get() const { return device_; }
  long long bytes() const { return bytes_.load(); }

  /// Throws the device's last error, if any, with `step`.
  void check(const char* step) {
    if (rtcGetDeviceError(device_) == RTC_ERROR_NONE) return;
    std::string message;
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      message.swap(message_);
    }
    throw std::runtime_error(std::string("Embree failed in ") + step + ": " + message);
  }

 private:
  static std::string errorName(RTCError error) {
    switch (error) {
      case RTC_ERROR_NONE:
        return "no error";
      case RTC_ERROR_INVALID_ARGUMENT:
        return "invalid argument";
      case RTC_ERROR_INVALID_OPERATION:
        return "invalid operation";
      case RTC_ERROR_OUT_OF_MEMORY:
        return "out of memory";
      case RTC_ERROR_UNSUPPORTED_CPU:
        return "unsupported CPU";
      case RTC_ERROR_CANCELLED:
        return "cancelled";
      default:
        return "unknown error";
    }
  }
  static void onError(void* self, RTCError error, const char* text) {
    auto& device = *static_cast<Device*>(self);
    const std::lock_guard<std::mutex> lock(device.mutex_);
    device.message_ = errorName(error) + (text != nullptr ? std::string(", ") + text : "");
  }
  static bool onMemory(void* self, ssize_t bytes, bool /*post*/) {
    static_cast<Device*>(self)->bytes_ += static_cast<long long>(bytes);
    return true;
  }

  RTCDevice device_ = nullptr;
  std::atomic<long long> bytes_{0};
  std::mutex mutex_;
  std::string message_;
};

/// Triangles with corners in some frame, as one user geometry's primitives.
struct Corners {
  const Eigen::Matrix3Xd* vertices = nullptr;
  const Eigen::Matrix3Xi* triangles = nullptr;
  Eigen::Vector3d corner(Eigen::Index t, int k) const { return vertices->col((*triangles)(k, t)); }
};

float roundDown(double value) {
  const auto f = static_cast<float>(value);
  return static_cast<double>(f) > value ? std::nextafter(f, -std::numeric_limits<float>::infinity())
                                        : f;
}

float roundUp(double value) {
  const auto f = static_cast<float>(value);
  return static_cast<double>(f) < value ? std::nextafter(f, std::numeric_limits<float>::infinity())
                                        : f;
}

void triangleBounds(const RTCBoundsFunctionArguments* args) {
  const auto& corners = *static_cast<const Corners*>(args->geometryUserPtr);
  const auto t = static_cast<Eigen::Index>(args->primID);
  Eigen::Vector3d lower = corners.corner(t, 0);
  Eigen::Vector3d upper = lower;
  for (int k = 1; k < 3; ++k) {
    lower = lower.cwiseMin(corners.corner(t, k));
    upper = upper.cwiseMax(corners.corner(t, k));
  }
  RTCBounds& b = *args->bounds_o;
  b.lower_x = roundDown(lower.x());
  b.lower_y = roundDown(lower.y());
  b.lower_z = roundDown(lower.z());
  b.upper_x = roundUp(upper.x());
  b.upper_y = roundUp(upper.y());
  b.upper_z = roundUp(upper.z());
}

/// An Embree scene of one user geometry over `corners`, committed.
class Scene {
 public:
  Scene(Device& device, const Corners* corners, RTCBuildQuality quality, bool dynamic)
      : device_(device), scene_(rtcNewScene(device.get())) {
    device.check("rtcNewScene");
    rtcSetSceneBuildQuality(
        scene_, quality == RTC_BUILD_QUALITY_REFIT ? RTC_BUILD_QUALITY_MEDIUM : quality);
    if (dynamic) rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_DYNAMIC);
    geometry_ = rtcNewGeometry(device.get(), RTC_GEOMETRY_TYPE_USER);
    device.check("rtcNewGeometry");
    rtcSetGeometryUserPrimitiveCount(geometry_, static_cast<unsigned>(corners->triangles->cols()));
    rtcSetGeometryUserData(geometry_, const_cast<Corners*>(corners));
    rtcSetGeometryBoundsFunction(geometry_, &triangleBounds, nullptr);
    rtcSetGeometryBuildQuality(geometry_, quality);
    rtcCommitGeometry(geometry_);
    rtcAttachGeometry(scene_, geometry_);
    device.check("rtcAttachGeometry");
    rtcCommitScene(scene_);
    device.check("rtcCommitScene");
  }
  ~Scene() {
    rtcReleaseGeometry(geometry_);
    rtcReleaseScene(scene_);
  }
  Scene(const Scene&) = delete;
  Scene& operator=(const Scene&) = delete;

  RTCScene get() const { return scene_; }
  /// After the corners moved: the geometry's boxes anew, and the scene's BVH refit or rebuilt
  /// as the geometry's build quality says.
  void recommit() {
    rtcCommitGeometry(geometry_);
    rtcCommitScene(scene_);
    device_.check("rtcCommitScene (update)");
  }

 private:
  Device& device_;
  RTCScene scene_;
  RTCGeometry geometry_ = nullptr;
};

class EmbreeModel final : public BackendModel {
 public:
  EmbreeModel(Device& device, const MeshView& mesh, bool deforms)
      : vertices_(mesh.vertices), triangles_(mesh.triangles) {
    corners_.vertices = &vertices_;
    corners_.triangles = &triangles_;
    const long long before = device.bytes();
    scene_ = std::make_unique<Scene>(
        device, &corners_, deforms ? RTC_BUILD_QUALITY_REFIT : RTC_BUILD_QUALITY_MEDIUM, deforms);
    embree_bytes_ = std::max(0LL, device.bytes() - before);
  }

  void update(const Eigen::Ref<const Eigen::Matrix3Xd>& positions) {
    vertices_ = positions;
    scene_->recommit();
  }

  const Eigen::Matrix3Xd& vertices() const { return vertices_; }
  const Eigen::Matrix3Xi& triangles() const { return triangles_; }
  const Corners& corners() const { return corners_; }
  RTCScene scene() const { return scene_->get(); }
  Eigen::Index triangleCount() const { return triangles_.cols(); }

  std::size_t memoryBytes() const override {
    return static_cast<std::size_t>(embree_bytes_) +
           static_cast<std::size_t>(vertices_.size()) * sizeof(double) +
           static_cast<std::size_t>(triangles_.size()) * sizeof(int) + sizeof(*this);
  }

 private:
  Eigen::Matrix3Xd vertices_;
  Eigen::Matrix3Xi triangles_;
  Corners corners_;
  std::unique_ptr<Scene> scene_;
  long long embree_bytes_ = 0;
};

/// What the collision callback needs and fills.
struct CollisionJob {
  const Corners* fixed = nullptr;   // scene 0: the static mesh, in its own frame
  const Corners* moving = nullptr;  // scene 1: the other mesh, mapped into that frame
  bool swapped = false;             // the static mesh is B
  bool first_only = false;          // boolean: stop deciding after the first hit
  std::mutex mutex;
  std::vector<TrianglePair> pairs;
  std::atomic<bool> found{false};
};

void onCollisions(void* user, RTCCollision* collisions, unsigned count) {
  auto& job = *static_cast<CollisionJob*>(user);
  std::vector<TrianglePair> hits;
  for (unsigned i = 0; i < count; ++i) {
    if (job.first_only && job.found.load(std::memory_order_relaxed)) return;
    const auto s = static_cast<Eigen::Index>(collisions[i].primID0);
    const auto m = static_cast<Eigen::Index>(collisions[i].primID1);
    if (!exact::trianglesIntersect(job.fixed->corner(s, 0), job.fixed->corner(s, 1),
                                   job.fixed->corner(s, 2), job.moving->corner(m, 0),
                                   job.moving->corner(m, 1), job.moving->corner(m, 2))) {
      continue;
    }
    job.found = true;
    const auto fixed = static_cast<std::int32_t>(s);
    const auto moving = static_cast<std::int32_t>(m);
    hits.push_back(job.swapped ? TrianglePair{moving, fixed} : TrianglePair{fixed, moving});
  }
  if (hits.empty()) return;
  const std::lock_guard<std::mutex> lock(job.mutex);
  job.pairs.insert(job.pairs.end(), hits.begin(), hits.end());
}

class EmbreeBackend final : public Backend {
 public:
  EmbreeBackend(int threads, double contact_merge_radius)
      : device_(threads), threads_(threads), contact_merge_radius_(contact_merge_radius) {}

  Capabilities capabilities() const override {
    Capabilities caps;
    caps.shape_kinds = static_cast<std::uint32_t>(ShapeKind::kTriangleMesh);
    caps.queries = QueryKindSet(QueryKind::kBoolean) | QueryKind::kAllPairs | QueryKind::kContacts;
    caps.update = true;
    caps.notes =
        "Embree " COLLIDO_EMBREE_VERSION
        " rtcCollide on user-geometry BVHs; the smaller mesh is mapped into the other's frame "
        "(in double) and its BVH built per query, inside the query's time; candidates decided "
        "by core's exact triangle test; contacts from each pair's exact intersection set "
        "(rationals), merged within contact_merge_radius, capped by keeping the deepest and the "
        "farthest; update refits. " +
        std::to_string(threads_) + " thread(s). No work counters.";
    return caps;
  }

  Result<std::unique_ptr<BackendModel>> build(const MeshView& mesh, const BuildNeeds& needs,
                                              const StateSibling& /*sibling*/) override {
    return std::unique_ptr<BackendModel>(
        std::make_unique<EmbreeModel>(device_, mesh, needs.deforms));
  }

  Status update(BackendModel& model, const Eigen::Ref<const Eigen::Matrix3Xd>& positions,
                UpdateCounters& /*counters*/) override {
    static_cast<EmbreeModel&>(model).update(positions);
    return {};
  }

  Status query(BackendModel& a_model, const Pose& pose_a, BackendModel& b_model, const Pose& pose_b,
               const QueryRequest& request, QueryResult& result) override {
    const auto& a = static_cast<const EmbreeModel&>(a_model);
    const auto& b = static_cast<const EmbreeModel&>(b_model);
    // The smaller mesh moves: its BVH is the one rebuilt per query.
    const bool swapped = b.triangleCount() > a.triangleCount();
    const EmbreeModel& fixed = swapped ? b : a;
    const EmbreeModel& moving = swapped ? a : b;
    const Pose to_fixed =
        (swapped ? pose_b : pose_a).inverse(Eigen::Isometry) * (swapped ? pose_a : pose_b);
    moved_ = to_fixed * moving.vertices();
    Corners moved{&moved_, &moving.triangles()};
    const Scene moved_scene(device_, &moved, RTC_BUILD_QUALITY_LOW, true);

    CollisionJob job;
    job.fixed = &fixed.corners();
    job.moving = &moved;
    job.swapped = swapped;
    job.first_only = request.kind == QueryKind::kBoolean;
    rtcCollide(fixed.scene(), moved_scene.get(), &onCollisions, &job);
    device_.check("rtcCollide");

    result.intersecting = job.found;
    if (request.kind == QueryKind::kBoolean) return {};
    std::sort(job.pairs.begin(), job.pairs.end(), [](const TrianglePair& x, const TrianglePair& y) {
      return x.a != y.a ? x.a < y.a : x.b < y.b;
    });
    if (request.kind == QueryKind::kContacts) {
      contactsOf(a, pose_a, b, pose_b, job.pairs, request.max_contacts, result);
      return {};
    }
    result.pairs = std::move(job.pairs);
    if (request.max_pairs != 0 && result.pairs.size() > request.max_pairs) {
      result.pairs.resize(request.max_pairs);
      result.truncated = true;
    }
    return {};
  }

 private:
  // One contact per pair whose world triangles meet exactly: a pair that only the mapped
  // corners' rounding made meet has an empty set and gives none.
  void contactsOf(const EmbreeModel& a, const Pose& pose_a, const EmbreeModel& b,
                  const Pose& pose_b, const std::vector<TrianglePair>& pairs,
                  std::uint64_t max_contacts, QueryResult& result) const {
    const auto cornersOf = [](const EmbreeModel& model, std::int32_t t) {
      return std::array<Eigen::Vector3d, 3>{
          model.corners().corner(t, 0), model.corners().corner(t, 1), model.corners().corner(t, 2)};
    };
    const auto posed = [](const Pose& pose, const std::array<Eigen::Vector3d, 3>& t) {
      return std::array<Eigen::Vector3d, 3>{pose * t[0], pose * t[1], pose * t[2]};
    };
    result.contacts.clear();
    result.contacts.reserve(pairs.size());
    for (const TrianglePair& pair : pairs) {
      const std::array<Eigen::Vector3d, 3> model_a = cornersOf(a, pair.a);
      const std::array<Eigen::Vector3d, 3> model_b = cornersOf(b, pair.b);
      const ExactIntersection set = exactPosedIntersection(model_a, pose_a, model_b, pose_b);
      if (set.shape == ExactIntersection::Shape::kEmpty) continue;
      const ContactFrame frame = contactFrame(posed(pose_a, model_a), posed(pose_b, model_b));
      result.contacts.push_back(
          Contact{intersectionMean(set), frame.normal, frame.depth, pair.a, pair.b});
    }
    result.intersecting = !result.contacts.empty();
    mergeNearbyContacts(contact_merge_radius_, result.contacts);
    if (max_contacts != 0 && result.contacts.size() > max_contacts) {
      keepSpreadContacts(static_cast<std::size_t>(max_contacts), result.contacts);
      result.truncated = true;
    }
  }

  Device device_;
  int threads_;
  double contact_merge_radius_;
  Eigen::Matrix3Xd moved_;
};

Result<std::unique_ptr<Backend>> create(const std::string& variant, BackendOptions& options) {
  // Embree's device takes any thread count; 256 bounds a typo, not a machine.
  const Result<std::int64_t> threads = options.getInt("threads", 1, 1, 256);
  if (!threads.ok()) return threads.status();
  const Result<double> merge_radius = options.getDouble("contact_merge_radius", 0.0, 0.0, 1e300);
  if (!merge_radius.ok()) return merge_radius.status();
  if (variant == "embree") {
    return std::unique_ptr<Backend>(
        std::make_unique<EmbreeBackend>(static_cast<int>(threads.value()), merge_radius.value()));
  }
  return Status(StatusCode::kInvalidArgument, "embree has no variant '" + variant + "'");
}

const PluginInfo& describe() {
  static const PluginInfo info{
      "embree",
      "0.1.0",
      "Embree",
      COLLIDO_EMBREE_VERSION,
      {{"embree",
        "Embree's rtcCollide on SIMD BVHs, candidates decided by the exact test; options threads "
        "(default 1: Embree's device threads), contact_merge_radius (default 0: contacts closer "
        "than this merge into the deepest; 0 merges coincident ones only)"}},
      &create};
  return info;
}

}  // namespace
}  // namespace collido::embree_backend

COLLIDO_DEFINE_PLUGIN(embree, collido::embree_backend::describe)
