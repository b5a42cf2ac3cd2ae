// Movable nodes: each rule moves vertices as its formula says, selections and recordings, and
// frames are pure functions of the rest shape (any order, same positions).
#include <collido/scene/deformation.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <collido/mesh/procedural.h>
#include "support/numbers.h"

namespace collido {
namespace {

using test::kPi;

TriangleMesh points(const Eigen::Matrix3Xd& vertices) {
  TriangleMesh mesh;
  mesh.vertices = vertices;
  mesh.triangles.resize(3, 0);
  return mesh;
}

Deformation with(const DeformationRule& rule, std::size_t frames) {
  Deformation d;
  d.rules = {rule};
  d.frames = frames;
  return d;
}

TEST(DeformationTiming, RampAndSine) {
  DeformationTiming ramp;
  EXPECT_EQ(ramp.factor(0, 5), 0.0);
  EXPECT_EQ(ramp.factor(2, 5), 0.5);
  EXPECT_EQ(ramp.factor(4, 5), 1.0);
  EXPECT_EQ(ramp.factor(0, 1), 0.0);
  DeformationTiming sine{8.0, 0.0};
  EXPECT_NEAR(sine.factor(2, 100), 1.0, 1e-15);
  EXPECT_NEAR(sine.factor(6, 100), -1.0, 1e-15);
}

TEST(Deformation, TwistTurnsByTheAngleAtItsDistanceAlongTheAxis) {
  DeformationRule twist;
  twist.kind = DeformationRule::Kind::kTwist;
  twist.angle = kPi / 2;
  twist.length = 2.0;
  twist.axis = Eigen::Vector3d::UnitZ();
  Eigen::Matrix3Xd v(3, 2);
  v << 1, 1, 0, 0, 0, 2;  // (1, 0, 0) on the base, (1, 0, 2) one length up
  const Eigen::Matrix3Xd out = with(twist, 3).positionsAt(points(v), 2);  // ramp: factor 1
  EXPECT_TRUE(out.col(0).isApprox(Eigen::Vector3d(1, 0, 0)));
  EXPECT_NEAR((out.col(1) - Eigen::Vector3d(0, 1, 2)).norm(), 0.0, 1e-15);
}

TEST(Deformation, PulsateMovesAlongTheVertexNormals) {
  const Result<TriangleMesh> sphere = makeSphere(SphereParams{1.0, 24, 12});
  ASSERT_TRUE(sphere.ok());
  DeformationRule pulsate;
  pulsate.kind = DeformationRule::Kind::kPulsate;
  pulsate.amplitude = 0.1;
  const Eigen::Matrix3Xd out = with(pulsate, 2).positionsAt(sphere.value(), 1);
  for (Eigen::Index v = 0; v < out.cols(); ++v) {
    // On a sphere the vertex normals point away from the centre: every radius grows by 0.1.
    EXPECT_NEAR(out.col(v).norm(), 1.1, 1e-3);
  }
}

TEST(Deformation, BendKeepsTheBaseAndTheCentreLineLength) {
  DeformationRule bend;
  bend.kind = DeformationRule::Kind::kBend;
  bend.angle = kPi / 2;
  bend.length = 1.0;
  bend.axis = Eigen::Vector3d::UnitZ();
  bend.direction = Eigen::Vector3d::UnitX();
  Eigen::Matrix3Xd v(3, 4);
  v << 0, 0, 0, 0,  //
      0, 0, 0, 0,   //
      -1, 0.5, 1, 2;
  const Eigen::Matrix3Xd out = with(bend, 2).positionsAt(points(v), 1);
  EXPECT_TRUE(out.col(0).isApprox(v.col(0)));  // below the origin: untouched
  // A quarter circle of length 1 has radius 2/pi: its end is at (2/pi, 0, 2/pi).
  const double radius = 2.0 / kPi;
  EXPECT_NEAR((out.col(2) - Eigen::Vector3d(radius, 0, radius)).norm(), 0.0, 1e-12);
  // Half way along the arc: 45 degrees round.
  EXPECT_NEAR((out.col(1) -
               Eigen::Vector3d(radius * (1 - std::cos(kPi / 4)), 0, radius * std::sin(kPi / 4)))
                  .norm(),
              0.0, 1e-12);
  // Beyond the span: straight on along the end's tangent (+x).
  EXPECT_NEAR((out.col(3) - Eigen::Vector3d(radius + 1.0, 0, radius)).norm(), 0.0, 1e-12);
}

TEST(Deformation, SquashKeepsVolume) {
  DeformationRule squash;
  squash.kind = DeformationRule::Kind::kSquash;
  squash.amount = 0.36;
  Eigen::Matrix3Xd v(3, 1);
  v << 1, 1, 1;
  const Eigen::Matrix3Xd out = with(squash, 2).positionsAt(points(v), 1);
  EXPECT_NEAR(out(2, 0), 0.64, 1e-15);
  EXPECT_NEAR(out(0, 0), 1.25, 1e-15);
  EXPECT_NEAR(out(0, 0) * out(1, 0) * out(2, 0), 1.0, 1e-14);
}

TEST(Deformation, WaveTravelsAlongItsDirection) {
  DeformationRule wave;
  wave.kind = DeformationRule::Kind::kWave;
  wave.amplitude = 0.5;
  wave.wavelength = 4.0;
  wave.timing.period = 8.0;
  Eigen::Matrix3Xd v(3, 2);
  v << 1, 0, 0, 0, 0, 0;  // x = 1 and x = 0
  const Deformation d = with(wave, 8);
  // Frame 0: sin(2 pi x / 4); frame 2 (a quarter period later) the crest has moved to x = 2.
  EXPECT_NEAR(d.positionsAt(points(v), 0)(2, 0), 0.5, 1e-15);
  EXPECT_NEAR(d.positionsAt(points(v), 2)(2, 0), 0.0, 1e-15);
  EXPECT_NEAR(d.positionsAt(points(v), 2)(2, 1), -0.5, 1e-15);
}

TEST(Deformation, NoiseIsBoundedDeterministicAndSelective) {
  const Result<TriangleMesh> torus = makeTorus(TorusParams{});
  ASSERT_TRUE(torus.ok());
  DeformationRule noise;
  noise.kind = DeformationRule::Kind::kNoise;
  noise.amplitude = 0.01;
  noise.seed = 7;
  Deformation d = with(noise, 10);
  d.select_low = Eigen::Vector3d(0, -10, -10);  // only x >= 0 moves
  const Eigen::Matrix3Xd late = d.positionsAt(torus.value(), 7);
  const Eigen::Matrix3Xd early = d.positionsAt(torus.value(), 3);
  EXPECT_EQ(late, d.positionsAt(torus.value(), 7));  // the same frame again, after another
  std::size_t moved = 0;
  for (Eigen::Index v = 0; v < late.cols(); ++v) {
    const double shift = (late.col(v) - torus.value().vertices.col(v)).norm();
    EXPECT_LE(shift, 0.01 + 1e-15);
    if (torus.value().vertices(0, v) < 0) {
      EXPECT_EQ(shift, 0.0);
    } else if (shift > 0) {
      ++moved;
    }
  }
  EXPECT_GT(moved, static_cast<std::size_t>(late.cols() / 3));
  EXPECT_NE(late, early);
}

TEST(RecordedPositions, RoundTripAndReplacesTheRestPositions) {
  const std::string path =
      (std::filesystem::temp_directory_path() / "collido_recorded_test.pos").string();
  RecordedPositions recording;
  recording.vertices = 2;
  recording.frames = 3;
  for (int i = 0; i < 18; ++i)
    recording.values.push_back(0.5 * i);
  ASSERT_TRUE(writeRecordedPositions(path, recording).ok());
  const Result<RecordedPositions> back = readRecordedPositions(path);
  ASSERT_TRUE(back.ok()) << back.status().message();
  EXPECT_EQ(back.value().values, recording.values);
  Deformation d;
  d.recorded = std::make_shared<const RecordedPositions>(back.value());
  d.frames = 3;
  Eigen::Matrix3Xd rest = Eigen::Matrix3Xd::Zero(3, 2);
  const Eigen::Matrix3Xd frame1 = d.positionsAt(points(rest), 1);
  EXPECT_EQ(frame1(0, 0), 3.0);  // value 6 of 18: frame 1, vertex 0, x
  EXPECT_EQ(frame1(2, 1), 5.5);
  std::filesystem::remove(path);
}

TEST(RecordedPositions, BadFilesAreRefusedWithTheReason) {
  const std::string path =
      (std::filesystem::temp_directory_path() / "collido_recorded_bad.pos").string();
  RecordedPositions recording;
  recording.vertices = 2;
  recording.frames = 2;
  recording.values.assign(12, 1.0);
  recording.values[10] = std::nan("");
  ASSERT_TRUE(writeRecordedPositions(path, recording).ok());
  Result<RecordedPositions> read = readRecordedPositions(path);
  ASSERT_FALSE(read.ok());
  EXPECT_NE(read.status().message().find("frame 1, vertex 1"), std::string::npos)
      << read.status().message();
  EXPECT_NE(read.status().message().find(path), std::string::npos);

  std::filesystem::resize_file(path, 32 + 24 * 3);  // one vertex-frame short
  read = readRecordedPositions(path);
  ASSERT_FALSE(read.ok());
  EXPECT_NE(read.status().message().find("24 per vertex per frame"), std::string::npos)
      << read.status().message();

  std::ofstream(path, std::ios::binary | std::ios::trunc) << "NOTAFILE and some more bytes here!";
  read = readRecordedPositions(path);
  ASSERT_FALSE(read.ok());
  EXPECT_NE(read.status().message().find("COLLIPOS"), std::string::npos);
  std::filesystem::remove(path);
  EXPECT_FALSE(readRecordedPositions(path).ok());
}

}  // namespace
}  // namespace collido
