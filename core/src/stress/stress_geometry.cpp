#include "stress_geometry.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace collido::stress::detail {

Eigen::Vector3d Rng::dyadicVector(double bound, int denominator) {
  Eigen::Vector3d v;
  for (int i = 0; i < 3; ++i)
    v[i] = dyadic(-bound, bound, denominator);
  return v;
}

Eigen::Vector3d Rng::uniformVector(double low, double high) {
  Eigen::Vector3d v;
  for (int i = 0; i < 3; ++i)
    v[i] = uniform(low, high);
  return v;
}

int MeshBuilder::vertex(const Eigen::Vector3d& p) {
  vertices_.push_back(p);
  return static_cast<int>(vertices_.size()) - 1;
}

void MeshBuilder::triangle(int i, int j, int k) {
  triangles_.emplace_back(i, j, k);
}

void MeshBuilder::append(const TriangleMesh& mesh) {
  const int offset = static_cast<int>(vertices_.size());
  for (Eigen::Index v = 0; v < mesh.vertices.cols(); ++v)
    vertices_.push_back(mesh.vertices.col(v));
  for (Eigen::Index t = 0; t < mesh.triangles.cols(); ++t)
    triangles_.push_back(mesh.triangles.col(t).array() + offset);
}

TriangleMesh MeshBuilder::build() const {
  TriangleMesh mesh;
  mesh.vertices.resize(3, static_cast<Eigen::Index>(vertices_.size()));
  for (std::size_t i = 0; i < vertices_.size(); ++i)
    mesh.vertices.col(static_cast<Eigen::Index>(i)) = vertices_[i];
  mesh.triangles.resize(3, static_cast<Eigen::Index>(triangles_.size()));
  for (std::size_t i = 0; i < triangles_.size(); ++i)
    mesh.triangles.col(static_cast<Eigen::Index>(i)) = triangles_[i];
  return mesh;
}

void orientOutward(TriangleMesh& mesh) {
  const Eigen::Vector3d centre = mesh.vertices.rowwise().mean();
  for (Eigen::Index t = 0; t < mesh.triangles.cols(); ++t) {
    const Eigen::Vector3d p = mesh.vertices.col(mesh.triangles(0, t));
    const Eigen::Vector3d q = mesh.vertices.col(mesh.triangles(1, t));
    const Eigen::Vector3d r = mesh.vertices.col(mesh.triangles(2, t));
    if ((q - p).cross(r - p).dot((p + q + r) / 3.0 - centre) < 0.0) {
      std::swap(mesh.triangles(1, t), mesh.triangles(2, t));
    }
  }
}

TriangleMesh boxMesh(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  MeshBuilder builder;
  for (int i = 0; i < 8; ++i) {
    builder.vertex({(i & 1) != 0 ? hi.x() : lo.x(), (i & 2) != 0 ? hi.y() : lo.y(),
                    (i & 4) != 0 ? hi.z() : lo.z()});
  }
  // Two triangles per face, corners by bit pattern (x = 1, y = 2, z = 4).
  const std::array<std::array<int, 4>, 6> faces = {
      {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}}};
  for (const auto& f : faces) {
    builder.triangle(f[0], f[1], f[2]);
    builder.triangle(f[0], f[2], f[3]);
  }
  TriangleMesh mesh = builder.build();
  orientOutward(mesh);
  return mesh;
}

TriangleMesh ridgePrism(const Eigen::Vector3d& centre, const Eigen::Vector2d& d, double half_length,
                        double half_width, double base_z) {
  const Eigen::Vector3d along(d.x() * half_length, d.y() * half_length, 0.0);
  const Eigen::Vector3d across(-d.y() * half_width, d.x() * half_width, 0.0);
  const Eigen::Vector3d base(centre.x(), centre.y(), base_z);
  MeshBuilder builder;
  const int r0 = builder.vertex(centre - along);
  const int r1 = builder.vertex(centre + along);
  const int b00 = builder.vertex(base - along - across);
  const int b01 = builder.vertex(base - along + across);
  const int b10 = builder.vertex(base + along - across);
  const int b11 = builder.vertex(base + along + across);
  builder.triangle(r0, b00, b01);  // end caps
  builder.triangle(r1, b11, b10);
  builder.triangle(r0, r1, b10);  // slanted sides
  builder.triangle(r0, b10, b00);
  builder.triangle(r0, b01, b11);
  builder.triangle(r0, b11, r1);
  builder.triangle(b00, b10, b11);  // base
  builder.triangle(b00, b11, b01);
  TriangleMesh mesh = builder.build();
  orientOutward(mesh);
  return mesh;
}

TriangleMesh pyramid(const Eigen::Vector3d& apex, double half_width, double base_z) {
  MeshBuilder builder;
  const int top = builder.vertex(apex);
  std::array<int, 4> corner{};
  const std::array<std::array<double, 2>, 4> signs = {{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}};
  for (int i = 0; i < 4; ++i) {
    corner[static_cast<std::size_t>(i)] =
        builder.vertex({apex.x() + signs[static_cast<std::size_t>(i)][0] * half_width,
                        apex.y() + signs[static_cast<std::size_t>(i)][1] * half_width, base_z});
  }
  for (std::size_t i = 0; i < 4; ++i)
    builder.triangle(top, corner[i], corner[(i + 1) % 4]);
  builder.triangle(corner[0], corner[2], corner[1]);
  builder.triangle(corner[0], corner[3], corner[2]);
  TriangleMesh mesh = builder.build();
  orientOutward(mesh);
  return mesh;
}

