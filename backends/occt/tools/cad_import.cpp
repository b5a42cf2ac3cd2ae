// collido_cad_import: the faces of a STEP or IGES file as NURBS surfaces in Collidoscope's surface
// file format (scenes/README.md), through OpenCASCADE: each face's surface, moved by the face's
// location, restricted to the face's parameter rectangle and converted to a B-spline
// (GeomConvert; planes, cylinders, spheres, tori, offsets... become rational B-splines).
// Trimming curves are not kept: a face trimmed by other than its parameter rectangle is imported
// as the rectangle, which the report says.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <string>
#include <vector>

#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <GeomConvert.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <IGESControl_Reader.hxx>
#include <STEPControl_Reader.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TopExp_Explorer.hxx>
#include <TopLoc_Location.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>
#include <XSControl_Reader.hxx>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

namespace {

struct Arguments {
  std::string input;
  std::string output;
  std::vector<int> faces;  // empty: all
};

std::string lowerExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

// Reads the file's shape with STEP's or IGES's reader (both XSControl_Reader); the error names
// the file and what went wrong.
bool readShape(const std::string& path, TopoDS_Shape& shape, std::string& error) {
  const std::string ext = lowerExtension(path);
  if (!std::filesystem::exists(path)) {
    error = path + ": file not found";
    return false;
  }
  const bool step = ext == ".step" || ext == ".stp";
  if (!step && ext != ".iges" && ext != ".igs") {
    error = path + ": extension '" + ext + "' is not .step, .stp, .iges or .igs";
    return false;
  }
  STEPControl_Reader step_reader;
  IGESControl_Reader iges_reader;
  XSControl_Reader& reader = step ? static_cast<XSControl_Reader&>(step_reader) : iges_reader;
  const std::string format = step ? "STEP" : "IGES";
  if (reader.ReadFile(path.c_str()) != IFSelect_RetDone) {
    error = path + ": not a readable " + format + " file";
    return false;
  }
  if (reader.TransferRoots() == 0) {
    error = path + ": " + format + " file has no transferable shape";
    return false;
  }
  shape = reader.OneShape();
  if (shape.IsNull()) {
    error = path + ": no shape in the file";
    return false;
  }
  return true;
}

std::vector<double> knotSequence(const TColStd_Array1OfReal& knots) {
  std::vector<double> out;
  for (int i = knots.Lower(); i <= knots.Upper(); ++i)
    out.push_back(knots.Value(i));
  return out;
}

// One face as a surface-file entry, or an error.
bool faceToJson(const TopoDS_Face& face, const std::string& name, nlohmann::json& out,
                std::string& note) {
  TopLoc_Location location;
  Handle(Geom_Surface) surface = BRep_Tool::Surface(face, location);
  if (surface.IsNull()) {
    note = "no underlying surface";
    return false;
  }
  double u0 = 0.0;
  double u1 = 0.0;
  double v0 = 0.0;
  double v1 = 0.0;
  BRepTools::UVBounds(face, u0, u1, v0, v1);
  if (!(u1 > u0 && v1 > v0)) {
    note = "empty parameter rectangle";
    return false;
  }
  if (!location.IsIdentity()) {
    surface = Handle(Geom_Surface)::DownCast(surface->Transformed(location.Transformation()));
  }
  const std::string type = surface->DynamicType()->Name();
  Handle(Geom_RectangularTrimmedSurface) trimmed =
      new Geom_RectangularTrimmedSurface(surface, u0, u1, v0, v1);
  Handle(Geom_BSplineSurface) spline = GeomConvert::SurfaceToBSplineSurface(trimmed);
  // Collidoscope's surfaces are clamped: a periodic spline is opened, and segmenting to the
  // domain makes the end knots' multiplicity degree + 1.
  if (spline->IsUPeriodic()) spline->SetUNotPeriodic();
  if (spline->IsVPeriodic()) spline->SetVNotPeriodic();
  double a0 = 0.0;
  double a1 = 0.0;
  double b0 = 0.0;
  double b1 = 0.0;
  spline->Bounds(a0, a1, b0, b1);
  spline->Segment(a0, a1, b0, b1);
  TColStd_Array1OfReal knots_u(1, spline->NbUPoles() + spline->UDegree() + 1);
  TColStd_Array1OfReal knots_v(1, spline->NbVPoles() + spline->VDegree() + 1);
  spline->UKnotSequence(knots_u);
  spline->VKnotSequence(knots_v);
  nlohmann::json control = nlohmann::json::array();
  for (int i = 1; i <= spline->NbUPoles(); ++i) {
    nlohmann::json row = nlohmann::json::array();
    for (int j = 1; j <= spline->NbVPoles(); ++j) {
      const gp_Pnt p = spline->Pole(i, j);
      const double w = spline->Weight(i, j);
      if (w == 1.0) {
        row.push_back({p.X(), p.Y(), p.Z()});
      } else {
        row.push_back({p.X(), p.Y(), p.Z(), w});
      }
    }
    control.push_back(row);
  }
  out = {{"name", name},
         {"degree_u", spline->UDegree()},
         {"degree_v", spline->VDegree()},
         {"knots_u", knotSequence(knots_u)},
         {"knots_v", knotSequence(knots_v)},
         {"control", control}};
  note = type + " -> degree " + std::to_string(spline->UDegree()) + " x " +
         std::to_string(spline->VDegree()) + ", " + std::to_string(spline->NbUPoles()) + " x " +
         std::to_string(spline->NbVPoles()) + " control points" +
         (spline->IsURational() || spline->IsVRational() ? ", rational" : "");
  return true;
}

int run(const Arguments& args) {
  TopoDS_Shape shape;
  std::string error;
  if (!readShape(args.input, shape, error)) {
    std::cerr << "error: " << error << "\n";
    return 2;
  }
  const std::set<int> wanted(args.faces.begin(), args.faces.end());
  const std::string stem = std::filesystem::path(args.input).stem().string();
  nlohmann::json surfaces = nlohmann::json::array();
  int index = 0;
  int failed = 0;
  for (TopExp_Explorer it(shape, TopAbs_FACE); it.More(); it.Next(), ++index) {
    if (!wanted.empty() && wanted.count(index) == 0) continue;
    const std::string name = stem + "_face" + std::to_string(index);
    nlohmann::json entry;
    std::string note;
    bool ok = false;
    try {
      ok = faceToJson(TopoDS::Face(it.Current()), name, entry, note);
    } catch (const Standard_Failure& e) {
      note = std::string(e.DynamicType()->Name()) + ": " + e.GetMessageString();
    }
    std::cout << "face " << index << ": " << (ok ? name + ", " : "skipped, ") << note
              << "; the face's parameter rectangle (trimming curves are not kept)\n";
    if (ok) {
      surfaces.push_back(entry);
    } else {
      ++failed;
    }
  }
  for (int f : wanted) {
    if (f < 0 || f >= index) {
      std::cerr << "error: " << args.input << ": --faces: no face " << f << " (the file has "
                << index << ")\n";
      return 2;
    }
  }
  if (surfaces.empty()) {
    std::cerr << "error: " << args.input << ": no face could be converted\n";
    return 1;
  }
  const nlohmann::json file = {
      {"comment", "Imported from " + std::filesystem::path(args.input).filename().string() +
                      " by collido_cad_import (OpenCASCADE): each face's surface over its "
                      "parameter rectangle, as a B-spline; trimming curves are not kept."},
      {"surfaces", surfaces}};
  std::ofstream out(args.output);
  out << file.dump(1) << "\n";
  if (!out) {
    std::cerr << "error: " << args.output << ": cannot write\n";
    return 2;
  }
  std::cout << surfaces.size() << " surface(s) written to " << args.output
            << (failed > 0 ? " (" + std::to_string(failed) + " face(s) skipped)" : "") << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app(
      "The faces of a STEP or IGES file as NURBS surfaces in Collidoscope's surface "
      "file format (collido surface-distance FILE), through OpenCASCADE");
  Arguments args;
  app.add_option("input", args.input, "a .step/.stp or .iges/.igs file")->required();
  app.add_option("-o,--output", args.output, "the surface file to write (JSON)")->required();
  app.add_option("--faces", args.faces, "face indices to import (default: all)")->delimiter(',');
  CLI11_PARSE(app, argc, argv);
  return run(args);
}
