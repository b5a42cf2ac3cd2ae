// Writes a bundled robot cell's sources into a folder: a 6-axis arm with a parallel gripper in
// URDF, its links' collision meshes and the cell's, and a pick-and-place trajectory as a joints
// CSV. The box arm (arm6.urdf, scenes/robot_cell) has links of boxes and cylinders from our
// generators, overlapping in one mesh as station_module's parts do; the cast arm (--cast,
// arm6_cast.urdf, scenes/robot_cell_cast) has the same joints with free-form links polygonized
// from FRep solids (cast_links.h), and its cell adds a bench and thin sheet-metal guards. The
// scene is then `collido import urdf` of these files (tools/make_robot_cell.sh); ctest
// robot_cell.regenerates checks that the committed files are what this program and the import
// write.
//
// Usage: collido_make_robot_cell [--cast] FOLDER
#include <array>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include <collido/mesh/procedural.h>

#include "cast_links.h"

namespace {

using collido::TriangleMesh;
namespace robot_cell = collido::robot_cell;

[[noreturn]] void fail(const std::string& problem) {
  std::cerr << "collido_make_robot_cell: " << problem << "\n";
  std::exit(1);
}

// Numbers as the shortest text that reads back to the same double, so the files are stable and
// keep the generators' double precision (assimp's exporters would round through float).
std::string number(double value) {
  std::array<char, 32> text{};
  const auto written = std::to_chars(text.data(), text.data() + text.size(), value);
  return std::string(text.data(), written.ptr);
}

void writeObj(const TriangleMesh& mesh, const std::filesystem::path& path) {
  std::ofstream out(path, std::ios::binary);
  out << "# " << path.filename().string() << ", written by collido_make_robot_cell\n";
  for (Eigen::Index v = 0; v < mesh.vertices.cols(); ++v)
    out << "v " << number(mesh.vertices(0, v)) << " " << number(mesh.vertices(1, v)) << " "
        << number(mesh.vertices(2, v)) << "\n";
  for (Eigen::Index t = 0; t < mesh.triangles.cols(); ++t)
    out << "f " << mesh.triangles(0, t) + 1 << " " << mesh.triangles(1, t) + 1 << " "
        << mesh.triangles(2, t) + 1 << "\n";
  if (!out) fail("cannot write " + path.string());
}

// Generated parts in one mesh: their vertices and triangles appended, each part placed by a pose.
class MeshAssembly {
 public:
  void add(const collido::Result<TriangleMesh>& part, const Eigen::Isometry3d& pose) {
    if (!part.ok()) fail(part.status().toString());
    const TriangleMesh& mesh = part.value();
    const Eigen::Index first = mesh_.vertices.cols();
    mesh_.vertices.conservativeResize(3, first + mesh.vertices.cols());
    mesh_.vertices.rightCols(mesh.vertices.cols()) = pose * mesh.vertices;
    const Eigen::Index first_triangle = mesh_.triangles.cols();
    mesh_.triangles.conservativeResize(3, first_triangle + mesh.triangles.cols());
    mesh_.triangles.rightCols(mesh.triangles.cols()) =
        mesh.triangles.array() + static_cast<int>(first);
  }

  void write(const std::filesystem::path& path) const { writeObj(mesh_, path); }

 private:
  TriangleMesh mesh_;
};

enum class Axis { kX, kY, kZ };

// The generators' cylinders run along z; these exact permutations (no rounding) turn z to x or y.
Eigen::Isometry3d placed(const Eigen::Vector3d& centre, Axis along = Axis::kZ) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  if (along == Axis::kX) pose.linear() << 0, 0, 1, 1, 0, 0, 0, 1, 0;
  if (along == Axis::kY) pose.linear() << 0, 1, 0, 0, 0, 1, 1, 0, 0;
  pose.translation() = centre;
  return pose;
}

void box(MeshAssembly& mesh, const Eigen::Vector3d& size, const Eigen::Vector3d& centre) {
  mesh.add(collido::makeBox({size}), placed(centre));
}

void cylinder(MeshAssembly& mesh, double radius, double length, const Eigen::Vector3d& centre,
              Axis along, int segments = 32, double bore = 0.0) {
  mesh.add(collido::makeCylinder({radius, length, segments, bore}), placed(centre, along));
}

