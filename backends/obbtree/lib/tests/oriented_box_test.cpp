#include <cmath>
#include <random>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <collido/obbtree/oriented_box.h>

namespace collido::obbtree {
namespace {

struct Soup {
  Eigen::Matrix3Xd vertices;
  Eigen::Matrix3Xi triangles;
  std::vector<std::int32_t> order;
};

// A closed box mesh with half sizes (hx, hy, hz), rotated and moved.
Soup boxMesh(const Eigen::Vector3d& half, const Eigen::Matrix3d& rotation,
             const Eigen::Vector3d& offset) {
  Soup s;
  s.vertices.resize(3, 8);
  for (int i = 0; i < 8; ++i) {
    const Eigen::Vector3d corner((i & 1) ? half.x() : -half.x(), (i & 2) ? half.y() : -half.y(),
                                 (i & 4) ? half.z() : -half.z());
    s.vertices.col(i) = rotation * corner + offset;
  }
  const int faces[12][3] = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                            {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  s.triangles.resize(3, 12);
  for (int f = 0; f < 12; ++f)
    s.triangles.col(f) << faces[f][0], faces[f][1], faces[f][2];
  for (int f = 0; f < 12; ++f)
    s.order.push_back(f);
  return s;
}

Soup randomSoup(std::mt19937_64& rng, int triangles, double spread) {
  std::uniform_real_distribution<double> u(-spread, spread);
  Soup s;
  s.vertices.resize(3, 3 * triangles);
  s.triangles.resize(3, triangles);
  for (int t = 0; t < triangles; ++t) {
    const Eigen::Vector3d base(u(rng), u(rng), u(rng));
    for (int k = 0; k < 3; ++k) {
      s.vertices.col(3 * t + k) = base + 0.1 * Eigen::Vector3d(u(rng), u(rng), u(rng));
    }
    s.triangles.col(t) << 3 * t, 3 * t + 1, 3 * t + 2;
    s.order.push_back(t);
  }
  return s;
}

OrientedBox fit(const Soup& s) {
  return fitBox(s.vertices, s.triangles, s.order.data(), static_cast<std::int32_t>(s.order.size()));
}

TEST(OrientedBoxFit, ContainsEveryVertexOfRandomSoups) {
  std::mt19937_64 rng(7);
  for (int trial = 0; trial < 200; ++trial) {
    const double spread = std::pow(10.0, trial % 9 - 3);  // 1e-3 .. 1e5
    const Soup s = randomSoup(rng, 1 + trial % 40, spread);
    const OrientedBox box = fit(s);
    for (int v = 0; v < s.vertices.cols(); ++v) {
      ASSERT_TRUE(boxContains(box, s.vertices.col(v))) << "trial " << trial << " vertex " << v;
    }
  }
}

TEST(OrientedBoxFit, ContainsVerticesFarFromTheOrigin) {
  std::mt19937_64 rng(8);
  Soup s = randomSoup(rng, 30, 1.0);
  s.vertices.colwise() += Eigen::Vector3d(1e8, -3e7, 5e6);
  const OrientedBox box = fit(s);
  for (int v = 0; v < s.vertices.cols(); ++v)
    EXPECT_TRUE(boxContains(box, s.vertices.col(v)));
}

TEST(OrientedBoxFit, AxesAreOrthonormalAndRightHanded) {
  std::mt19937_64 rng(9);
  for (int trial = 0; trial < 100; ++trial) {
    const OrientedBox box = fit(randomSoup(rng, 2 + trial % 20, 1.0));
    EXPECT_LT((box.axes.transpose() * box.axes - Eigen::Matrix3d::Identity()).norm(), 1e-12);
    EXPECT_NEAR(box.axes.determinant(), 1.0, 1e-12);
    EXPECT_GE(box.half_extents[0], box.half_extents[1]);
    EXPECT_GE(box.half_extents[1], box.half_extents[2]);
  }
}

TEST(OrientedBoxFit, RotatedCuboidGivesItsOwnAxesAndExtents) {
  const Eigen::Matrix3d rotation =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const Eigen::Vector3d half(3.0, 2.0, 1.0);
  const Eigen::Vector3d offset(10, -4, 2);
  const OrientedBox box = fit(boxMesh(half, rotation, offset));
  // Distinct extents make the covariance eigenvectors the cuboid's own axes (up to sign).
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(std::abs(box.axes.col(k).dot(rotation.col(k))), 1.0, 1e-9) << "axis " << k;
    EXPECT_NEAR(box.half_extents[k], half[k], 1e-9);
  }
  EXPECT_LT((box.center - offset).norm(), 1e-9);
}

TEST(OrientedBoxFit, FlatTriangleGetsAZeroThicknessAxisNormalToIt) {
  Soup s;
  s.vertices.resize(3, 3);
  s.vertices << 0, 4, 0,  //
      0, 0, 1,            //
      2, 2, 2;
  s.triangles.resize(3, 1);
  s.triangles.col(0) << 0, 1, 2;
  s.order = {0};
  const OrientedBox box = fit(s);
  EXPECT_NEAR(std::abs(box.axes.col(2).z()), 1.0, 1e-12);
  EXPECT_LT(box.half_extents[2], 1e-12);
}

TEST(OrientedBoxFit, DegenerateSetsStillGetAContainingBox) {
  Soup s;
  s.vertices.resize(3, 3);
  s.vertices << 1, 1, 1,  //
      2, 2, 2,            //
      3, 3, 3;            // three copies of one point
  s.triangles.resize(3, 1);
  s.triangles.col(0) << 0, 1, 2;
  s.order = {0};
  const OrientedBox box = fit(s);
  EXPECT_TRUE(box.axes.allFinite());
  EXPECT_TRUE(boxContains(box, Eigen::Vector3d(1, 2, 3)));
}

double surface(const OrientedBox& box) {
  const Eigen::Vector3d& h = box.half_extents;
  return h.x() * h.y() + h.y() * h.z() + h.z() * h.x();
}

// fit() then tighten() on the same triangles, as the build does for an inner node.
std::pair<OrientedBox, OrientedBox> fitAndTighten(const Soup& s) {
  BoxFitter fitter(static_cast<std::size_t>(s.vertices.cols()));
  const auto count = static_cast<std::int32_t>(s.order.size());
  const OrientedBox fitted = fitter.fit(s.vertices, s.triangles, s.order.data(), count);
  return {fitted, fitter.tighten(fitted, s.vertices, s.triangles, s.order.data(), count)};
}

TEST(OrientedBoxTighten, ContainsEveryVertexAndNeverGrows) {
  std::mt19937_64 rng(17);
  int tightened = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const double spread = std::pow(10.0, trial % 9 - 3);  // 1e-3 .. 1e5
    Soup s = randomSoup(rng, 2 + trial % 40, spread);
    if (trial % 5 == 0) s.vertices.colwise() += Eigen::Vector3d(1e7, -3e6, 5e5) * spread;
    const auto [fitted, tight] = fitAndTighten(s);
    for (int v = 0; v < s.vertices.cols(); ++v)
      ASSERT_TRUE(boxContains(tight, s.vertices.col(v))) << "trial " << trial << " vertex " << v;
    EXPECT_LT((tight.axes.transpose() * tight.axes - Eigen::Matrix3d::Identity()).norm(), 1e-12);
    EXPECT_NEAR(tight.axes.determinant(), 1.0, 1e-12);
    EXPECT_GE(tight.half_extents[0], tight.half_extents[1]);
    EXPECT_GE(tight.half_extents[1], tight.half_extents[2]);
    EXPECT_LE(surface(tight), surface(fitted) * (1.0 + 1e-9)) << "trial " << trial;
    tightened += tight.axes != fitted.axes;
  }
  EXPECT_GT(tightened, 0);  // the search was exercised, not only its no-change path
}

// A flat 4 x 1 plate, tilted, whose vertices crowd along one diagonal (fans from two corners to
// points on it): the covariance's first axis follows the diagonal, and its box is far larger
// than the plate. The plate's own frame is the frame of a triangle that has one of its sides as
// an edge.
TEST(OrientedBoxTighten, FindsTheFrameOfAPlateWhoseVerticesCrowdAlongADiagonal) {
  const Eigen::Matrix3d rotation =
      Eigen::AngleAxisd(0.4, Eigen::Vector3d(2, -1, 3).normalized()).toRotationMatrix();
  const Eigen::Vector3d offset(5, -2, 7);
  const Eigen::Vector3d a(-2, -0.5, 0);
  const Eigen::Vector3d b(2, -0.5, 0);
  const Eigen::Vector3d c(2, 0.5, 0);
  const Eigen::Vector3d d(-2, 0.5, 0);
  const int on_diagonal = 40;  // a, then points along a -> c, ending at c
  Soup s;
  s.vertices.resize(3, on_diagonal + 3);
  for (int i = 0; i <= on_diagonal; ++i)
    s.vertices.col(i) = rotation * (a + (c - a) * (static_cast<double>(i) / on_diagonal)) + offset;
  s.vertices.col(on_diagonal + 1) = rotation * b + offset;
  s.vertices.col(on_diagonal + 2) = rotation * d + offset;
  s.triangles.resize(3, 2 * on_diagonal);
  for (int i = 0; i < on_diagonal; ++i) {
    s.triangles.col(2 * i) << on_diagonal + 1, i + 1, i;
    s.triangles.col(2 * i + 1) << on_diagonal + 2, i, i + 1;
    s.order.push_back(2 * i);
    s.order.push_back(2 * i + 1);
  }
  const auto [fitted, tight] = fitAndTighten(s);
  ASSERT_GT(surface(fitted), 1.1 * surface(tight));  // the covariance's box is the loose one
  EXPECT_NEAR(tight.half_extents[0], 2.0, 1e-9);
  EXPECT_NEAR(tight.half_extents[1], 0.5, 1e-9);
  EXPECT_LT(tight.half_extents[2], 1e-9);
  EXPECT_NEAR(std::abs(tight.axes.col(0).dot(rotation.col(0))), 1.0, 1e-9);
  EXPECT_NEAR(std::abs(tight.axes.col(2).dot(rotation.col(2))), 1.0, 1e-9);
  EXPECT_LT((tight.center - offset).norm(), 1e-9);
}

// Triangles with coincident or collinear corners have no frame: a zero edge or normal must not
// become a frame of zeros, under which every box would look empty and win.
TEST(OrientedBoxTighten, SkipsTheFramesOfDegenerateTriangles) {
  std::mt19937_64 rng(23);
  for (int trial = 0; trial < 50; ++trial) {
    Soup s = randomSoup(rng, 12, 1.0);
    for (int t = 0; t < 12; t += 2) {
      const Eigen::Index first = s.triangles(0, t);
      if (t % 4 == 0) {
        s.vertices.col(s.triangles(1, t)) = s.vertices.col(first);  // two corners coincide
      } else {
        s.vertices.col(s.triangles(2, t)) =  // the third corner on the line of the others
            2.0 * s.vertices.col(s.triangles(1, t)) - s.vertices.col(first);
      }
    }
    const auto [fitted, tight] = fitAndTighten(s);
    EXPECT_LT((tight.axes.transpose() * tight.axes - Eigen::Matrix3d::Identity()).norm(), 1e-12);
    EXPECT_GT(tight.half_extents[0], 0.0);
    EXPECT_LE(surface(tight), surface(fitted) * (1.0 + 1e-9));
    for (int v = 0; v < s.vertices.cols(); ++v)
      ASSERT_TRUE(boxContains(tight, s.vertices.col(v))) << "trial " << trial << " vertex " << v;
  }
}

// Half of a 2 x 1 rectangle: its box lies flush with the diagonal, so the other half's far
// corner is outside it, and it is no larger than the covariance's box.
TEST(OrientedBoxTighten, LaysASingleTriangleFlushWithItsLongestEdge) {
  const Eigen::Matrix3d rotation =
      Eigen::AngleAxisd(1.1, Eigen::Vector3d(-1, 3, 2).normalized()).toRotationMatrix();
  const Eigen::Vector3d offset(-3, 8, 1);
  const auto place = [&](double x, double y) {
    return Eigen::Vector3d(rotation * Eigen::Vector3d(x, y, 0) + offset);
  };
  Soup s;
  s.vertices.resize(3, 3);
  s.vertices.col(0) = place(0, 0);
  s.vertices.col(1) = place(2, 0);
  s.vertices.col(2) = place(0, 1);
  s.triangles.resize(3, 1);
  s.triangles.col(0) << 0, 1, 2;
  s.order = {0};
  const auto [fitted, tight] = fitAndTighten(s);
  const Eigen::Vector3d diagonal = (place(0, 1) - place(2, 0)).normalized();
  EXPECT_NEAR(std::abs(tight.axes.col(0).dot(diagonal)), 1.0, 1e-12);
  EXPECT_NEAR(tight.half_extents[0], 0.5 * std::sqrt(5.0), 1e-9);
  EXPECT_NEAR(tight.half_extents[1], 1.0 / std::sqrt(5.0), 1e-9);  // half the altitude
  EXPECT_LT(tight.half_extents[2], 1e-12);
  EXPECT_LE(surface(tight), surface(fitted) * (1.0 + 1e-12));
  for (int v = 0; v < 3; ++v)
    EXPECT_TRUE(boxContains(tight, s.vertices.col(v)));
  EXPECT_FALSE(boxContains(tight, place(2, 1)));
}

// The cuboid's covariance frame is its own (RotatedCuboidGivesItsOwnAxesAndExtents): no frame of
// its triangles is clearly smaller, so tighten keeps the box as fitted.
TEST(OrientedBoxTighten, KeepsACuboidsOwnFrame) {
  const Eigen::Matrix3d rotation =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const auto [fitted, tight] =
      fitAndTighten(boxMesh(Eigen::Vector3d(3, 2, 1), rotation, Eigen::Vector3d(10, -4, 2)));
  EXPECT_EQ(tight.axes, fitted.axes);
  EXPECT_EQ(tight.half_extents, fitted.half_extents);
}

TEST(OrientedBoxRefit, KeepsAxesAndContainsMovedVertices) {
  std::mt19937_64 rng(10);
  Soup s = randomSoup(rng, 20, 1.0);
  OrientedBox box = fit(s);
  const Eigen::Matrix3d axes = box.axes;
  s.vertices.array() *= 1.7;
  s.vertices.row(0).array() += 3.0;
  Eigen::Matrix3Xi ordered = s.triangles;
  refitBoxExtents(box, s.vertices, ordered);
  EXPECT_EQ(box.axes, axes);
  for (int v = 0; v < s.vertices.cols(); ++v)
    EXPECT_TRUE(boxContains(box, s.vertices.col(v)));
}

// Compact boxes keep 15 bits a component of the quaternion and 8 significant bits of each extent,
// rounded up: the decoded box still holds every vertex and is at most about 1/128 looser. Half
// turns (w = 0, where a stored x, y, z would leave w poorly determined) decode to the same axes.
TEST(CompactBox, HoldsEveryVertexAndStaysCloseToTheFittedBox) {
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Eigen::Matrix3d> rotations = {
      Eigen::Matrix3d(Eigen::AngleAxisd(EIGEN_PI, Eigen::Vector3d::UnitZ())),
      Eigen::Matrix3d(Eigen::AngleAxisd(EIGEN_PI, Eigen::Vector3d(1, 1, 0).normalized()))};
  for (int trial = 0; trial < 40; ++trial) {
    const Eigen::Vector3d axis = Eigen::Vector3d(u(rng), u(rng), u(rng)).normalized();
    rotations.emplace_back(Eigen::AngleAxisd(EIGEN_PI * (1.0 + u(rng)), axis));
  }
  for (const Eigen::Matrix3d& rotation : rotations) {
    const Soup s = boxMesh(Eigen::Vector3d(3.0, 0.7, 0.01), rotation, Eigen::Vector3d(5, -2, 1));
    const OrientedBox fitted = fit(s);
    const OrientedBox decoded = expandBox(compactBox(fitted, s.vertices, s.triangles));
    for (int v = 0; v < s.vertices.cols(); ++v)
      EXPECT_TRUE(boxContains(decoded, s.vertices.col(v)));
    EXPECT_LT(axisDefect(decoded.axes), 1e-12);
    EXPECT_LT((decoded.axes - fitted.axes).cwiseAbs().maxCoeff(), 2e-4);
    for (int k = 0; k < 3; ++k) {
      EXPECT_GE(decoded.half_extents[k], fitted.half_extents[k] * (1.0 - 1e-9));
      EXPECT_LE(decoded.half_extents[k], fitted.half_extents[k] * (1.0 + 1.0 / 128) + 2e-3);
    }
  }
}

}  // namespace
}  // namespace collido::obbtree
