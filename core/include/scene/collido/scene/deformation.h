#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include <collido/mesh/triangle_mesh.h>
#include <collido/status.h>

namespace collido {

/// How a rule's strength follows the frames: a sine of the frame's phase, or a ramp.
struct DeformationTiming {
  /// Frames per cycle of sin(2 pi (f / period + phase)); 0: a ramp instead, f / (frames - 1)
  /// from 0 at the first frame to 1 at the last (0 throughout with one frame).
  double period = 0.0;
  double phase = 0.0;  ///< in cycles, for the sine

  /// The factor in [-1, 1] (sine) or [0, 1] (ramp) of frame `frame` of `frames`.
  double factor(std::size_t frame, std::size_t frames) const;
};

/// One rule that moves vertices, in the object's own frame, each frame. Every rule is a pure
/// function of the rest positions (the active state's), the frame and its parameters: frames
/// can be computed in any order, and repeated frames give identical positions.
struct DeformationRule {
  enum class Kind {
    kNoise,    ///< each vertex along its own random unit direction by amplitude * sin(2 pi (f /
               ///< period + its own random phase)): uncorrelated jitter, smooth in time
    kWave,     ///< along `direction` by amplitude * factor * sin(2 pi (x . along) / wavelength -
               ///< 2 pi f / period): a wave travelling along `along`
    kTwist,    ///< about the line (origin, axis) by angle * factor * s / length, s = the
               ///< vertex's coordinate along the axis from the origin
    kPulsate,  ///< along the rest mesh's vertex normal by amplitude * factor
    kBend,     ///< the span [0, length] along `axis` from `origin` bent towards `direction` into
               ///< a circular arc of total angle angle * factor (points beyond length follow
               ///< the arc's end rigidly)
    kSquash,   ///< scaled about `origin` by 1 - amount * factor along `axis` and by
               ///< 1 / sqrt(1 - amount * factor) across it (volume kept)
    kDrape,    ///< along `direction` by min(amplitude * factor, stop + penetration): falls
               ///< until it meets another object (its stop distance), then sinks `penetration`
               ///< into it and stays; a sheet settling onto a shape
  };
  Kind kind = Kind::kNoise;
  DeformationTiming timing;
  double amplitude = 0.0;    ///< noise, wave, pulsate: a length
  double wavelength = 1.0;   ///< wave: > 0
  double angle = 0.0;        ///< twist, bend: radians
  double length = 1.0;       ///< twist, bend: > 0
  double amount = 0.0;       ///< squash: in [0, 1)
  double penetration = 0.0;  ///< drape: how far past the surface a vertex comes to rest, >= 0
  /// drape: per vertex of the rest shape, the distance along `direction` to the surface it
  /// lands on (infinity where it meets none), computed when the scene is read.
  std::shared_ptr<const std::vector<double>> stops;
  std::uint64_t seed = 1;  ///< noise
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();       ///< twist, bend, squash: unit
  Eigen::Vector3d along = Eigen::Vector3d::UnitX();      ///< wave: unit
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();  ///< wave, bend, drape: unit (bend:
                                                         ///< across the axis)
};

/// Every position of a deforming object, frame by frame, from a recording (format: scenes/
/// README.md, "Recorded positions"): frames x vertices x 3 doubles.
struct RecordedPositions {
  std::size_t vertices = 0;
  std::size_t frames = 0;
  std::vector<double> values;  ///< frame-major, then vertex, then x, y, z

  /// Frame `frame`'s positions (frames past the last repeat it).
  Eigen::Map<const Eigen::Matrix3Xd> frame(std::size_t frame) const;
};

/// Reads a recording; errors name the file and what is wrong (magic, version, sizes, a
/// non-finite value with its frame and vertex).
Result<RecordedPositions> readRecordedPositions(const std::string& path);
/// Writes a recording (little-endian, as readRecordedPositions reads it).
Status writeRecordedPositions(const std::string& path, const RecordedPositions& recording);

/// Movable nodes: which vertices move and how. The recording (when given) replaces the rest
/// positions, then the rules apply in order to the selected vertices; the others keep their
/// rest (or recorded) positions.
struct Deformation {
  std::vector<DeformationRule> rules;
  std::shared_ptr<const RecordedPositions> recorded;  ///< may be empty
  /// Selection: the vertices whose rest (or recorded) positions lie in this box move.
  Eigen::Vector3d select_low = Eigen::Vector3d::Constant(-std::numeric_limits<double>::infinity());
  Eigen::Vector3d select_high = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());

  std::size_t frames = 1;  ///< the scene's frames (a ramp runs over them)

  /// The positions of `rest`'s vertices in frame `frame`.
  Eigen::Matrix3Xd positionsAt(const TriangleMesh& rest, std::size_t frame) const;
};

}  // namespace collido