// An open box standing on the floor: a bottom and four walls, `wall` thick. The walls stand half
// a wall deep in the bottom and the end walls half a wall into the side walls, so that no two
// parts share a corner (a mesh with coincident vertices would be reported as duplicates).
void bin(MeshAssembly& mesh, const Eigen::Vector3d& size, const Eigen::Vector3d& floor_centre,
         double wall) {
  const Eigen::Vector3d& c = floor_centre;
  box(mesh, {size.x(), size.y(), wall}, c + Eigen::Vector3d(0, 0, wall / 2));
  const double height = size.z() - wall / 2;
  const double z = wall / 2 + height / 2;
  for (const double side : {-1.0, 1.0}) {
    box(mesh, {size.x(), wall, height}, c + Eigen::Vector3d(0, side * (size.y() - wall) / 2, z));
    box(mesh, {wall, size.y() - wall, height},
        c + Eigen::Vector3d(side * (size.x() - wall) / 2, 0, z));
  }
}

// The arm's links, each in its own frame (the frame of the joint that moves it). Hubs turn in the
// forks of the link before with 5 mm to spare on each side.
void writeLinks(const std::filesystem::path& folder) {
  MeshAssembly base;  // a floor plate and a pedestal up to the first joint, at z = 0.2
  box(base, {0.34, 0.34, 0.02}, {0, 0, 0.01});
  cylinder(base, 0.12, 0.18, {0, 0, 0.11}, Axis::kZ, 48);
  base.write(folder / "base.obj");

  MeshAssembly turret;  // turns about z; a fork of two cheeks holds the shoulder at (0.08, 0, 0.22)
  cylinder(turret, 0.11, 0.10, {0, 0, 0.05}, Axis::kZ, 48);
  box(turret, {0.20, 0.24, 0.03}, {0.06, 0, 0.085});
  for (const double side : {-1.0, 1.0})
    box(turret, {0.16, 0.04, 0.20}, {0.08, side * 0.10, 0.17});
  turret.write(folder / "turret.obj");

  MeshAssembly upper_arm;  // turns about y; 0.45 up to the elbow
  cylinder(upper_arm, 0.08, 0.15, {0, 0, 0}, Axis::kY);
  box(upper_arm, {0.10, 0.10, 0.45}, {0, 0, 0.225});
  cylinder(upper_arm, 0.07, 0.12, {0, 0, 0.45}, Axis::kY);
  upper_arm.write(folder / "upper_arm.obj");

  MeshAssembly forearm;  // turns about y; a fork round the elbow, a motor behind, a tube forward
  for (const double side : {-1.0, 1.0})
    box(forearm, {0.12, 0.03, 0.14}, {0, side * 0.08, 0});
  box(forearm, {0.10, 0.19, 0.08}, {-0.08, 0, 0.04});
  cylinder(forearm, 0.05, 0.20, {0.10, 0, 0.04}, Axis::kX);
  forearm.write(folder / "forearm.obj");

  MeshAssembly wrist;  // rolls about x; a fork holds the hand at 0.22
  cylinder(wrist, 0.045, 0.16, {0.08, 0, 0}, Axis::kX);
  for (const double side : {-1.0, 1.0})
    box(wrist, {0.10, 0.02, 0.07}, {0.21, side * 0.05, 0});
  wrist.write(folder / "wrist.obj");

  MeshAssembly hand;  // bends about y; the flange at 0.08
  cylinder(hand, 0.035, 0.07, {0, 0, 0}, Axis::kY, 24);
  cylinder(hand, 0.03, 0.08, {0.04, 0, 0}, Axis::kX, 24);
  hand.write(folder / "hand.obj");

  MeshAssembly gripper;  // rolls about x; a flange and a palm the fingers slide along
  cylinder(gripper, 0.045, 0.015, {0.0075, 0, 0}, Axis::kX);
  box(gripper, {0.045, 0.13, 0.05}, {0.0375, 0, 0});
  gripper.write(folder / "gripper.obj");

  for (const double side : {1.0, -1.0}) {  // slide along ±y from ±0.02, 0.07 long
    MeshAssembly finger;
    box(finger, {0.07, 0.015, 0.03}, {0.035, side * 0.0075, 0});
    finger.write(folder / (side > 0 ? "finger_left.obj" : "finger_right.obj"));
  }
}