TriangleMesh gridPlate(double x0, double x1, double y0, double y1, double z, int cells_x,
                       int cells_y) {
  MeshBuilder builder;
  for (int j = 0; j <= cells_y; ++j) {
    for (int i = 0; i <= cells_x; ++i) {
      // Endpoints exactly as given; interior lines by interpolation.
      const double x = i == cells_x ? x1 : x0 + (x1 - x0) * i / cells_x;
      const double y = j == cells_y ? y1 : y0 + (y1 - y0) * j / cells_y;
      builder.vertex({x, y, z});
    }
  }
  const auto at = [cells_x](int i, int j) { return j * (cells_x + 1) + i; };
  for (int j = 0; j < cells_y; ++j) {
    for (int i = 0; i < cells_x; ++i) {
      builder.triangle(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      builder.triangle(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  }
  return builder.build();
}

TriangleMesh singleTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& q,
                            const Eigen::Vector3d& r) {
  MeshBuilder builder;
  builder.triangle(builder.vertex(p), builder.vertex(q), builder.vertex(r));
  return builder.build();
}

Eigen::Matrix3d signedPermutation(int index) {
  // The 48 signed permutation matrices in a fixed order, keeping the 24 with determinant +1.
  static const std::vector<Eigen::Matrix3d> rotations = [] {
    std::vector<Eigen::Matrix3d> out;
    std::array<int, 3> perm = {0, 1, 2};
    do {
      for (int signs = 0; signs < 8; ++signs) {
        Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
        for (int row = 0; row < 3; ++row) {
          m(row, perm[static_cast<std::size_t>(row)]) = ((signs >> row) & 1) != 0 ? -1.0 : 1.0;
        }
        if (m.determinant() > 0.0) out.push_back(m);
      }
    } while (std::next_permutation(perm.begin(), perm.end()));
    return out;
  }();
  return rotations[static_cast<std::size_t>(index) % rotations.size()];
}

Eigen::Matrix3d rotationAbout(int axis, double angle) {
  const double c = std::cos(angle);
  const double s = std::sin(angle);
  const int u = (axis + 1) % 3;
  const int v = (axis + 2) % 3;
  Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
  m(axis, axis) = 1.0;
  m(u, u) = c;
  m(u, v) = -s;
  m(v, u) = s;
  m(v, v) = c;
  return m;
}

void transformVertices(TriangleMesh& mesh, const Eigen::Matrix3d& linear,
                       const Eigen::Vector3d& translation) {
  for (Eigen::Index v = 0; v < mesh.vertices.cols(); ++v)
    mesh.vertices.col(v) = linear * mesh.vertices.col(v) + translation;
}

Pose makePose(const Eigen::Matrix3d& rotation, const Eigen::Vector3d& translation) {
  Pose pose = Pose::Identity();
  pose.linear() = rotation;
  pose.translation() = translation;
  return pose;
}

Placed placeShared(TriangleMesh a, TriangleMesh b, const Pose& pose) {
  Placed out;
  out.a = std::move(a);
  out.b = std::move(b);
  out.pose_a = pose;
  out.pose_b = pose;
  return out;
}

Placed placeDistinct(TriangleMesh a, TriangleMesh b, const Pose& pose_a, Rng& rng) {
  const Eigen::Matrix3d p = signedPermutation(rng.integer(0, 23));
  const Eigen::Vector3d t = rng.dyadicVector(2.0, 8);
  transformVertices(b, Eigen::Matrix3d::Identity(), -t);
  transformVertices(b, p.transpose(), Eigen::Vector3d::Zero());
  Placed out;
  out.a = std::move(a);
  out.b = std::move(b);
  out.pose_a = pose_a;
  out.pose_b = pose_a * makePose(p, t);
  out.exact = false;
  return out;
}

Placed place(Placement placement, TriangleMesh a, TriangleMesh b, Rng& rng) {
  switch (placement) {
    case Placement::kIdentity:
      return placeShared(std::move(a), std::move(b), Pose::Identity());
    case Placement::kExactShared: {
      const Eigen::Matrix3d rotation = signedPermutation(rng.integer(0, 23));
      const Eigen::Vector3d translation = rng.dyadicVector(4.0, 8);
      return placeShared(std::move(a), std::move(b), makePose(rotation, translation));
    }
    case Placement::kExactDistinct: {
      // Model = P^T · contact frame: a signed permutation of the coordinates, exact for any
      // doubles, so pose · model gives back the contact frame exactly.
      const Eigen::Matrix3d pa = signedPermutation(rng.integer(0, 23));
      const Eigen::Matrix3d pb = signedPermutation(rng.integer(0, 23));
      transformVertices(a, pa.transpose(), Eigen::Vector3d::Zero());
      transformVertices(b, pb.transpose(), Eigen::Vector3d::Zero());
      Placed out;
      out.a = std::move(a);
      out.b = std::move(b);
      out.pose_a = makePose(pa, Eigen::Vector3d::Zero());
      out.pose_b = makePose(pb, Eigen::Vector3d::Zero());
      return out;
    }
    case Placement::kGenericShared: {
      const Eigen::Matrix3d rotation = rng.rotation();
      const Eigen::Vector3d translation = rng.uniformVector(-2.0, 2.0);
      return placeShared(std::move(a), std::move(b), makePose(rotation, translation));
    }
    case Placement::kGenericDistinct: {
      const Eigen::Matrix3d rotation = rng.rotation();
      const Eigen::Vector3d translation = rng.uniformVector(-2.0, 2.0);
      return placeDistinct(std::move(a), std::move(b), makePose(rotation, translation), rng);
    }
  }
  return placeShared(std::move(a), std::move(b), Pose::Identity());
}

}  // namespace collido::stress::detail
