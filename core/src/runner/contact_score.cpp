// Contacts against the exact reference, per docs/DESIGN.md's "Contact geometry".
#include <collido/runner/contact_score.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include <collido/oracle/contact_reference.h>
#include <collido/oracle/exact_oracle.h>
#include <collido/runner/text_table.h>

namespace collido {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A NaN figure stays visible: it is a finding, not a zero.
void raise(std::optional<double>& maximum, double value) {
  if (!maximum || std::isnan(value) || value > *maximum) maximum = value;
}

double angleDegrees(const Eigen::Vector3d& u, const Eigen::Vector3d& v) {
  // atan2 of |u x v| and u.v stays accurate near 0 and 180 degrees, where acos does not.
  return std::atan2(u.cross(v).norm(), u.dot(v)) * 180.0 / kPi;
}

bool inRange(std::int32_t t, const TriangleMesh& mesh) {
  return t >= 0 && static_cast<std::size_t>(t) < mesh.triangleCount();
}

}  // namespace

void ContactScore::add(const ContactScore& other) {
  contacts += other.contacts;
  false_pairs += other.false_pairs;
  bad_normals += other.bad_normals;
  bad_depths += other.bad_depths;
  off_set += other.off_set;
  for (auto [mine, theirs] : {std::pair{&position_error, &other.position_error},
                              std::pair{&surface_error, &other.surface_error},
                              std::pair{&normal_error_deg, &other.normal_error_deg},
                              std::pair{&depth_error, &other.depth_error}}) {
    if (*theirs) raise(*mine, **theirs);
  }
  covered_length += other.covered_length;
  total_length += other.total_length;
  if (coverage || other.coverage) {
    coverage = total_length > 0.0 ? covered_length / total_length
                                  : std::min(coverage.value_or(1.0), other.coverage.value_or(1.0));
  }
}

ContactScore scoreContacts(const TriangleMesh& a, const Pose& pose_a, const TriangleMesh& b,
                           const Pose& pose_b, const std::vector<TrianglePair>& exact_pairs,
                           const std::vector<Contact>& contacts) {
  ContactScore score;
  score.contacts = contacts.size();
  if (contacts.empty() && exact_pairs.empty()) return score;
  const double rounding = 1e-10 * std::max((pose_a * a.vertices).cwiseAbs().maxCoeff(),
                                           (pose_b * b.vertices).cwiseAbs().maxCoeff());
  std::vector<PairContact> reference;
  reference.reserve(exact_pairs.size());
  for (const TrianglePair& pair : exact_pairs)
    reference.push_back(exactPairContact(a, pose_a, b, pose_b, pair));
  std::vector<bool> covered(exact_pairs.size(), false);

  for (const Contact& c : contacts) {
    if (!c.normal.allFinite() || std::abs(c.normal.norm() - 1.0) > 1e-6) ++score.bad_normals;
    if (!std::isfinite(c.depth) || c.depth < 0.0) ++score.bad_depths;
    if (!c.position.allFinite()) {
      ++score.off_set;
      continue;
    }
    // The pair it stands for: the one it names, else the nearest intersecting one.
    std::optional<std::size_t> index;
    PairContact named;
    const PairContact* ref = nullptr;
    if (inRange(c.triangle_a, a) && inRange(c.triangle_b, b)) {
      const TrianglePair pair{c.triangle_a, c.triangle_b};
      const auto it = std::lower_bound(exact_pairs.begin(), exact_pairs.end(), pair);
      if (it != exact_pairs.end() && *it == pair) {
        index = static_cast<std::size_t>(it - exact_pairs.begin());
      } else {
        ++score.false_pairs;
        named = exactPairContact(a, pose_a, b, pose_b, pair);
        ref = &named;
      }
    } else {
      double nearest = std::numeric_limits<double>::infinity();
      for (std::size_t i = 0; i < reference.size(); ++i) {
        const double d = distanceToIntersection(reference[i].set, c.position);
        if (d < nearest) {
          nearest = d;
          index = i;
        }
      }
    }
    if (index) {
      covered[*index] = true;
      ref = &reference[*index];
    }
    if (ref == nullptr) {  // the meshes do not meet: a contact stands for nothing
      ++score.off_set;
      continue;
    }
    const TrianglePair pair =
        index ? exact_pairs[*index] : TrianglePair{c.triangle_a, c.triangle_b};
    if (index) {
      const double off = distanceToIntersection(ref->set, c.position);
      raise(score.position_error, off);
      if (!(off <= rounding)) ++score.off_set;
    }
    const std::array<Eigen::Vector3d, 3> ta = posedTriangle(a, pose_a, pair.a);
    const std::array<Eigen::Vector3d, 3> tb = posedTriangle(b, pose_b, pair.b);
    raise(score.surface_error,
          std::max(distanceToTriangle(c.position, ta), distanceToTriangle(c.position, tb)));
    const ContactFrame& frame = ref->frame;
    if (frame.owner == NormalOwner::kNone || !c.normal.allFinite() || c.normal.norm() == 0.0)
      continue;
    const double to_a = frame.normal_a ? angleDegrees(c.normal, *frame.normal_a) : 180.0;
    const double to_b = frame.normal_b ? angleDegrees(c.normal, *frame.normal_b) : 180.0;
    raise(score.normal_error_deg, std::min(to_a, to_b));
    if (std::isfinite(c.depth)) {
      const double reference_depth = to_a <= to_b ? frame.depth_a : frame.depth_b;
      raise(score.depth_error, std::abs(c.depth - reference_depth));
    }
  }

  double weights = 0.0;
  double covered_weights = 0.0;
  for (std::size_t i = 0; i < reference.size(); ++i) {
    const double w = intersectionLength(reference[i].set);
    weights += w;
    if (covered[i]) covered_weights += w;
  }
  if (!reference.empty()) {
    if (weights > 0.0) {
      score.total_length = weights;
      score.covered_length = covered_weights;
      score.coverage = covered_weights / weights;
    } else {
      const auto count = static_cast<double>(std::count(covered.begin(), covered.end(), true));
      score.coverage = count / static_cast<double>(reference.size());
    }
  }
  return score;
}

std::string contactScoreText(const ContactScore& score) {
  const auto figure = [](const std::optional<double>& value) {
    return value ? formatNumber("%.3g", *value) : std::string("-");
  };
  std::string text = std::to_string(score.contacts) + " contacts; points within " +
                     figure(score.position_error) + " of the exact set and " +
                     figure(score.surface_error) + " of both triangles; normals within " +
                     figure(score.normal_error_deg) + " deg of a face normal; depths within " +
                     figure(score.depth_error) + "; coverage " +
                     (score.coverage ? formatNumber("%.1f", 100.0 * *score.coverage) + "%" : "-");
  if (score.false_pairs != 0)
    text += "; " + std::to_string(score.false_pairs) + " name a pair that does not meet";
  if (score.bad_normals != 0) text += "; " + std::to_string(score.bad_normals) + " bad normals";
  if (score.bad_depths != 0) text += "; " + std::to_string(score.bad_depths) + " bad depths";
  if (score.off_set != 0)
    text += "; " + std::to_string(score.off_set) + " off their exact set beyond rounding";
  return text;
}

}  // namespace collido
