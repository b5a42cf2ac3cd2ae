#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <collido/geometry.h>
#include <collido/mesh/triangle_mesh.h>
#include <collido/query.h>

namespace collido {

/// A contacts answer held to the exact reference (docs/DESIGN.md, "Contact geometry"). Each
/// contact is compared with the reference contact of the pair it names, or, when it names none
/// (or only one triangle), of the intersecting pair whose set lies nearest its point. Errors are
/// maxima over the contacts; unset where nothing was there to measure.
struct ContactScore {
  std::size_t contacts = 0;     ///< contacts reported
  std::size_t false_pairs = 0;  ///< contacts naming a pair that does not intersect
  std::size_t bad_normals = 0;  ///< normals not unit length within 1e-6, or not finite
  std::size_t bad_depths = 0;   ///< negative or not finite depths
  /// Contacts whose point lies farther from their pair's exact set than rounding allows (1e-10
  /// of the largest posed coordinate, as for distances), or that stand for no pair at all.
  std::size_t off_set = 0;
  /// Distance of a contact point to the exact intersection set of its pair.
  std::optional<double> position_error;
  /// Distance of a contact point to the farther of its pair's two triangles.
  std::optional<double> surface_error;
  /// Angle (degrees) between a normal and the face normal it is nearest (n_A or -n_B).
  std::optional<double> normal_error_deg;
  /// |depth - the reference depth along that face|.
  std::optional<double> depth_error;
  /// Share of the exact intersection curve whose pairs some contact stands for (each pair
  /// weighted by its set's length; by count where every set is a point); unset when the meshes
  /// do not meet.
  std::optional<double> coverage;
  double covered_length = 0.0;  ///< the parts of `coverage`, kept so frames can be summed
  double total_length = 0.0;

  /// Folds another object pair's score into this one (a group query's frame).
  void add(const ContactScore& other);
  /// Whether any contact is wrong by the definition: naming a pair that does not meet, off its
  /// pair's set, with a non-unit normal or a negative depth.
  bool anyWrong() const { return false_pairs + off_set + bad_normals + bad_depths != 0; }
};

/// Scores `contacts` for meshes a, b posed by pose_a, pose_b whose exact intersecting pairs are
/// `exact_pairs` (sorted, as the oracle gives them).
ContactScore scoreContacts(const TriangleMesh& a, const Pose& pose_a, const TriangleMesh& b,
                           const Pose& pose_b, const std::vector<TrianglePair>& exact_pairs,
                           const std::vector<Contact>& contacts);

/// One line for people: "240 contacts; points within 1.2e-16 of the exact set ...".
std::string contactScoreText(const ContactScore& score);

}  // namespace collido
