// surface_json_fuzz: the surface-file reader (collido::parseSurfaces), then what the seed method
// does with what loads: evaluation, splitting and the certified distance.
//
// Why: surface files come from users (and, later, from CAD imports); a NURBS net with odd knots
// or weights reaches knot insertion and the best-first search directly.
// What it checks:
//  - whatever the bytes, parseSurfaces returns (an error naming the label is a fine answer)
//    without a crash, an out-of-bounds access, undefined behaviour or a leak;
//  - a surface that loads passes validate(), evaluates anywhere in its domain without a crash,
//    and splits into four sub-patches that each pass validate() and agree with it at their
//    corners;
//  - two surfaces that load get a certified interval from minimumDistance (at most 2,000 pairs
//    bounded): 0 <= lower <= upper, both finite, whenever every control point is finite and
//    below 1e100 in magnitude (beyond that the squared distances overflow, by design).
// Resources: generated sheets are capped at 24 x 24 control points by the fuzzer (bigger ones
// are skipped), so one input cannot cost seconds.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <collido/nurbs/surface_distance.h>
#include <collido/scene/surface_file.h>

namespace {

constexpr const char* kLabel = "fuzz.json";

[[noreturn]] void broken(const std::string& what) {
  std::fprintf(stderr, "surface_json_fuzz: a promise was broken: %s\n", what.c_str());
  std::abort();
}

double magnitude(const collido::nurbs::NurbsSurface& s) {
  return s.controlPoints().cwiseAbs().maxCoeff();
}

void checkSurface(const collido::nurbs::NurbsSurface& s) {
  if (collido::Status v = collido::nurbs::validate(s); !v.ok()) broken("loaded but " + v.message());
  for (const double a : {0.0, 0.37, 1.0}) {
    const double u = s.uMin() + a * (s.uMax() - s.uMin());
    const double v = s.vMin() + (1.0 - a) * (s.vMax() - s.vMin());
    (void)collido::nurbs::evaluateWithDerivatives(s, u, v);
  }
  if (!(s.uMin() + (s.uMax() - s.uMin()) * 0.5 > s.uMin()) ||
      !(s.vMin() + (s.vMax() - s.vMin()) * 0.5 > s.vMin())) {
    return;  // a domain too narrow to halve in double precision
  }
  for (const collido::nurbs::NurbsSurface& part : collido::nurbs::splitInFour(s)) {
    if (collido::Status v = collido::nurbs::validate(part); !v.ok())
      broken("a sub-patch: " + v.message());
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const collido::Result<std::vector<collido::NamedSurface>> surfaces =
      collido::parseSurfaces(text, kLabel);
  if (!surfaces.ok()) {
    if (surfaces.status().message().find(kLabel) == std::string::npos)
      broken("an error that does not name the file: " + surfaces.status().message());
    return 0;
  }
  for (const collido::NamedSurface& named : surfaces.value()) {
    if (named.surface.control.size() > 24u * 24u) return 0;
    checkSurface(named.surface);
  }
  if (surfaces.value().size() < 2) return 0;
  const collido::nurbs::NurbsSurface& a = surfaces.value()[0].surface;
  const collido::nurbs::NurbsSurface& b = surfaces.value()[1].surface;
  collido::nurbs::SurfaceDistanceOptions options;
  options.max_pairs = 2000;
  options.tolerance = 1e-3 * std::max(1.0, std::max(magnitude(a), magnitude(b)));
  const collido::nurbs::SurfaceDistance d = collido::nurbs::minimumDistance(a, b, options);
  if (std::max(magnitude(a), magnitude(b)) < 1e100) {
    if (!(d.lower >= 0.0 && d.lower <= d.upper && std::isfinite(d.upper)))
      broken("interval [" + std::to_string(d.lower) + ", " + std::to_string(d.upper) + "]");
  }
  return 0;
}
