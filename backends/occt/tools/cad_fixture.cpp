// Writes the CAD files the importer's tests read: two unit spheres with centres 3 apart (their
// distance is 1) as STEP and as IGES, made with OpenCASCADE's primitives, so the test input is
// produced by a CAD kernel's own writers rather than by us.
// Usage: collido_cad_fixture OUT_DIR
#include <filesystem>
#include <iostream>
#include <string>

#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRep_Builder.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <IGESControl_Controller.hxx>
#include <IGESControl_Writer.hxx>
#include <STEPControl_Writer.hxx>
#include <TopoDS_Compound.hxx>
#include <gp_Pnt.hxx>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: collido_cad_fixture OUT_DIR\n";
    return 2;
  }
  const std::filesystem::path dir = argv[1];
  std::filesystem::create_directories(dir);
  TopoDS_Compound both;
  BRep_Builder builder;
  builder.MakeCompound(both);
  builder.Add(both, BRepPrimAPI_MakeSphere(gp_Pnt(0, 0, 0), 1.0).Shape());
  builder.Add(both, BRepPrimAPI_MakeSphere(gp_Pnt(3, 0, 0), 1.0).Shape());

  STEPControl_Writer step;
  if (step.Transfer(both, STEPControl_AsIs) != IFSelect_RetDone ||
      step.Write((dir / "two_spheres.step").string().c_str()) != IFSelect_RetDone) {
    std::cerr << "error: cannot write " << (dir / "two_spheres.step") << "\n";
    return 1;
  }
  IGESControl_Controller::Init();
  IGESControl_Writer iges("MM", 1);  // BRep mode: faces with their surfaces
  iges.AddShape(both);
  iges.ComputeModel();
  if (!iges.Write((dir / "two_spheres.iges").string().c_str())) {
    std::cerr << "error: cannot write " << (dir / "two_spheres.iges") << "\n";
    return 1;
  }
  return 0;
}
