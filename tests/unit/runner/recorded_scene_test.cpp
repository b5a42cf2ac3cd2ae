// collido::Recorder as a user meets it: an application's frames, poses and questions recorded,
// loaded back as a scene and run, with objects and queries that come and go; the calls it
// refuses; and a recording killed mid-frame, closed afterwards.
#include <collido/record/recorder.h>

#include <csignal>
#include <filesystem>
#include <fstream>

#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <collido/runner/runner.h>
#include <collido/scene/scene.h>

#include "support/runs/run_plugin.h"
#include "support/runs/scripted_backend.h"
#include "support/test_paths.h"

namespace collido {
namespace {

// A unit cube's 8 corners and 12 triangles.
struct Cube {
  Eigen::Matrix3Xd vertices{3, 8};
  Eigen::Matrix3Xi triangles{3, 12};
  explicit Cube(double size) {
    for (int i = 0; i < 8; ++i)
      vertices.col(i) = size * Eigen::Vector3d(i & 1, (i >> 1) & 1, (i >> 2) & 1);
    triangles << 0, 0, 4, 4, 0, 0, 2, 2, 0, 0, 1, 1,  //
        1, 3, 5, 7, 1, 5, 3, 7, 2, 6, 3, 7,           //
        3, 2, 7, 6, 5, 4, 7, 6, 6, 4, 7, 5;
  }
};

Eigen::Isometry3d at(double x, double degrees = 0.0) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translate(Eigen::Vector3d(x, 0.5, 0.0));
  pose.rotate(Eigen::AngleAxisd(degrees * M_PI / 180.0, Eigen::Vector3d::UnitZ()));
  return pose;
}

const SceneQuery& queryNamed(const Scene& scene, const std::string& name) {
  for (const SceneQuery& q : scene.queries) {
    if (q.name == name) return q;
  }
  throw std::runtime_error("no query " + name);
}

TEST(RecordedScene, LoadsAsRecordedAndRunsEachQueryInItsOwnFrames) {
  const std::string folder = test::makeTempDirectory("recording") + "/cell";
  const Cube cube(1.0);
  const Cube small(0.5);
  {
    Recorder rec(folder);
    const auto a = rec.addMesh("a", cube.vertices, cube.triangles);
    const auto b = rec.addMesh("b", cube.vertices, cube.triangles);
    EXPECT_EQ(rec.addMesh("a", cube.vertices, cube.triangles), a);  // the same mesh again
    rec.setPose(b, at(3.0));
    for (int frame = 0; frame < 4; ++frame) {
      rec.beginFrame();
      if (frame == 1) {
        const auto c = rec.addMesh("c", small.vertices, small.triangles);
        rec.setPose(c, Eigen::Matrix4d(at(0.25, 30.0).matrix()));
      }
      rec.setPose(a, Eigen::Matrix<double, 3, 4>(at(0.1 * frame, 10.0 * frame).affine()));
      rec.ask(a, b, RecordedKind::kBoolean);
      rec.ask(a, b, RecordedKind::kBoolean);  // asked twice, one query of the frame
      if (frame == 1 || frame == 2) rec.ask(a, 2, RecordedKind::kDistance, 0.01);
      if (frame == 3) rec.ask(b, a, RecordedKind::kAllPairs);
      if (frame == 2) rec.removeObject(2);
      rec.endFrame();
    }
    EXPECT_EQ(rec.framesRecorded(), 4u);
  }  // closed into scene.json

  Result<Scene> loaded = loadScene(folder + "/scene.json");
  ASSERT_TRUE(loaded.ok()) << loaded.status().toString();
  const Scene& scene = loaded.value();
  EXPECT_EQ(scene.frames, 4u);
  ASSERT_EQ(scene.objects.size(), 3u);
  // Identical meshes share one file.
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(folder + "/meshes"),
                          std::filesystem::directory_iterator()),
            2);
  for (std::size_t f = 0; f < 4; ++f) {
    EXPECT_TRUE(scene.objects[0].poseAt(f).isApprox(
        at(0.1 * static_cast<double>(f), 10.0 * static_cast<double>(f)), 0.0));
    EXPECT_TRUE(scene.objects[1].poseAt(f).isApprox(at(3.0), 0.0));
  }
  EXPECT_TRUE(scene.objects[2].poseAt(1).isApprox(at(0.25, 30.0), 0.0));
  EXPECT_TRUE(scene.objects[0].present.everyFrame());
  EXPECT_EQ(scene.objects[2].present.ranges, (FrameRanges{{{1, 2}}}.ranges));
  EXPECT_TRUE(queryNamed(scene, "a-b boolean").asked.everyFrame());
  EXPECT_EQ(queryNamed(scene, "a-c distance").asked.ranges, (FrameRanges{{{1, 2}}}.ranges));
  EXPECT_EQ(queryNamed(scene, "a-c distance").request.abs_tolerance, 0.01);
  EXPECT_EQ(queryNamed(scene, "b-a all_pairs").asked.ranges, (FrameRanges{{{3, 3}}}.ranges));

  // The runner asks each query in its frames only.
  const RunReport report =
      runScene(scene, BackendSpec{test::scriptedBackend(), "scripted", {}}, test::repeated(1));
  ASSERT_EQ(report.measurements.size(), 3u);
  for (const QueryMeasurement& m : report.measurements) {
    ASSERT_TRUE(m.ok()) << m.query << ": " << m.status.text();
    std::vector<std::size_t> frames;
    for (const FrameRecord& f : m.frames)
      frames.push_back(f.frame);
    const FrameRanges& asked = queryNamed(scene, m.query).asked;
    EXPECT_EQ(frames.size(), asked.countIn(scene.frames)) << m.query;
    for (const std::size_t f : frames)
      EXPECT_TRUE(asked.contains(f)) << m.query << " frame " << f;
  }
}

