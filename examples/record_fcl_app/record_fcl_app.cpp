// An application's own collision loop, with FCL: a part slides through the slot of a fixture,
// wobbling so that it grazes the jaws, while a clamp comes down onto the base for part of the
// run. Every FCL query the loop makes is also recorded with collido::Recorder, so that
// `collido study RECORDING/scene.json` replays this workload on every backend.
//
//   record_fcl_app RECORDING_FOLDER
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include <fcl/fcl.h>

#include <collido/record/recorder.h>

namespace {

// A box of the given size with its minimum corner at `low`, as 8 vertices and 12 triangles.
struct Mesh {
  Eigen::Matrix3Xd vertices{3, 8};
  Eigen::Matrix3Xi triangles{3, 12};
};

Mesh box(const Eigen::Vector3d& low, const Eigen::Vector3d& size) {
  Mesh m;
  for (int i = 0; i < 8; ++i) {
    m.vertices.col(i) = low + size.cwiseProduct(Eigen::Vector3d(i & 1, (i >> 1) & 1, (i >> 2) & 1));
  }
  m.triangles << 0, 0, 4, 4, 0, 0, 2, 2, 0, 0, 1, 1,  //
      1, 3, 5, 7, 1, 5, 3, 7, 2, 6, 3, 7,             //
      3, 2, 7, 6, 5, 4, 7, 6, 6, 4, 7, 5;
  return m;
}

// The application's own FCL object for a mesh.
std::unique_ptr<fcl::CollisionObjectd> fclObject(const Mesh& mesh) {
  std::vector<fcl::Vector3d> points;
  std::vector<fcl::Triangle> triangles;
  for (Eigen::Index v = 0; v < mesh.vertices.cols(); ++v)
    points.emplace_back(mesh.vertices.col(v));
  for (Eigen::Index t = 0; t < mesh.triangles.cols(); ++t) {
    triangles.emplace_back(mesh.triangles(0, t), mesh.triangles(1, t), mesh.triangles(2, t));
  }
  auto model = std::make_shared<fcl::BVHModel<fcl::OBBRSSd>>();
  model->beginModel();
  model->addSubModel(points, triangles);
  model->endModel();
  return std::make_unique<fcl::CollisionObjectd>(model);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: record_fcl_app RECORDING_FOLDER\n");
    return 2;
  }
  const Mesh part = box({-0.2, -0.2, 0.0}, {0.4, 0.4, 1.0});
  const Mesh jaw = box({-1.0, 0.0, 0.0}, {2.0, 0.5, 0.8});
  const Mesh base = box({-1.5, -1.5, -0.2}, {3.0, 3.0, 0.2});
  const Mesh clamp = box({-0.1, -0.1, 0.0}, {0.2, 0.2, 0.6});

  try {
    collido::Recorder rec(argv[1]);
    struct Body {
      std::unique_ptr<fcl::CollisionObjectd> fcl;
      collido::Recorder::ObjectId id;
    };
    const auto add = [&](const char* name, const Mesh& mesh) {
      return Body{fclObject(mesh), rec.addMesh(name, mesh.vertices, mesh.triangles)};
    };
    Body moving = add("part", part);
    Body left = add("jaw_left", jaw);
    Body right = add("jaw_right", jaw);
    Body floor = add("base", base);
    const auto place = [&](Body& body, const Eigen::Isometry3d& pose) {
      body.fcl->setTransform(pose);
      body.fcl->computeAABB();
      rec.setPose(body.id, pose);
    };
    // The slot between the jaws is 0.42 wide; the part is 0.4 across, so a turn of its own
    // brings its corners into the jaws.
    place(left, Eigen::Isometry3d(Eigen::Translation3d(0.0, 0.21, 0.0)));
    place(right, Eigen::Isometry3d(Eigen::Translation3d(0.0, -0.71, 0.0)));
    place(floor, Eigen::Isometry3d::Identity());

    std::unique_ptr<Body> holder;
    int contacts = 0;
    double closest = INFINITY;
    constexpr int kFrames = 40;
    for (int frame = 0; frame < kFrames; ++frame) {
      rec.beginFrame();
      const double s = static_cast<double>(frame) / (kFrames - 1);
      Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
      pose.translate(Eigen::Vector3d(-1.6 + 3.2 * s, 0.0, 0.05));
      pose.rotate(Eigen::AngleAxisd(0.08 * std::sin(9.0 * s), Eigen::Vector3d::UnitZ()));
      place(moving, pose);
      if (frame == 10) {  // the clamp arrives, and leaves at frame 30
        holder = std::make_unique<Body>(add("clamp", clamp));
        place(*holder, Eigen::Isometry3d(Eigen::Translation3d(1.2, 1.0, 0.0)));
      }
      if (frame == 30) {
        rec.removeObject(holder->id);
        holder.reset();
      }

      for (const Body* jaw_body : {&left, &right}) {
        fcl::CollisionRequestd request;
        fcl::CollisionResultd result;
        fcl::collide(moving.fcl.get(), jaw_body->fcl.get(), request, result);
        contacts += result.isCollision() ? 1 : 0;
        rec.ask(moving.id, jaw_body->id, collido::RecordedKind::kBoolean);
      }
      fcl::DistanceRequestd request;
      fcl::DistanceResultd result;
      fcl::distance(moving.fcl.get(), floor.fcl.get(), request, result);
      closest = std::min(closest, result.min_distance);
      rec.ask(moving.id, floor.id, collido::RecordedKind::kDistance);
      if (holder) {
        fcl::CollisionRequestd clamp_request;
        fcl::CollisionResultd clamp_result;
        fcl::collide(holder->fcl.get(), floor.fcl.get(), clamp_request, clamp_result);
        rec.ask(holder->id, floor.id, collido::RecordedKind::kBoolean);
      }
      rec.endFrame();
    }
    std::printf(
        "%d frames: FCL found %d part-jaw contacts, closest to the base %.3g; recorded "
        "in %s\n",
        kFrames, contacts, closest, rec.folder().c_str());
  } catch (const collido::RecordError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  return 0;
}
