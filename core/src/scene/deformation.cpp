#include <collido/scene/deformation.h>

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

namespace collido {
namespace {

constexpr double kTwoPi = 6.283185307179586476925286766559;

// SplitMix64: a fixed, platform-independent hash, so a seed gives the same noise everywhere.
std::uint64_t mix(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

// A number in [0, 1) from a hash.
double unit(std::uint64_t h) {
  return static_cast<double>(h >> 11) * (1.0 / 9007199254740992.0);
}

// Vertex normals of the rest mesh: the area-weighted sum of the faces' normals, unit length (a
// vertex of no face, or whose faces cancel, gets none).
Eigen::Matrix3Xd vertexNormals(const TriangleMesh& mesh) {
  Eigen::Matrix3Xd normals = Eigen::Matrix3Xd::Zero(3, mesh.vertices.cols());
  for (Eigen::Index t = 0; t < mesh.triangles.cols(); ++t) {
    const Eigen::Vector3d a = mesh.vertices.col(mesh.triangles(0, t));
    const Eigen::Vector3d b = mesh.vertices.col(mesh.triangles(1, t));
    const Eigen::Vector3d c = mesh.vertices.col(mesh.triangles(2, t));
    const Eigen::Vector3d n = (b - a).cross(c - a);  // twice the area, along the normal
    for (int k = 0; k < 3; ++k)
      normals.col(mesh.triangles(k, t)) += n;
  }
  for (Eigen::Index v = 0; v < normals.cols(); ++v) {
    const double length = normals.col(v).norm();
    normals.col(v) =
        length > 0.0 ? Eigen::Vector3d(normals.col(v) / length) : Eigen::Vector3d::Zero();
  }
  return normals;
}

// `direction` without its part along unit `axis`, unit length (the axis's own perpendicular
// when nothing is left).
Eigen::Vector3d across(const Eigen::Vector3d& axis, const Eigen::Vector3d& direction) {
  Eigen::Vector3d d = direction - direction.dot(axis) * axis;
  if (d.norm() < 1e-12) d = axis.unitOrthogonal();
  return d.normalized();
}

Eigen::Vector3d bent(const DeformationRule& rule, double theta, const Eigen::Vector3d& d,
                     const Eigen::Vector3d& p) {
  const Eigen::Vector3d& u = rule.axis;
  const Eigen::Vector3d rel = p - rule.origin;
  const double s = rel.dot(u);
  if (s <= 0.0 || theta == 0.0) return p;
  const double h = rel.dot(d);
  const Eigen::Vector3d rest = rel - s * u - h * d;
  const double radius = rule.length / theta;  // signed: the centre lies at h = radius
  const double on_arc = std::min(s, rule.length);
  const double phi = on_arc / radius;
  Eigen::Vector3d out = rule.origin + rest + (radius - h) * std::sin(phi) * u +
                        (radius - (radius - h) * std::cos(phi)) * d;
  if (s > rule.length) out += (s - rule.length) * (std::cos(theta) * u + std::sin(theta) * d);
  return out;
}

void applyRule(const DeformationRule& rule, const TriangleMesh& rest, std::size_t frame,
               std::size_t frames, const std::vector<char>& moves, Eigen::Matrix3Xd& positions) {
  const double factor = rule.timing.factor(frame, frames);
  const auto each = [&](auto&& move) {
    for (Eigen::Index v = 0; v < positions.cols(); ++v) {
      if (moves[static_cast<std::size_t>(v)] != 0) positions.col(v) = move(v, positions.col(v));
    }
  };
  switch (rule.kind) {
    case DeformationRule::Kind::kNoise: {
      const double period = rule.timing.period > 0.0
                                ? rule.timing.period
                                : static_cast<double>(std::max<std::size_t>(frames, 1));
      each([&](Eigen::Index v, const Eigen::Vector3d& p) {
        const std::uint64_t h = mix(rule.seed ^ mix(static_cast<std::uint64_t>(v)));
        // A uniform direction on the sphere, and a phase, from the vertex's own hashes.
        const double z = 2.0 * unit(mix(h + 1)) - 1.0;
        const double azimuth = kTwoPi * unit(mix(h + 2));
        const double ring = std::sqrt(std::max(0.0, 1.0 - z * z));
        const Eigen::Vector3d dir(ring * std::cos(azimuth), ring * std::sin(azimuth), z);
        const double phase = unit(mix(h + 3)) + rule.timing.phase;
        const double wave = std::sin(kTwoPi * (static_cast<double>(frame) / period + phase));
        return Eigen::Vector3d(p + rule.amplitude * wave * dir);
      });
      break;
    }
    case DeformationRule::Kind::kWave: {
      const double period = rule.timing.period > 0.0
                                ? rule.timing.period
                                : static_cast<double>(std::max<std::size_t>(frames, 1));
      const double travel = static_cast<double>(frame) / period - rule.timing.phase;
      each([&](Eigen::Index, const Eigen::Vector3d& p) {
        const double x = (p - rule.origin).dot(rule.along) / rule.wavelength;
        return Eigen::Vector3d(p +
                               rule.amplitude * std::sin(kTwoPi * (x - travel)) * rule.direction);
      });
      break;
    }
    case DeformationRule::Kind::kTwist: {
      const double per_length = rule.angle * factor / rule.length;
      each([&](Eigen::Index, const Eigen::Vector3d& p) {
        const Eigen::Vector3d rel = p - rule.origin;
        const Eigen::AngleAxisd turn(per_length * rel.dot(rule.axis), rule.axis);
        return Eigen::Vector3d(rule.origin + turn * rel);
      });
      break;
    }
    case DeformationRule::Kind::kPulsate: {
      const Eigen::Matrix3Xd normals = vertexNormals(rest);
      const double offset = rule.amplitude * factor;
      each([&](Eigen::Index v, const Eigen::Vector3d& p) {
        return Eigen::Vector3d(p + offset * normals.col(v));
      });
      break;
    }
    case DeformationRule::Kind::kBend: {
      const Eigen::Vector3d d = across(rule.axis, rule.direction);
      const double theta = rule.angle * factor;
      each([&](Eigen::Index, const Eigen::Vector3d& p) { return bent(rule, theta, d, p); });
      break;
    }
    case DeformationRule::Kind::kDrape: {
      const double fallen = rule.amplitude * factor;
      each([&](Eigen::Index v, const Eigen::Vector3d& p) {
        const double stop = (*rule.stops)[static_cast<std::size_t>(v)] + rule.penetration;
        return Eigen::Vector3d(p + std::min(fallen, stop) * rule.direction);
      });
      break;
    }
    case DeformationRule::Kind::kSquash: {
      const double along = 1.0 - rule.amount * factor;
      const double side = 1.0 / std::sqrt(along);
      each([&](Eigen::Index, const Eigen::Vector3d& p) {
        const Eigen::Vector3d rel = p - rule.origin;
        const double s = rel.dot(rule.axis);
        return Eigen::Vector3d(rule.origin + along * s * rule.axis + side * (rel - s * rule.axis));
      });
      break;
    }
  }
}

}  // namespace

double DeformationTiming::factor(std::size_t frame, std::size_t frames) const {
  if (period > 0.0) return std::sin(kTwoPi * (static_cast<double>(frame) / period + phase));
  if (frames <= 1) return 0.0;
  return static_cast<double>(std::min(frame, frames - 1)) / static_cast<double>(frames - 1);
}

Eigen::Map<const Eigen::Matrix3Xd> RecordedPositions::frame(std::size_t f) const {
  const std::size_t k = frames == 0 ? 0 : std::min(f, frames - 1);
  return {values.data() + 3 * vertices * k, 3, static_cast<Eigen::Index>(vertices)};
}

Eigen::Matrix3Xd Deformation::positionsAt(const TriangleMesh& rest, std::size_t frame) const {
  Eigen::Matrix3Xd positions = recorded ? Eigen::Matrix3Xd(recorded->frame(frame)) : rest.vertices;
  std::vector<char> moves(static_cast<std::size_t>(positions.cols()));
  for (Eigen::Index v = 0; v < positions.cols(); ++v) {
    const auto p = positions.col(v);
    moves[static_cast<std::size_t>(v)] =
        (p.array() >= select_low.array()).all() && (p.array() <= select_high.array()).all();
  }
  for (const DeformationRule& rule : rules)
    applyRule(rule, rest, frame, frames, moves, positions);
  return positions;
}

}  // namespace collido
