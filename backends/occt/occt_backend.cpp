// OpenCASCADE as a comparator for the minimum distance between NURBS surfaces: each surface
// becomes a Geom_BSplineSurface (and a face on it); distance queries go to
// BRepExtrema_DistShapeShape (occt:brep_extrema) or GeomAPI_ExtremaSurfaceSurface
// (occt:extrema_surface). Neither certifies its answer; the runner measures it against ours.
#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <GeomAPI_ExtremaSurfaceSurface.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Precision.hxx>
#include <Standard_Failure.hxx>
#include <Standard_Version.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopLoc_Location.hxx>
#include <TopoDS_Face.hxx>
#include <gp_Trsf.hxx>

#include <collido/plugin_export.h>

namespace collido::occt {
namespace {

constexpr const char* kVersion = "0.1.0";

// A knot vector as OpenCASCADE wants it: distinct values and their multiplicities.
struct DistinctKnots {
  std::vector<double> values;
  std::vector<int> multiplicities;
};

DistinctKnots distinct(const Eigen::Map<const Eigen::VectorXd>& knots) {
  DistinctKnots out;
  for (Eigen::Index i = 0; i < knots.size(); ++i) {
    if (out.values.empty() || knots[i] != out.values.back()) {
      out.values.push_back(knots[i]);
      out.multiplicities.push_back(1);
    } else {
      ++out.multiplicities.back();
    }
  }
  return out;
}

Handle(Geom_BSplineSurface) toOcct(const SurfaceView& view) {
  TColgp_Array2OfPnt poles(1, view.count_u, 1, view.count_v);
  TColStd_Array2OfReal weights(1, view.count_u, 1, view.count_v);
  for (int i = 0; i < view.count_u; ++i) {
    for (int j = 0; j < view.count_v; ++j) {
      const Eigen::Vector4d c = view.control.col(static_cast<Eigen::Index>(i) * view.count_v + j);
      poles.SetValue(i + 1, j + 1, gp_Pnt(c.x() / c.w(), c.y() / c.w(), c.z() / c.w()));
      weights.SetValue(i + 1, j + 1, c.w());
    }
  }
  const DistinctKnots u = distinct(view.knots_u);
  const DistinctKnots v = distinct(view.knots_v);
  TColStd_Array1OfReal u_knots(1, static_cast<int>(u.values.size()));
  TColStd_Array1OfInteger u_mults(1, static_cast<int>(u.values.size()));
  for (std::size_t k = 0; k < u.values.size(); ++k) {
    u_knots.SetValue(static_cast<int>(k) + 1, u.values[k]);
    u_mults.SetValue(static_cast<int>(k) + 1, u.multiplicities[k]);
  }
  TColStd_Array1OfReal v_knots(1, static_cast<int>(v.values.size()));
  TColStd_Array1OfInteger v_mults(1, static_cast<int>(v.values.size()));
  for (std::size_t k = 0; k < v.values.size(); ++k) {
    v_knots.SetValue(static_cast<int>(k) + 1, v.values[k]);
    v_mults.SetValue(static_cast<int>(k) + 1, v.multiplicities[k]);
  }
  return new Geom_BSplineSurface(poles, weights, u_knots, v_knots, u_mults, v_mults, view.degree_u,
                                 view.degree_v);
}

gp_Trsf toTrsf(const Pose& pose) {
  const Eigen::Matrix3d& r = pose.linear();
  const Eigen::Vector3d& t = pose.translation();
  gp_Trsf trsf;
  trsf.SetValues(r(0, 0), r(0, 1), r(0, 2), t.x(), r(1, 0), r(1, 1), r(1, 2), t.y(), r(2, 0),
                 r(2, 1), r(2, 2), t.z());
  return trsf;
}

Eigen::Vector3d toEigen(const gp_Pnt& p) {
  return {p.X(), p.Y(), p.Z()};
}

class OcctModel final : public BackendModel {
 public:
  OcctModel(Handle(Geom_BSplineSurface) surface, TopoDS_Face face, std::size_t poles)
      : surface_(std::move(surface)), face_(std::move(face)), poles_(poles) {}
  // OpenCASCADE does not report its memory; the surface's arrays are the bulk of it.
  std::size_t memoryBytes() const override { return sizeof(*this) + poles_ * 4 * sizeof(double); }
  const Handle(Geom_BSplineSurface) & surface() const { return surface_; }
  const TopoDS_Face& face() const { return face_; }

 private:
  Handle(Geom_BSplineSurface) surface_;
  TopoDS_Face face_;
  std::size_t poles_;
};

enum class Method { kBRepExtrema, kExtremaSurface };

class OcctBackend final : public SurfaceBackend {
 public:
  explicit OcctBackend(Method method) : method_(method) {}

  Capabilities capabilities() const override {
    Capabilities caps;
    caps.shape_kinds = static_cast<std::uint32_t>(ShapeKind::kNurbsSurface);
    caps.queries = QueryKindSet(QueryKind::kDistance);
    caps.notes =
        method_ == Method::kBRepExtrema
            ? "NURBS surfaces only, through OpenCASCADE's BRepExtrema_DistShapeShape on faces "
              "(vertices, edges and the face interior): no certified bound; the request's "
              "absolute tolerance is its deflection (default Precision::Confusion(), 1e-7)."
            : "NURBS surfaces only, through OpenCASCADE's GeomAPI_ExtremaSurfaceSurface: "
              "stationary points of the distance in the surfaces' interiors, so minima on patch "
              "edges can be missed; no certified bound; fails when it finds no extremum.";
    return caps;
  }

