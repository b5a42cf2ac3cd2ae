#include "marker_reader.h"

#include <filesystem>
#include <memory>
#include <sstream>

#include <collido/scene/marker_tracks_file.h>

namespace collido::scene_reading {
namespace {

pose::MarkerLayout readLayout(const Reader& r, const Node& node) {
  if (!node.value.is_object() || node.value.empty())
    r.fail(node, "expected an object of marker id: [x, y, z] (object frame), at least one");
  pose::MarkerLayout layout;
  for (const auto& item : node.value.items()) {
    const Node at = node.at(item.key());
    std::size_t used = 0;
    int id = 0;
    try {
      id = std::stoi(item.key(), &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != item.key().size())
      r.fail(at, "marker ids are integers, not '" + item.key() + "'");
    layout[id] = r.vector3(at);
  }
  return layout;
}

TrackNoise readNoise(const Reader& r, const Node& node) {
  r.expectObject(node, {"noise", "dropout", "outliers", "outlier_offset", "seed"});
  TrackNoise noise;
  noise.noise = r.number(node, "noise", 0.0);
  noise.dropout = r.number(node, "dropout", 0.0);
  noise.outliers = r.number(node, "outliers", 0.0);
  noise.outlier_offset = r.number(node, "outlier_offset", noise.outlier_offset);
  noise.seed = static_cast<std::uint64_t>(r.integer(node, "seed", 1, 0, INT64_MAX));
  if (noise.noise < 0.0) r.fail(node.at("noise"), "noise must be >= 0");
  for (const char* rate : {"dropout", "outliers"}) {
    const double v = r.number(node, rate, 0.0);
    if (v < 0.0 || v > 1.0) r.fail(node.at(rate), std::string(rate) + " must be in [0, 1]");
  }
  if (noise.outlier_offset < 0.0) r.fail(node.at("outlier_offset"), "must be >= 0");
  return noise;
}

std::string noiseText(const TrackNoise& noise) {
  std::ostringstream text;
  text << "generated: noise " << noise.noise << ", dropout " << noise.dropout << ", outliers "
       << noise.outliers << " (offset " << noise.outlier_offset << "), seed " << noise.seed;
  return text.str();
}

}  // namespace

void readMarkers(const Reader& r, const Node& markers, const std::string& base_directory,
                 std::size_t frames, SceneObject& object) {
  r.expectObject(markers, {"layout", "tracks", "generate", "solver", "reject_outliers",
                           "noise_sigma", "max_condition"});
  if (!markers.has("layout")) r.fail(markers, "missing 'layout' (marker id: [x, y, z])");
  auto tracking = std::make_shared<MarkerTracking>();
  tracking->layout = readLayout(r, markers.at("layout"));
  if (markers.has("tracks") == markers.has("generate"))
    r.fail(markers, "give exactly one of 'tracks' (a CSV file) and 'generate'");
  if (markers.has("solver")) {
    const std::string solver = r.string(markers.at("solver"));
    if (solver == "rigid") {
      tracking->fit.solver = pose::PoseSolver::kRigid;
    } else if (solver == "affine") {
      tracking->fit.solver = pose::PoseSolver::kAffine;
    } else {
      r.fail(markers.at("solver"), "expected \"rigid\" or \"affine\", got \"" + solver + "\"");
    }
  }
  if (markers.has("reject_outliers")) {
    tracking->fit.reject_outliers = true;
    tracking->fit.inlier_threshold = r.positive(markers, "reject_outliers", 1.0);
  }
  tracking->fit.noise_sigma = r.number(markers, "noise_sigma", 0.0);
  if (tracking->fit.noise_sigma < 0.0) r.fail(markers.at("noise_sigma"), "must be >= 0");
  tracking->fit.max_condition = r.number(markers, "max_condition", tracking->fit.max_condition);
  if (!(tracking->fit.max_condition >= 1.0)) r.fail(markers.at("max_condition"), "must be >= 1");

  tracking->true_poses.resize(frames);
  for (std::size_t f = 0; f < frames; ++f)
    tracking->true_poses[f] = object.poseAt(f);
  MarkerTracks observed;
  if (markers.has("tracks")) {
    const std::string file = r.string(markers.at("tracks"));
    const std::string path = (std::filesystem::path(base_directory) / file).string();
    Result<MarkerTracks> read = readMarkerTracks(path, object.name, frames, tracking->layout);
    if (!read.ok()) r.fail(markers.at("tracks"), read.status().message());
    observed = std::move(read).value();
    tracking->source = file;
  } else {
    const TrackNoise noise = readNoise(r, markers.at("generate"));
    observed = generateTracks(tracking->layout, tracking->true_poses, noise);
    tracking->source = noiseText(noise);
  }
  tracking->frames.resize(frames);
  for (std::size_t f = 0; f < frames; ++f)
    tracking->frames[f].observed = std::move(observed[f]);

  // The rest shape's bounding-box corners bound the predicted spread over its vertices.
  const Eigen::Vector3d low = object.mesh->vertices.rowwise().minCoeff();
  const Eigen::Vector3d high = object.mesh->vertices.rowwise().maxCoeff();
  std::vector<Eigen::Vector3d> corners;
  corners.reserve(8);
  for (int k = 0; k < 8; ++k) {
    corners.emplace_back((k & 1) != 0 ? high.x() : low.x(), (k & 2) != 0 ? high.y() : low.y(),
                         (k & 4) != 0 ? high.z() : low.z());
  }
  Result<std::vector<Pose>> recovered = recoverPoses(*tracking, corners);
  if (!recovered.ok()) r.fail(markers, recovered.status().message());
  object.poses = std::move(recovered).value();
  object.tracking = std::move(tracking);
}

}  // namespace collido::scene_reading
