// The cast arm's links as FRep solids, polygonized (cast_links.h). Each link keeps the bundled
// box arm's envelope and joint frames, so the same URDF joints and trajectory drive it; its
// parts are rounded superellipsoids (housings, hubs, caps, a flange) joined by Rvachev's
// R-function union, which rounds the seams away from the common edge.
#include "cast_links.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <numeric>
#include <tuple>

#include <Eigen/Geometry>

#include <collido/frep/solid.h>
#include <collido/frep_mesh/polygonize.h>

namespace collido::robot_cell {
namespace {

using Eigen::Vector3d;
using frep::SolidPtr;

enum class Axis { kX, kY, kZ };

// A rounded cylinder: round across, flat ends with rounded rims (a superellipsoid whose
// north-south exponent is small), of `radius` and half length `half`, along `axis`.
SolidPtr roundedCylinder(const Vector3d& centre, double radius, double half, Axis axis,
                         double rim = 0.25) {
  const SolidPtr along_z = frep::superellipsoid(Vector3d::Zero(), {radius, radius, half}, 1.0, rim);
  Eigen::Affine3d pose = Eigen::Affine3d::Identity();
  if (axis == Axis::kX) pose.linear() << 0, 0, 1, 0, 1, 0, -1, 0, 0;
  if (axis == Axis::kY) pose.linear() << 1, 0, 0, 0, 0, 1, 0, -1, 0;
  pose.translation() = centre;
  return frep::transformed(along_z, pose);
}

// A rounded box (a housing, a cheek, a palm): superellipsoid exponents below 1 square it off.
SolidPtr roundedBox(const Vector3d& centre, const Vector3d& half, double roundness = 0.35) {
  return frep::superellipsoid(centre, half, roundness, roundness);
}

SolidPtr cast(std::vector<SolidPtr> parts) {
  return frep::unionOf(std::move(parts), frep::SetBlend::kRFunction);
}

std::vector<std::pair<std::string, SolidPtr>> linkSolids() {
  std::vector<std::pair<std::string, SolidPtr>> links;
  // The pedestal: a foot plate and a column up to the first joint at z = 0.2.
  links.emplace_back("base", cast({roundedCylinder({0, 0, 0.012}, 0.17, 0.012, Axis::kZ, 0.2),
                                   roundedCylinder({0, 0, 0.105}, 0.12, 0.09, Axis::kZ),
                                   roundedBox({0.09, 0, 0.08}, {0.05, 0.06, 0.045})}));
  // The turret: a round housing and a fork of two cheeks round the shoulder at (0.08, 0, 0.22).
  std::vector<SolidPtr> turret = {roundedCylinder({0.01, 0, 0.05}, 0.11, 0.05, Axis::kZ),
                                  roundedBox({0.06, 0, 0.095}, {0.09, 0.12, 0.018})};
  for (const double side : {-1.0, 1.0})
    turret.push_back(roundedBox({0.08, side * 0.10, 0.17}, {0.075, 0.02, 0.095}, 0.5));
  links.emplace_back("turret", cast(turret));
  // The upper arm: hubs at the shoulder and the elbow (z = 0.45), a cast beam between with a
  // cable boss along its back.
  links.emplace_back("upper_arm", cast({roundedCylinder({0, 0, 0}, 0.078, 0.07, Axis::kY),
                                        roundedBox({0, 0, 0.225}, {0.05, 0.055, 0.2}, 0.5),
                                        roundedBox({-0.05, 0, 0.24}, {0.02, 0.03, 0.12}, 0.5),
                                        roundedCylinder({0, 0, 0.45}, 0.066, 0.058, Axis::kY)}));
  // The forearm: a fork round the elbow, a motor housing behind, a tube forward to the wrist.
  std::vector<SolidPtr> forearm = {roundedBox({-0.08, 0, 0.04}, {0.05, 0.093, 0.04}),
                                   roundedCylinder({0.10, 0, 0.04}, 0.048, 0.1, Axis::kX),
                                   roundedCylinder({0.19, 0, 0.04}, 0.056, 0.008, Axis::kX, 0.2)};
  for (const double side : {-1.0, 1.0})
    forearm.push_back(roundedBox({0, side * 0.08, 0}, {0.06, 0.014, 0.07}, 0.5));
  links.emplace_back("forearm", cast(forearm));
  // The wrist: a tube rolling about x and a fork holding the hand at 0.22.
  std::vector<SolidPtr> wrist = {roundedCylinder({0.08, 0, 0}, 0.044, 0.08, Axis::kX)};
  for (const double side : {-1.0, 1.0})
    wrist.push_back(roundedBox({0.2, side * 0.05, 0}, {0.05, 0.009, 0.034}, 0.5));
  links.emplace_back("wrist", cast(wrist));
  // The hand: a hub about y and a nose out to the flange at 0.08.
  links.emplace_back("hand", cast({roundedCylinder({0, 0, 0}, 0.034, 0.034, Axis::kY),
                                   roundedCylinder({0.04, 0, 0}, 0.029, 0.04, Axis::kX)}));
  // The gripper: a tool flange and a palm the fingers slide along.
  links.emplace_back("gripper", cast({roundedCylinder({0.0075, 0, 0}, 0.044, 0.0075, Axis::kX, 0.2),
                                      roundedBox({0.0375, 0, 0}, {0.022, 0.064, 0.024})}));
  // The fingers: rounded jaws with a tapered tip.
  for (const double side : {1.0, -1.0}) {
    const SolidPtr jaw = roundedBox({0.035, side * 0.0075, 0}, {0.034, 0.0072, 0.014}, 0.4);
    const SolidPtr tip = frep::halfSpace(Vector3d(1.0, 0.0, 0.5).normalized(), 0.07);
    links.emplace_back(side > 0 ? "finger_left" : "finger_right",
                       frep::intersectionOf({jaw, tip}, frep::SetBlend::kRFunction));
  }
  return links;
}

// Vertices sorted by position and triangles by their corners (each rotated to start at its
// least corner, keeping the winding): polygonization's output order may depend on threading.
TriangleMesh canonical(const TriangleMesh& mesh) {
  std::vector<int> order(static_cast<std::size_t>(mesh.vertices.cols()));
  std::iota(order.begin(), order.end(), 0);
  const auto position = [&mesh](int v) {
    return std::make_tuple(mesh.vertices(0, v), mesh.vertices(1, v), mesh.vertices(2, v));
  };
  std::sort(order.begin(), order.end(),
            [&position](int a, int b) { return position(a) < position(b); });
  TriangleMesh out;
  out.vertices.resize(3, mesh.vertices.cols());
  std::vector<int> renamed(order.size());
  for (std::size_t i = 0; i < order.size(); ++i) {
    out.vertices.col(static_cast<Eigen::Index>(i)) = mesh.vertices.col(order[i]);
    renamed[static_cast<std::size_t>(order[i])] = static_cast<int>(i);
  }
  std::vector<std::array<int, 3>> triangles;
  for (Eigen::Index t = 0; t < mesh.triangles.cols(); ++t) {
    std::array<int, 3> corners{};
    for (int k = 0; k < 3; ++k)
      corners[static_cast<std::size_t>(k)] =
          renamed[static_cast<std::size_t>(mesh.triangles(k, t))];
    std::rotate(corners.begin(), std::min_element(corners.begin(), corners.end()), corners.end());
    triangles.push_back(corners);
  }
  std::sort(triangles.begin(), triangles.end());
  out.triangles.resize(3, static_cast<Eigen::Index>(triangles.size()));
  for (std::size_t t = 0; t < triangles.size(); ++t)
    out.triangles.col(static_cast<Eigen::Index>(t)) << triangles[t][0], triangles[t][1],
        triangles[t][2];
  return out;
}

TriangleMesh polygonized(const std::string& name, const frep::Solid& solid, int resolution) {
  const Result<TriangleMesh> mesh = frep::polygonize(solid, solid.bounds(), resolution);
  if (!mesh.ok()) {
    std::cerr << "collido_make_robot_cell: link " << name << ": " << mesh.status().message()
              << "\n";
    std::exit(1);
  }
  return mesh.value();
}

}  // namespace

std::vector<CastLink> castLinks(int triangles_per_link) {
  std::vector<CastLink> links;
  for (const auto& [name, solid] : linkSolids()) {
    // Triangles grow with the square of the resolution: one trial at a coarse grid sets it.
    constexpr int kTrial = 24;
    const double trial = static_cast<double>(polygonized(name, *solid, kTrial).triangleCount());
    const int resolution = std::clamp(
        static_cast<int>(std::lround(kTrial * std::sqrt(triangles_per_link / trial))), kTrial, 400);
    links.push_back({name, canonical(polygonized(name, *solid, resolution))});
  }
  return links;
}

}  // namespace collido::robot_cell
