#include "generator_reader.h"

#include <limits>
#include <map>
#include <set>
#include <vector>

#include <collido/mesh/procedural.h>

namespace collido::scene_reading {
namespace {

// One parameter as a scene writes it: the keys it reads and how it sets its field of the
// generator's parameter struct. A key left out keeps the struct's default; every value is left
// for the generator to judge.
template <class P>
struct Param {
  std::vector<std::string> keys;
  std::function<void(const Reader&, const Node&, P&)> read;
};

template <class P>
Param<P> number(const char* key, double P::*field) {
  return {{key}, [key, field](const Reader& r, const Node& n, P& p) {
            if (n.has(key)) p.*field = r.number(n.at(key));
          }};
}

// A structural count (links, teeth, bays, holes): the load's resolution leaves it alone.
template <class P>
Param<P> structure(const char* key, int P::*field) {
  return {{key}, [key, field](const Reader& r, const Node& n, P& p) {
            if (n.has(key)) {
              p.*field = static_cast<int>(r.integer(n.at(key), std::numeric_limits<int>::min(),
                                                    std::numeric_limits<int>::max()));
            }
          }};
}

// A sample count: it follows the load's resolution, never below `floor`, the generator's minimum.
template <class P>
Param<P> samples(const char* key, int P::*field, int floor) {
  const Param<P> given = structure(key, field);
  return {{key}, [given, field, floor](const Reader& r, const Node& n, P& p) {
            given.read(r, n, p);
            p.*field = r.resolved(p.*field, floor);
          }};
}

template <class P>
Param<P> vector(const char* key, Eigen::Vector3d P::*field) {
  return {{key}, [key, field](const Reader& r, const Node& n, P& p) {
            if (n.has(key)) p.*field = r.vector3(n.at(key));
          }};
}

const std::vector<Param<TorusParams>>& torusParams() {
  static const std::vector<Param<TorusParams>> table = {
      number("major_radius", &TorusParams::major_radius),
      number("minor_radius", &TorusParams::minor_radius),
      samples("major_segments", &TorusParams::major_segments, 3),
      samples("minor_segments", &TorusParams::minor_segments, 3)};
  return table;
}

// A torus's keys at the same level, setting `field` (a chain's link).
template <class P>
Param<P> torus(TorusParams P::*field) {
  Param<P> out;
  for (const Param<TorusParams>& param : torusParams())
    out.keys.insert(out.keys.end(), param.keys.begin(), param.keys.end());
  out.read = [field](const Reader& r, const Node& n, P& p) {
    for (const Param<TorusParams>& param : torusParams())
      param.read(r, n, p.*field);
  };
  return out;
}

struct Generator {
  std::set<std::string> keys;
  std::function<PlannedShape(const Reader&, const Node&)> read;
};

template <class P>
Generator generator(std::vector<Param<P>> table, std::string (*describe)(const P&),
                    Result<TriangleMesh> (*make)(const P&)) {
  Generator out;
  out.keys = {"generator"};
  for (const Param<P>& param : table)
    out.keys.insert(param.keys.begin(), param.keys.end());
  out.read = [table = std::move(table), describe, make, keys = out.keys](const Reader& r,
                                                                         const Node& n) {
    r.expectObject(n, keys);
    P p;
    for (const Param<P>& param : table)
      param.read(r, n, p);
    return PlannedShape{describe(p), triangleCount(p), [p, make] { return make(p); }};
  };
  return out;
}

std::string describeTorus(const TorusParams& p) {
  return "torus R=" + shortNumber(p.major_radius) + " r=" + shortNumber(p.minor_radius) + " " +
         std::to_string(p.major_segments) + "x" + std::to_string(p.minor_segments);
}

std::string describeChain(const ChainParams& p) {
  return "chain of " + std::to_string(p.links) + " tori R=" + shortNumber(p.link.major_radius) +
         " r=" + shortNumber(p.link.minor_radius) + " clearance=" + shortNumber(p.clearance);
}

std::string describeSphere(const SphereParams& p) {
  return "sphere r=" + shortNumber(p.radius) + " " + std::to_string(p.slices) + "x" +
         std::to_string(p.stacks);
}

std::string describeBox(const BoxParams& p) {
  return "box " + shortNumber(p.size.x()) + "x" + shortNumber(p.size.y()) + "x" +
         shortNumber(p.size.z());
}

std::string describeGridSheet(const GridSheetParams& p) {
  return "grid sheet " + std::to_string(p.cells_x) + "x" + std::to_string(p.cells_y);
}

std::string describeGear(const GearParams& p) {
  return "gear z=" + std::to_string(p.teeth) + " m=" + shortNumber(p.module);
}

std::string describeStationModule(const StationModuleParams& p) {
  return "station module R=" + shortNumber(p.radius) + " L=" + shortNumber(p.length) + " " +
         std::to_string(p.segments) + "x" + std::to_string(p.rings) + ", " +
         std::to_string(p.truss_bays) + " truss bays";
}

std::string describeCylinder(const CylinderParams& p) {
  return (p.inner_radius > 0.0
              ? "tube R=" + shortNumber(p.radius) + " r=" + shortNumber(p.inner_radius)
              : "cylinder r=" + shortNumber(p.radius)) +
         " h=" + shortNumber(p.height) + " " + std::to_string(p.segments) + " segments";
}

std::string describeFlange(const FlangeParams& p) {
  return "flange R=" + shortNumber(p.outer_radius) + " bore=" + shortNumber(p.bore_radius) + ", " +
         std::to_string(p.bolt_holes) + " bolt holes r=" + shortNumber(p.hole_radius);
}

const std::map<std::string, Generator>& generators() {
  static const std::map<std::string, Generator> table = {
      {"torus", generator(torusParams(), &describeTorus, &makeTorus)},
      {"chain", generator<ChainParams>(
                    {structure("links", &ChainParams::links),
                     number("clearance", &ChainParams::clearance), torus(&ChainParams::link)},
                    &describeChain, &makeChain)},
      {"sphere", generator<SphereParams>({number("radius", &SphereParams::radius),
                                          samples("slices", &SphereParams::slices, 3),
                                          samples("stacks", &SphereParams::stacks, 2)},
                                         &describeSphere, &makeSphere)},
      {"box", generator<BoxParams>({vector("size", &BoxParams::size)}, &describeBox, &makeBox)},
      {"grid_sheet", generator<GridSheetParams>({number("width", &GridSheetParams::width),
                                                 number("depth", &GridSheetParams::depth),
                                                 samples("cells_x", &GridSheetParams::cells_x, 1),
                                                 samples("cells_y", &GridSheetParams::cells_y, 1),
                                                 number("amplitude", &GridSheetParams::amplitude),
                                                 number("waves", &GridSheetParams::waves)},
                                                &describeGridSheet, &makeGridSheet)},
      {"gear", generator<GearParams>(
                   {structure("teeth", &GearParams::teeth), number("module", &GearParams::module),
                    number("face_width", &GearParams::face_width),
                    number("pressure_angle_deg", &GearParams::pressure_angle_deg),
                    samples("flank_samples", &GearParams::flank_samples, 2),
                    samples("root_samples", &GearParams::root_samples, 1)},
                   &describeGear, &makeGear)},
      {"station_module",
       generator<StationModuleParams>({number("radius", &StationModuleParams::radius),
                                       number("length", &StationModuleParams::length),
                                       samples("segments", &StationModuleParams::segments, 3),
                                       samples("rings", &StationModuleParams::rings, 1),
                                       number("port_radius", &StationModuleParams::port_radius),
                                       number("port_length", &StationModuleParams::port_length),
                                       structure("truss_bays", &StationModuleParams::truss_bays),
                                       number("panel_span", &StationModuleParams::panel_span),
                                       number("panel_width", &StationModuleParams::panel_width)},
                                      &describeStationModule, &makeStationModule)},
      {"cylinder",
       generator<CylinderParams>(
           {number("radius", &CylinderParams::radius), number("height", &CylinderParams::height),
            samples("segments", &CylinderParams::segments, 3),
            number("inner_radius", &CylinderParams::inner_radius)},
           &describeCylinder, &makeCylinder)},
      {"flange",
       generator<FlangeParams>({number("outer_radius", &FlangeParams::outer_radius),
                                number("bore_radius", &FlangeParams::bore_radius),
                                number("thickness", &FlangeParams::thickness),
                                structure("bolt_holes", &FlangeParams::bolt_holes),
                                number("bolt_circle_radius", &FlangeParams::bolt_circle_radius),
                                number("hole_radius", &FlangeParams::hole_radius),
                                samples("arc_segments", &FlangeParams::arc_segments, 1),
                                samples("radial_segments", &FlangeParams::radial_segments, 1)},
                               &describeFlange, &makeFlange)}};
  return table;
}

}  // namespace

PlannedShape readGenerator(const Reader& r, const Node& node) {
  const std::string name = r.string(node.at("generator"));
  const auto found = generators().find(name);
  if (found == generators().end()) {
    std::string list;
    for (const auto& [known, entry] : generators())
      list += (list.empty() ? "" : ", ") + known;
    r.fail(node.at("generator"), "unknown generator '" + name + "' (known: " + list + ")");
  }
  return found->second.read(r, node);
}

}  // namespace collido::scene_reading