TEST(RecordedScene, RefusesBadCallsNamingThemAndKeepsRecording) {
  const std::string folder = test::makeTempDirectory("recording") + "/bad";
  const Cube cube(1.0);
  Recorder rec(folder, RecorderOptions{2, 1.0});
  const auto a = rec.addMesh("a", cube.vertices, cube.triangles);
  const auto b = rec.addMesh("b", cube.vertices, cube.triangles);
  const auto refused = [](const auto& call, const std::string& words) {
    try {
      call();
      ADD_FAILURE() << "not refused: " << words;
    } catch (const RecordError& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  };
  refused([&] { rec.ask(a, b, RecordedKind::kBoolean); }, "ask(0, 1): no frame is open");
  refused([&] { rec.addMesh("a", 2.0 * cube.vertices, cube.triangles); },
          "addMesh('a'): 'a' was added with another mesh");
  refused([&] { rec.addMesh(" a", cube.vertices, cube.triangles); }, "begins or ends with a space");
  refused([&] { rec.addMesh("Geh\xe4use", cube.vertices, cube.triangles); },
          "the name is not UTF-8 (byte 3)");
  Eigen::Matrix3Xd nan_vertices = cube.vertices;
  nan_vertices(1, 3) = std::nan("");
  refused([&] { rec.addMesh("n", nan_vertices, cube.triangles); }, "vertex 3 is not finite");
  rec.beginFrame();
  Eigen::Isometry3d nan_pose = at(1.0);
  nan_pose.translation().x() = std::nan("");
  refused([&] { rec.setPose(a, nan_pose); }, "setPose(object 'a'): the pose has a NaN");
  refused([&] { rec.setPose(7, at(1.0)); }, "setPose(id 7): unknown object id 7");
  Eigen::Matrix4d sheared = at(1.0).matrix();
  sheared(0, 1) = 0.1;
  refused([&] { rec.setPose(a, sheared); }, "the rotation is not a rotation");
  rec.ask(a, b, RecordedKind::kDistance);
  rec.ask(a, b, RecordedKind::kDistance, -0.0);  // the same question: one query
  refused([&] { rec.setPose(a, at(1.0)); }, "'a' was already asked about in this frame");
  refused([&] { rec.ask(a, b, RecordedKind::kBoolean, 0.5); }, "distance queries only");
  rec.endFrame();
  // Past max_frames (2), frames are checked but not recorded.
  for (int frame = 0; frame < 3; ++frame) {
    rec.beginFrame();
    rec.setPose(b, at(2.0 + frame));
    rec.ask(a, b, RecordedKind::kDistance);
    rec.endFrame();
  }
  EXPECT_EQ(rec.framesRecorded(), 2u);
  const auto c = rec.addMesh("c", cube.vertices, cube.triangles);
  rec.removeObject(c);
  refused([&] { rec.addMesh("c", cube.vertices, cube.triangles); }, "'c' was removed");
  rec.close();
  refused([&] { rec.beginFrame(); }, "the recording is closed");
  Result<Scene> loaded = loadScene(folder + "/scene.json");
  ASSERT_TRUE(loaded.ok()) << loaded.status().toString();
  EXPECT_EQ(loaded.value().frames, 2u);
  EXPECT_EQ(loaded.value().queries.size(), 1u);
}

TEST(RecordedScene, AKilledRecordingClosesWithItsCompletedFrames) {
  const std::string folder = test::makeTempDirectory("recording") + "/killed";
  const Cube cube(1.0);
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    Recorder rec(folder);
    const auto a = rec.addMesh("a", cube.vertices, cube.triangles);
    const auto b = rec.addMesh("b", cube.vertices, cube.triangles);
    for (int frame = 0; frame < 4; ++frame) {
      rec.beginFrame();
      rec.setPose(b, at(0.5 * frame));
      rec.ask(a, b, RecordedKind::kBoolean);
      if (frame == 3) raise(SIGKILL);  // mid-frame: frames 0-2 are complete
      rec.endFrame();
    }
    _exit(0);
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status));
  EXPECT_FALSE(std::filesystem::exists(folder + "/scene.json"));
  // A write torn by the kill: part of a frame's block, not ended by its line.
  std::ofstream(folder + "/journal.txt", std::ios::app) << "P 1 1 0 0 0 1 0 0 0 1 9 9";
  EXPECT_EQ(closeRecording(folder), 3u);
  Result<Scene> loaded = loadScene(folder + "/scene.json");
  ASSERT_TRUE(loaded.ok()) << loaded.status().toString();
  EXPECT_EQ(loaded.value().frames, 3u);
  EXPECT_TRUE(loaded.value().objects[1].poseAt(2).isApprox(at(1.0), 0.0));

  // A damaged line inside the completed frames is an error naming the file and line.
  std::ofstream(folder + "/journal.txt", std::ios::app) << "\nZ 1\nE 3\n";
  try {
    closeRecording(folder);
    ADD_FAILURE() << "a damaged journal was read";
  } catch (const RecordError& e) {
    EXPECT_NE(std::string(e.what()).find("journal.txt:"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace collido
