#pragma once

#include <string>
#include <vector>

#include <collido/nurbs/nurbs_surface.h>
#include <collido/status.h>

namespace collido {

/// A NURBS surface read from a surface file, with its name.
struct NamedSurface {
  std::string name;
  nurbs::NurbsSurface surface;
};

/// Reads a surface file: {"surfaces": [SURFACE, ...]}, each SURFACE either explicit —
///   {"name": "a", "degree_u": 3, "degree_v": 3, "knots_u": [...], "knots_v": [...],
///    "control": [[[x, y, z, w], ...], ...]}   (count_u rows of count_v points; w optional, 1)
/// — or generated: {"name": "b", "generator": "sphere_zone" | "saddle" | "wavy_sheet" |
/// "swept_blade", ...its parameters (collido/nurbs/surface_generators.h)}. Errors name the file,
/// the JSON path and the problem (a weight <= 0, unclamped knots, a missing key, a duplicate
/// name or key).
Result<std::vector<NamedSurface>> parseSurfaces(const std::string& text, const std::string& label);

/// parseSurfaces on a file's contents; a missing or unreadable file is an error naming it.
Result<std::vector<NamedSurface>> loadSurfaces(const std::string& path);

}  // namespace collido