// The cell, in world coordinates (the arm's base at the origin, z up).
void writeCell(const std::filesystem::path& folder) {
  MeshAssembly shelf;  // open towards the arm (-y): two sides, a back, four boards
  for (const double side : {-1.0, 1.0})
    box(shelf, {0.02, 0.30, 1.0}, {side * 0.29, 0.60, 0.50});
  box(shelf, {0.56, 0.01, 1.0}, {0, 0.745, 0.50});
  for (const double z : {0.02, 0.29, 0.57, 0.85})
    box(shelf, {0.56, 0.29, 0.02}, {0, 0.595, z});
  shelf.write(folder / "shelf.obj");

  for (const auto& [name, y] : {std::pair<const char*, double>{"bin_a.obj", 0.22},
                                std::pair<const char*, double>{"bin_b.obj", -0.12}}) {
    MeshAssembly part_bin;
    bin(part_bin, {0.30, 0.22, 0.15}, {0.55, y, 0}, 0.01);
    part_bin.write(folder / name);
  }

  MeshAssembly fixture;  // a pedestal, a nest ring the part sits in, two clamps
  box(fixture, {0.24, 0.24, 0.26}, {0.05, -0.55, 0.13});
  cylinder(fixture, 0.05, 0.04, {0.05, -0.55, 0.28}, Axis::kZ, 48, 0.035);
  for (const double side : {-1.0, 1.0})
    box(fixture, {0.04, 0.06, 0.05}, {0.05 + side * 0.09, -0.55, 0.285});
  fixture.write(folder / "fixture.obj");
}

// The links with geometry, each with its mesh of the same name (writeLinks), in the URDF's order.
// The cast arm's cell adds what real cells have around an arm: a work bench behind it and
// sheet-metal guards (1.5 mm panels with a folded edge) fencing the back and the fixture's side.
void writeCastCellExtras(const std::filesystem::path& folder) {
  MeshAssembly bench;  // a top at 0.72 on four legs, behind the arm (-x)
  box(bench, {0.40, 0.70, 0.03}, {-0.58, 0.05, 0.705});
  for (const double x : {-0.76, -0.40}) {
    for (const double y : {-0.27, 0.37})
      box(bench, {0.04, 0.04, 0.69}, {x, y, 0.345});
  }
  bench.write(folder / "bench.obj");

  constexpr double kSheet = 0.0015;
  MeshAssembly guard_back;  // across the back at x = -0.9, its top edge folded towards the arm
  box(guard_back, {kSheet, 1.6, 1.2}, {-0.9, 0.0, 0.65});
  box(guard_back, {0.04, 1.6, kSheet}, {-0.9 + 0.02, 0.0, 1.25});
  guard_back.write(folder / "guard_back.obj");

  MeshAssembly guard_side;  // beside the fixture at y = -0.9, its front edge folded inwards
  box(guard_side, {1.4, kSheet, 1.2}, {-0.2, -0.9, 0.65});
  box(guard_side, {kSheet, 0.04, 1.2}, {0.5, -0.9 + 0.02, 0.65});
  guard_side.write(folder / "guard_side.obj");
}

constexpr const char* kMeshLinks[] = {"base", "turret",  "upper_arm",   "forearm",     "wrist",
                                      "hand", "gripper", "finger_left", "finger_right"};

