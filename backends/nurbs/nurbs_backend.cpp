// The seed method for NURBS surfaces as a Collidoscope plugin: distance queries between two
// surfaces, answered with a certified interval by core/nurbs's subdivision search.
#include <algorithm>
#include <memory>

#include <collido/nurbs/surface_distance.h>
#include <collido/plugin_export.h>

namespace collido::nurbs {
namespace {

constexpr const char* kVersion = "0.1.0";

class SurfaceModel final : public BackendModel {
 public:
  explicit SurfaceModel(NurbsSurface surface) : surface_(std::move(surface)) {}
  std::size_t memoryBytes() const override {
    return sizeof(*this) + surface_.control.capacity() * sizeof(Eigen::Vector4d) +
           (surface_.knots_u.capacity() + surface_.knots_v.capacity()) * sizeof(double);
  }
  const NurbsSurface& surface() const { return surface_; }

 private:
  NurbsSurface surface_;
};

// The diagonal of the box around both posed control nets: the scale of rounding and of the
// default tolerance.
double modelSize(const NurbsSurface& a, const NurbsSurface& b) {
  const Eigen::Matrix3Xd pa = a.controlPoints();
  const Eigen::Matrix3Xd pb = b.controlPoints();
  const Eigen::Vector3d lo = pa.rowwise().minCoeff().cwiseMin(pb.rowwise().minCoeff());
  const Eigen::Vector3d hi = pa.rowwise().maxCoeff().cwiseMax(pb.rowwise().maxCoeff());
  return (hi - lo).norm();
}

struct SeedSettings {
  PatchBound bound = PatchBound::kConvexHull;
  bool descent = true;
  std::size_t max_pairs = 2'000'000;
  double default_tolerance = 1e-10;  // of the model's size, when the request names none
};

class SeedBackend final : public SurfaceBackend {
 public:
  explicit SeedBackend(SeedSettings settings) : settings_(settings) {}

  Capabilities capabilities() const override {
    Capabilities caps;
    caps.shape_kinds = static_cast<std::uint32_t>(ShapeKind::kNurbsSurface);
    caps.queries = QueryKindSet(QueryKind::kDistance);
    caps.notes =
        "NURBS surfaces only. The minimum distance by best-first subdivision (knot insertion "
        "into 4 sub-patches), each sub-patch pair bounded below by its control nets (convex "
        "hulls by GJK, or boxes), the upper bound from patch corners (and a local descent); the "
        "answer is the upper end of a certified interval whose width is within the request's "
        "tolerance (or default_tolerance of the model's size when the request names none). "
        "Intersecting surfaces answer a distance within the tolerance of 0, not 0 itself.";
    return caps;
  }

  Result<std::unique_ptr<BackendModel>> buildSurface(const SurfaceView& view,
                                                     const BuildNeeds& /*needs*/) override {
    NurbsSurface surface = fromView(view);
    if (Status s = validate(surface); !s.ok()) return s;
    return std::unique_ptr<BackendModel>(std::make_unique<SurfaceModel>(std::move(surface)));
  }

  Status query(BackendModel& a, const Pose& pose_a, BackendModel& b, const Pose& pose_b,
               const QueryRequest& request, QueryResult& result) override {
    const NurbsSurface surface_a = transformed(static_cast<SurfaceModel&>(a).surface(), pose_a);
    const NurbsSurface surface_b = transformed(static_cast<SurfaceModel&>(b).surface(), pose_b);
    SurfaceDistanceOptions options;
    options.bound = settings_.bound;
    options.refine = settings_.descent;
    options.max_pairs = settings_.max_pairs;
    const double size = modelSize(surface_a, surface_b);
    // A relative tolerance is met by an absolute one of rel x (a lower bound of the distance):
    // a coarse first search finds that lower bound when the request is relative.
    double tolerance = request.abs_tolerance;
    if (request.rel_tolerance > 0.0) {
      SurfaceDistanceOptions coarse = options;
      coarse.tolerance = std::max(request.abs_tolerance, 1e-3 * size);
      const SurfaceDistance first = minimumDistance(surface_a, surface_b, coarse);
      tolerance = std::max(tolerance, request.rel_tolerance * first.lower);
    }
    if (tolerance <= 0.0) tolerance = settings_.default_tolerance * size;
    // Below the rounding the bounds allow for, the search could never stop.
    options.tolerance = std::max(tolerance, 1e-13 * size);
    const SurfaceDistance d = minimumDistance(surface_a, surface_b, options);
    if (!d.converged) {
      return {StatusCode::kEngineFailure,
              "nurbs: the search stopped at max_pairs (" + std::to_string(settings_.max_pairs) +
                  ") with the distance in [" + std::to_string(d.lower) + ", " +
                  std::to_string(d.upper) + "], wider than the tolerance " +
                  std::to_string(options.tolerance)};
    }
    DistanceResult& out = result.distance;
    out.distance = (d.point_b - d.point_a).norm();
    out.point_a = d.point_a;
    out.point_b = d.point_b;
    out.params_a = std::array<double, 2>{d.params_a.x(), d.params_a.y()};
    out.params_b = std::array<double, 2>{d.params_b.x(), d.params_b.y()};
    out.lower = std::min(d.lower, out.distance);
    out.upper = std::max(d.upper, out.distance);
    result.intersecting = out.distance == 0.0;
    result.counters.bv_tests = d.pairs_bounded;
    result.counters.counts_bv_tests = true;
    return {};
  }

 private:
  SeedSettings settings_;
};

Result<std::unique_ptr<Backend>> create(const std::string& variant, BackendOptions& options) {
  SeedSettings settings;
  settings.bound = variant == "nurbs:box" ? PatchBound::kBox : PatchBound::kConvexHull;
  Result<bool> descent = options.getBool("descent", true);
  if (!descent.ok()) return descent.status();
  Result<std::int64_t> max_pairs = options.getInt("max_pairs", 2'000'000, 16, 1'000'000'000);
  if (!max_pairs.ok()) return max_pairs.status();
  Result<double> default_tolerance = options.getDouble("default_tolerance", 1e-10, 1e-13, 1.0);
  if (!default_tolerance.ok()) return default_tolerance.status();
  settings.descent = descent.value();
  settings.max_pairs = static_cast<std::size_t>(max_pairs.value());
  settings.default_tolerance = default_tolerance.value();
  return std::unique_ptr<Backend>(std::make_unique<SeedBackend>(settings));
}

const PluginInfo& describe() {
  static const std::string options_text =
      "; options descent (default true: a local descent improves the upper bound; false: the "
      "seed as published, corners only), max_pairs (default 2000000: patch pairs bounded "
      "before giving up), default_tolerance (default 1e-10: of the model's size, when the "
      "request names no tolerance)";
  static const PluginInfo info{
      "nurbs",
      kVersion,
      "Collidoscope NURBS seed method",
      kVersion,
      {{"nurbs:hull",
        "NURBS surface distance by subdivision with convex-hull (GJK) lower bounds" + options_text},
       {"nurbs:box",
        "NURBS surface distance by subdivision with axis-aligned box lower bounds (the seed's "
        "baseline)" +
            options_text}},
      &create};
  return info;
}

}  // namespace
}  // namespace collido::nurbs

COLLIDO_DEFINE_PLUGIN(nurbs, collido::nurbs::describe)