  Result<std::unique_ptr<BackendModel>> buildSurface(const SurfaceView& view,
                                                     const BuildNeeds& /*needs*/) override {
    try {
      Handle(Geom_BSplineSurface) surface = toOcct(view);
      BRepBuilderAPI_MakeFace make(surface, Precision::Confusion());
      if (!make.IsDone()) return Status(StatusCode::kEngineFailure, "occt: no face on surface");
      return std::unique_ptr<BackendModel>(std::make_unique<OcctModel>(
          surface, make.Face(), static_cast<std::size_t>(view.control.cols())));
    } catch (const Standard_Failure& e) {
      return Status(
          StatusCode::kEngineFailure,
          std::string("occt: build: ") + e.DynamicType()->Name() + ": " + e.GetMessageString());
    }
  }

  Status query(BackendModel& a, const Pose& pose_a, BackendModel& b, const Pose& pose_b,
               const QueryRequest& request, QueryResult& result) override {
    const auto& model_a = static_cast<OcctModel&>(a);
    const auto& model_b = static_cast<OcctModel&>(b);
    try {
      return method_ == Method::kBRepExtrema
                 ? brepExtrema(model_a, pose_a, model_b, pose_b, request, result)
                 : extremaSurface(model_a, pose_a, model_b, pose_b, result);
    } catch (const Standard_Failure& e) {
      return {StatusCode::kEngineFailure,
              std::string("occt: ") + e.DynamicType()->Name() + ": " + e.GetMessageString()};
    }
  }

 private:
  static Status brepExtrema(const OcctModel& a, const Pose& pose_a, const OcctModel& b,
                            const Pose& pose_b, const QueryRequest& request, QueryResult& result) {
    const TopoDS_Shape face_a = a.face().Moved(TopLoc_Location(toTrsf(pose_a)));
    const TopoDS_Shape face_b = b.face().Moved(TopLoc_Location(toTrsf(pose_b)));
    const double deflection =
        request.abs_tolerance > 0.0 ? request.abs_tolerance : Precision::Confusion();
    BRepExtrema_DistShapeShape extrema(face_a, face_b, deflection);
    if (!extrema.IsDone() || extrema.NbSolution() < 1) {
      return {StatusCode::kEngineFailure, "occt: BRepExtrema_DistShapeShape found no solution"};
    }
    DistanceResult& d = result.distance;
    d.point_a = toEigen(extrema.PointOnShape1(1));
    d.point_b = toEigen(extrema.PointOnShape2(1));
    d.distance = (d.point_b - d.point_a).norm();
    if (extrema.SupportTypeShape1(1) == BRepExtrema_IsInFace &&
        extrema.SupportTypeShape2(1) == BRepExtrema_IsInFace) {
      std::array<double, 2> pa{};
      std::array<double, 2> pb{};
      extrema.ParOnFaceS1(1, pa[0], pa[1]);
      extrema.ParOnFaceS2(1, pb[0], pb[1]);
      d.params_a = pa;
      d.params_b = pb;
    }
    result.intersecting = d.distance == 0.0;
    return {};
  }

  static Status extremaSurface(const OcctModel& a, const Pose& pose_a, const OcctModel& b,
                               const Pose& pose_b, QueryResult& result) {
    const Handle(Geom_Surface) surface_a =
        Handle(Geom_Surface)::DownCast(a.surface()->Transformed(toTrsf(pose_a)));
    const Handle(Geom_Surface) surface_b =
        Handle(Geom_Surface)::DownCast(b.surface()->Transformed(toTrsf(pose_b)));
    GeomAPI_ExtremaSurfaceSurface extrema(surface_a, surface_b);
    if (extrema.NbExtrema() < 1) {
      return {StatusCode::kEngineFailure, "occt: GeomAPI_ExtremaSurfaceSurface found no extremum"};
    }
    gp_Pnt pa;
    gp_Pnt pb;
    extrema.NearestPoints(pa, pb);
    std::array<double, 2> ua{};
    std::array<double, 2> ub{};
    extrema.LowerDistanceParameters(ua[0], ua[1], ub[0], ub[1]);
    DistanceResult& d = result.distance;
    d.point_a = toEigen(pa);
    d.point_b = toEigen(pb);
    d.distance = (d.point_b - d.point_a).norm();
    d.params_a = ua;
    d.params_b = ub;
    result.intersecting = d.distance == 0.0;
    return {};
  }

  Method method_;
};

Result<std::unique_ptr<Backend>> create(const std::string& variant, BackendOptions& /*options*/) {
  return std::unique_ptr<Backend>(std::make_unique<OcctBackend>(
      variant == "occt:extrema_surface" ? Method::kExtremaSurface : Method::kBRepExtrema));
}

const PluginInfo& describe() {
  static const PluginInfo info{
      "occt",
      kVersion,
      "OpenCASCADE",
      OCC_VERSION_COMPLETE,
      {{"occt:brep_extrema",
        "NURBS surface distance by OpenCASCADE's BRepExtrema_DistShapeShape on faces"},
       {"occt:extrema_surface",
        "NURBS surface distance by OpenCASCADE's GeomAPI_ExtremaSurfaceSurface (interior "
        "extrema)"}},
      &create};
  return info;
}

}  // namespace
}  // namespace collido::occt

COLLIDO_DEFINE_PLUGIN(occt, collido::occt::describe)