// The tool centre (no geometry) and the joints: origins, axes and limits.
constexpr const char* kJointsUrdf = R"(  <link name="tool_centre"/>
  <joint name="base_yaw" type="revolute"><parent link="base"/><child link="turret"/>
    <origin xyz="0 0 0.2"/><axis xyz="0 0 1"/>
    <limit lower="-2.9" upper="2.9" effort="100" velocity="2"/></joint>
  <joint name="shoulder" type="revolute"><parent link="turret"/><child link="upper_arm"/>
    <origin xyz="0.08 0 0.22"/><axis xyz="0 1 0"/>
    <limit lower="-1.6" upper="1.6" effort="100" velocity="2"/></joint>
  <joint name="elbow" type="revolute"><parent link="upper_arm"/><child link="forearm"/>
    <origin xyz="0 0 0.45"/><axis xyz="0 1 0"/>
    <limit lower="-1.2" upper="2.4" effort="60" velocity="2.5"/></joint>
  <joint name="forearm_roll" type="revolute"><parent link="forearm"/><child link="wrist"/>
    <origin xyz="0.2 0 0.04"/><axis xyz="1 0 0"/>
    <limit lower="-3.1" upper="3.1" effort="20" velocity="4"/></joint>
  <joint name="wrist_bend" type="revolute"><parent link="wrist"/><child link="hand"/>
    <origin xyz="0.22 0 0"/><axis xyz="0 1 0"/>
    <limit lower="-2" upper="2" effort="20" velocity="4"/></joint>
  <joint name="flange_roll" type="revolute"><parent link="hand"/><child link="gripper"/>
    <origin xyz="0.08 0 0"/><axis xyz="1 0 0"/>
    <limit lower="-3.1" upper="3.1" effort="10" velocity="5"/></joint>
  <joint name="finger_left_slide" type="prismatic"><parent link="gripper"/>
    <child link="finger_left"/><origin xyz="0.06 0.02 0"/><axis xyz="0 1 0"/>
    <limit lower="0" upper="0.03" effort="50" velocity="0.1"/></joint>
  <joint name="finger_right_slide" type="prismatic"><parent link="gripper"/>
    <child link="finger_right"/><origin xyz="0.06 -0.02 0"/><axis xyz="0 -1 0"/>
    <limit lower="0" upper="0.03" effort="50" velocity="0.1"/>
    <mimic joint="finger_left_slide"/></joint>
  <joint name="tool_centre_point" type="fixed"><parent link="gripper"/><child link="tool_centre"/>
    <origin xyz="0.1 0 0"/></joint>
</robot>
)";

// The arm's URDF: the links (meshes under package://PACKAGE/meshes/), then the joints.
std::string urdfText(const std::string& package, const std::string& what) {
  std::string text = R"(<?xml version="1.0"?>
<!-- )" + what + R"(: six revolute joints and a parallel
     gripper whose right finger mimics the left. Written by collido_make_robot_cell. -->
<robot name="arm6">
)";
  for (const char* link : kMeshLinks) {
    text.append("  <link name=\"").append(link).append("\"><collision><geometry>\n");
    text.append("    <mesh filename=\"package://" + package + "/meshes/")
        .append(link)
        .append(".obj\"/></geometry></collision></link>\n");
  }
  return text + kJointsUrdf;
}

constexpr int kJoints = 7;
constexpr double kOpen = 0.03;     // fingers 0.1 apart
constexpr double kClosed = 0.008;  // on a 56 mm part

// The pick-and-place cycle as joint-space waypoints (solved once for the tool centre's targets),
// each reached in `frames` frames with a smooth (cosine) start and stop.
struct Waypoint {
  const char* what;
  int frames;
  std::array<double, kJoints> joints;  // base_yaw ... flange_roll, finger_left_slide
};

