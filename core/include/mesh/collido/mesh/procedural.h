#pragma once

#include <collido/mesh/triangle_mesh.h>
#include <collido/status.h>

namespace collido {

// Every generator checks its parameters first and returns kInvalidArgument with a message that
// names the generator, the parameter and the allowed range ("torus: minor_segments = 2, must be
// >= 3"); non-finite numbers are rejected, and so is any resolution that would give more than
// 50 million triangles. Closed meshes (torus, chain, sphere, gear, cylinder, flange) are watertight
// 2-manifolds: every edge has exactly two triangles, counter-clockwise seen from outside, no
// zero-area triangles and no duplicate vertices; the station module is a union of such parts.
// Lengths are in the caller's unit.

/// Ring torus around the z axis, centred at the origin: major_segments * minor_segments vertices
/// and twice as many triangles. Vertex i * minor_segments + j lies at u = 2 pi i / major_segments
/// around z and v = 2 pi j / minor_segments around the tube, so the extremes (+-(R + r) on x and
/// y, +-r on z) are vertices when both resolutions are multiples of 4.
struct TorusParams {
  double major_radius = 1.0;   ///< centre of the tube to the z axis, > 0
  double minor_radius = 0.25;  ///< tube radius, > 0 and < major_radius
  int major_segments = 48;     ///< resolution around z, >= 3
  int minor_segments = 24;     ///< resolution around the tube, >= 3
};

/// A chain of interlocked tori along +x, as one mesh: link i is centred at (i * pitch, 0, 0) with
/// pitch = 2 * (major_radius - minor_radius) - clearance; even links lie in the xy plane, odd
/// links in the xz plane, so neighbours pass through each other's hole. At clearance 0 the tubes
/// of neighbours touch; clearance > 0 leaves a gap, < 0 makes them intersect (the tessellated
/// tubes deviate from the ideal ones by their chord sagitta; at clearance 0 with even resolutions
/// the contact point is a vertex of both links, i.e. two coincident vertices). Link i owns vertex
/// columns [i V, (i + 1) V) and triangle columns [2 i V, 2 (i + 1) V), V = major * minor segments.
struct ChainParams {
  int links = 3;     ///< >= 1
  TorusParams link;  ///< shape and resolution of every link
  /// Gap between neighbouring tubes, finite. pitch must stay > 2 * minor_radius (the far side of a
  /// neighbour's hole; the gap there is pitch - 2 r) and, with 3 or more links, > major_radius +
  /// minor_radius (links i and i + 2 lie in the same plane and would overlap).
  double clearance = 0.0;
};

/// UV sphere centred at the origin, poles on z: slices * (stacks - 1) + 2 vertices (one per
/// pole, vertex 0 north, the last south) and 2 * slices * (stacks - 1) triangles (fans at the
/// poles). Rings sit at polar angles pi k / stacks, so the equator is a ring when stacks is even.
struct SphereParams {
  double radius = 1.0;  ///< > 0
  int slices = 32;      ///< around z, >= 3
  int stacks = 16;      ///< pole to pole, >= 2
};

/// A rectangular sheet in the xy plane centred at the origin (two triangles per cell), optionally
/// waved: z = amplitude * sin(2 pi waves x / width) * cos(2 pi waves y / depth). Open, one-sided,
/// every triangle's normal has a positive z component. (cells_x + 1) * (cells_y + 1) vertices,
/// vertex i + j * (cells_x + 1) at column i, row j; 2 * cells_x * cells_y triangles.
struct GridSheetParams {
  double width = 2.0;      ///< along x, > 0
  double depth = 2.0;      ///< along y, > 0
  int cells_x = 32;        ///< >= 1
  int cells_y = 32;        ///< >= 1
  double amplitude = 0.0;  ///< finite, any sign
  double waves = 1.0;      ///< finite
};

/// Spur gear: an involute tooth profile extruded along z (from -face_width/2 to +face_width/2),
/// centred at the origin, closed, non-convex, tooth 0 centred on +x. Standard full-depth teeth:
/// pitch radius rp = module * teeth / 2, base radius rp cos(pressure angle), tip radius
/// rp + module, root radius rp - 1.25 module; the tooth is pi module / 2 thick on the pitch
/// circle (zero backlash), so two gears of the same module at centre distance
/// module (z1 + z2) / 2 touch when a tooth sits centred in the other's gap. Where the root
/// circle is inside the base circle the flank continues radially down to it (no undercut or
/// fillet is modelled). Each tooth's outline, counter-clockwise:
///   [root foot] flank_samples rising flank points, one tip-arc midpoint, flank_samples falling
///   flank points, [root foot], root_samples points strictly inside the root arc
/// (the two feet only when the root circle is inside the base circle); flanks are sampled
/// uniformly in the involute's roll angle from the base or root circle to the tip circle.
/// With P such points per tooth: 2 * teeth * P + 2 vertices (bottom outline, top outline, the
/// two cap centres) and 4 * teeth * P triangles (caps fanned from the centres, side walls).
/// Rejected as well: pointed teeth (no thickness left at the tip circle) and gaps closed at the
/// root circle, which happen with few resp. many teeth at high pressure angles.
struct GearParams {
  int teeth = 20;                  ///< >= 6
  double module = 0.1;             ///< pitch diameter / teeth, > 0
  double face_width = 0.2;         ///< thickness along z, > 0
  double pressure_angle_deg = 20;  ///< involute pressure angle, in (0, 45) degrees
  int flank_samples = 6;           ///< points per involute flank (resolution), >= 2
  int root_samples = 3;            ///< points along each root arc, >= 1
};

/// The space-station module of the dissertation's application (assembly of a station from
/// modules): a union of closed parts in one mesh. The parts touch or overlap one another (it is
/// a collision mesh, not a solid model); each part is a watertight 2-manifold wound outward, no
/// two parts share a vertex, and no vertex of one part coincides with a vertex of another.
/// With R = radius, L = length, t = R / 20 (beam thickness), w = R / 2 (truss width and depth),
/// in this order:
///   hull   closed cylinder of radius R around the z axis, z in [0, L], `rings` rings along z;
///   port   closed cylinder of radius port_radius around the z axis, z in
///          [L - port_length / 2, L + port_length]: it sticks out port_length beyond the hull's
///          +z end (the docking face is the disk z = L + port_length) and reaches port_length / 2
///          into the hull; also `rings` rings along z;
///   truss  a box lattice on the hull's +y side over z in [0, L]: four chords along z at
///          x = +-w / 2, y = yb and yb + w with yb = sqrt(R^2 - w^2 / 4) (the lower chords'
///          centre lines lie on the hull), truss_bays + 1 square frames of four cross beams at
///          z = L k / truss_bays, and one diagonal per bay on each of the four faces, alternating
///          in direction from bay to bay (a Warren truss); beams t x t in section (so the
///          frames at z = 0 and z = L reach t / 2 beyond the hull's ends);
///   mast   a 2t x 2t beam along +y from the truss top (y = yb + w) at z = L / 2, R long;
///   panels two solar panels, thin boxes t thick (in y) and panel_width wide (in z), centred
///          on z = L / 2 and y = yb + w + R - t, one along +x and one along -x, each reaching
///          from |x| = t / 2 (inside the mast) to |x| = t / 2 + panel_span.
/// Each cylinder has segments * (rings + 1) + 2 vertices (rings of `segments` vertices, ring k at
/// z0 + (z1 - z0) k / rings, vertex i at angle 2 pi i / segments from +x towards +y, then the
/// bottom and top cap centres) and 2 * segments * (rings + 1) triangles (the side quads ring by
/// ring, then the two cap fans). Each box (beam or panel) has 8 vertices and 12 triangles; there
/// are B = 8 * truss_bays + 11 of them (4 chords, 4 (truss_bays + 1) cross beams, 4 truss_bays
/// diagonals, the mast, two panels). In total 2 (segments (rings + 1) + 2) + 8 B vertices and
/// 4 segments (rings + 1) + 12 B triangles, laid out in the order above.
struct StationModuleParams {
  double radius = 1.0;       ///< hull radius, > 0
  double length = 4.0;       ///< hull length along z, > 0
  int segments = 48;         ///< resolution around z of the hull and the port, >= 3
  int rings = 16;            ///< subdivisions along z of the hull and of the port, >= 1
  double port_radius = 0.4;  ///< docking port radius, > 0 and < radius
  double port_length = 0.5;  ///< how far the port sticks out beyond the hull, > 0 and <= length
  int truss_bays = 8;        ///< bays of the truss along the hull, >= 1 and <= 10 L / R (a
                             ///< bay at least two beam thicknesses long)
  double panel_span = 3.0;   ///< length of each solar panel along x, > 0
  double panel_width = 1.0;  ///< width of each solar panel along z, > 0
};

/// A cylinder around the z axis from z = -height / 2 to +height / 2: a shaft, a pin or a bolt's
/// shank, or with inner_radius > 0 a tube (a pipe, a spacer, a washer, a round nut). `segments`
/// vertices per circle at angle 2 pi i / segments from +x towards +y, so two cylinders of the
/// same segments and radius share their side facets' planes (a nut's bore on a shank), and with
/// segments a multiple of 4 the extremes on x and y are vertices.
/// Solid: the bottom circle, the top circle, then the bottom and top cap centres (2 segments + 2
/// vertices; 4 segments triangles: side quads, then the caps fanned from their centres).
/// Tube: the outer bottom and top circles, then the inner ones (4 segments vertices; 8 segments
/// triangles: outer wall, inner wall, then the bottom and top annuli).
struct CylinderParams {
  double radius = 0.5;        ///< outer radius, > 0
  double height = 1.0;        ///< length along z, > 0
  int segments = 32;          ///< vertices per circle, >= 3
  double inner_radius = 0.0;  ///< 0 for a solid cylinder, else the bore: in (0, radius)
};

/// A pipe flange: an annular plate of the given thickness around the z axis (z from
/// -thickness / 2 to +thickness / 2) with a central bore and `bolt_holes` round holes whose
/// centres lie on the bolt circle, hole k at angle 2 pi k / bolt_holes from +x. The plate is cut
/// into one sector per hole (between the angles of the hole's centre +- pi / bolt_holes); each
/// sector's outline (arc_segments chords of the rim, radial_segments steps down its edge,
/// arc_segments chords of the bore, radial_segments steps up its other edge: M = 2 (arc_segments
/// + radial_segments) points) is joined to its hole by quads, each hole point on the ray from
/// the hole's centre through its outline point. So the faces z = +-thickness / 2 are exactly
/// flat, the rim and the bore are bolt_holes * arc_segments-gons, and a hole is an M-gon
/// inscribed in its circle. Per face: the rim circle, the bore circle (bolt_holes *
/// arc_segments each, the first vertex of both at angle -pi / bolt_holes), the inner points of
/// the sector edges (bolt_holes (radial_segments - 1)), the holes (bolt_holes * M); bottom face
/// first. 6 bolt_holes M + 4 bolt_holes arc_segments triangles: the top face, the bottom face,
/// the rim wall, the bore wall, the hole walls. A closed surface of genus bolt_holes + 1.
/// Each hole must lie inside its sector, which must be visible from the hole's centre
/// (bore_radius < bolt_circle_radius cos(pi / bolt_holes)); the generator says which bound a
/// parameter breaks.
struct FlangeParams {
  double outer_radius = 1.0;         ///< rim, > bolt_circle_radius
  double bore_radius = 0.5;          ///< > 0
  double thickness = 0.25;           ///< > 0
  int bolt_holes = 6;                ///< >= 3
  double bolt_circle_radius = 0.75;  ///< between the bore and the rim
  double hole_radius = 0.08;         ///< > 0, the hole inside its sector
  int arc_segments = 4;              ///< chords of the rim and of the bore per sector, >= 1
  int radial_segments = 2;           ///< steps along each sector edge, >= 1
};

/// An axis-aligned box about the origin: 8 vertices (corner (i, j, k) at column i + 2 j + 4 k,
/// coordinates +-size / 2), 12 outward triangles.
struct BoxParams {
  Eigen::Vector3d size = Eigen::Vector3d::Ones();  ///< full side lengths, each > 0
};

/// The number of triangles each generator makes from `params`, computed in double so that a huge
/// resolution cannot overflow, and without generating anything: a scene load charges it to its
/// triangle limit first. The generators hold themselves to the same count (at most 50 million).
/// Meaningful for parameters the generator accepts.
double triangleCount(const TorusParams& params);
double triangleCount(const ChainParams& params);
double triangleCount(const SphereParams& params);
double triangleCount(const BoxParams& params);
double triangleCount(const CylinderParams& params);
double triangleCount(const FlangeParams& params);
double triangleCount(const GridSheetParams& params);
double triangleCount(const GearParams& params);
double triangleCount(const StationModuleParams& params);

/// Generators. Each checks its parameters and returns kInvalidArgument naming the bad one.
Result<TriangleMesh> makeTorus(const TorusParams& params);
Result<TriangleMesh> makeChain(const ChainParams& params);
Result<TriangleMesh> makeSphere(const SphereParams& params);
Result<TriangleMesh> makeBox(const BoxParams& params);
Result<TriangleMesh> makeCylinder(const CylinderParams& params);
Result<TriangleMesh> makeFlange(const FlangeParams& params);
Result<TriangleMesh> makeGridSheet(const GridSheetParams& params);
Result<TriangleMesh> makeGear(const GearParams& params);
Result<TriangleMesh> makeStationModule(const StationModuleParams& params);

}  // namespace collido