const std::vector<Waypoint>& cycle() {
  static const std::vector<Waypoint> waypoints = {
      {"home, the tool forward at 0.75 m", 0, {0, -0.531, 0.764, 0, -0.233, 0, kOpen}},
      {"above bin a, pointing down", 4, {0.381, 0.56, 0.401, 0, 0.61, 0.381, kOpen}},
      {"into bin a: the fingertips scrape its floor, 1 mm deep",
       4,
       {0.381, 1.096, 0.301, 0, 0.174, 0.381, kOpen}},
      {"grip", 2, {0.381, 1.096, 0.301, 0, 0.174, 0.381, kClosed}},
      {"lift out of bin a", 4, {0.381, 0.476, 0.378, 0, 0.718, 0.381, kClosed}},
      {"above the fixture's nest", 6, {-1.48, 0.161, 0.257, 0, 1.152, 0.091, kClosed}},
      {"into the nest", 4, {-1.48, 0.408, 0.488, 0, 0.675, 0.091, kClosed}},
      {"release", 2, {-1.48, 0.408, 0.488, 0, 0.675, 0.091, kOpen}},
      {"back above the fixture", 3, {-1.48, 0.161, 0.257, 0, 1.152, 0.091, kOpen}},
      {"home", 5, {0, -0.531, 0.764, 0, -0.233, 0, kOpen}},
      {"before the shelf's middle compartment", 5, {1.571, -1.102, 1.146, 0, -0.044, 0, kOpen}},
      {"into the compartment, the flange 1 cm over the board",
       4,
       {1.571, -0.023, 0.709, 0, -0.685, 0, kOpen}},
      {"grip", 2, {1.571, -0.023, 0.709, 0, -0.685, 0, kClosed}},
      {"back out", 4, {1.571, -1.102, 1.146, 0, -0.044, 0, kClosed}},
      {"home", 5, {0, -0.531, 0.764, 0, -0.233, 0, kClosed}},
      {"above bin b", 4, {-0.215, 0.516, 0.483, 0, 0.572, -0.215, kClosed}},
      {"release", 2, {-0.215, 0.516, 0.483, 0, 0.572, -0.215, kOpen}},
      {"home", 4, {0, -0.531, 0.764, 0, -0.233, 0, kOpen}},
  };
  return waypoints;
}

void writeTrajectory(const std::filesystem::path& path) {
  std::ofstream out(path, std::ios::binary);
  out << "base_yaw,shoulder,elbow,forearm_roll,wrist_bend,flange_roll,finger_left_slide\n";
  const auto row = [&out](const std::array<double, kJoints>& joints) {
    for (int j = 0; j < kJoints; ++j)  // micro-radian steps keep the file readable
      out << (j > 0 ? "," : "") << number(std::round(joints[j] * 1e6) / 1e6 + 0.0);
    out << "\n";
  };
  const std::vector<Waypoint>& waypoints = cycle();
  row(waypoints.front().joints);
  for (std::size_t w = 1; w < waypoints.size(); ++w) {
    for (int f = 1; f <= waypoints[w].frames; ++f) {
      const double s = 0.5 - 0.5 * std::cos(M_PI * f / waypoints[w].frames);
      std::array<double, kJoints> joints{};
      for (int j = 0; j < kJoints; ++j)
        joints[j] =
            waypoints[w - 1].joints[j] + s * (waypoints[w].joints[j] - waypoints[w - 1].joints[j]);
      row(joints);
    }
  }
  if (!out) fail("cannot write " + path.string());
}

}  // namespace

int main(int argc, char** argv) {
  const bool cast = argc == 3 && std::string(argv[1]) == "--cast";
  if (argc != 2 && !cast) {
    std::cerr << "usage: collido_make_robot_cell [--cast] FOLDER\n";
    return 2;
  }
  const std::filesystem::path folder = argv[argc - 1];
  std::error_code error;
  for (const char* sub : {"meshes", "cell"}) {
    if (std::filesystem::create_directories(folder / sub, error); error)
      fail((folder / sub).string() + ": " + error.message());
  }
  std::string urdf_name = "arm6.urdf";
  std::string urdf_text =
      urdfText("robot_cell", "The bundled robot cell's arm (scenes/robot_cell.json)");
  if (cast) {
    // About 4,000 triangles a link: the 2k-10k of arm CAD exports' collision meshes.
    for (const robot_cell::CastLink& link : robot_cell::castLinks(4000))
      writeObj(link.mesh, folder / "meshes" / (link.name + ".obj"));
    writeCastCellExtras(folder / "cell");
    urdf_name = "arm6_cast.urdf";
    urdf_text = urdfText("robot_cell_cast",
                         "The bundled cast robot cell's arm (scenes/robot_cell_cast.json)");
  } else {
    writeLinks(folder / "meshes");
  }
  writeCell(folder / "cell");
  std::ofstream urdf(folder / urdf_name, std::ios::binary);
  if (!(urdf << urdf_text)) fail("cannot write " + (folder / urdf_name).string());
  writeTrajectory(folder / "pick_and_place.csv");
  return 0;
}
