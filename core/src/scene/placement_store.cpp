#include "placement_store.h"

#include <atomic>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <unistd.h>

#include <xxhash.h>
#include <nlohmann/json.hpp>

namespace collido::scene_reading {
namespace {

using Json = nlohmann::json;

// Bump when the solver or the stored fields change: older files then never match.
constexpr const char* kStoreVersion = "collido-placement-1";

template <typename T>
void append(std::string& bytes, const T* data, std::size_t count) {
  bytes.append(reinterpret_cast<const char*>(data), count * sizeof(T));
}

Json poseJson(const Pose& pose) {
  Json matrix = Json::array();
  for (int row = 0; row < 3; ++row) {
    for (int column = 0; column < 4; ++column)
      matrix.push_back(pose.matrix()(row, column));
  }
  return matrix;
}

std::optional<Pose> poseFrom(const Json& matrix) {
  if (!matrix.is_array() || matrix.size() != 12) return std::nullopt;
  Pose pose = Pose::Identity();
  std::size_t next = 0;
  for (int row = 0; row < 3; ++row) {
    for (int column = 0; column < 4; ++column) {
      const Json& value = matrix[next++];
      if (!value.is_number()) return std::nullopt;
      pose.matrix()(row, column) = value.get<double>();
    }
  }
  return pose;
}

std::optional<std::vector<double>> numbersFrom(const Json& list, std::size_t size) {
  if (!list.is_array() || list.size() != size) return std::nullopt;
  std::vector<double> numbers;
  for (const Json& value : list) {
    if (!value.is_number()) return std::nullopt;
    numbers.push_back(value.get<double>());
  }
  return numbers;
}

}  // namespace

PlacementKey::PlacementKey(const std::string& block_text, double largest_radius) {
  bytes_ = kStoreVersion;
  bytes_ += '\0';
  bytes_ += block_text;
  bytes_ += '\0';
  append(bytes_, &largest_radius, 1);
}

void PlacementKey::addBody(const Pose& pose, const TriangleMesh& mesh) {
  append(bytes_, pose.matrix().data(), 16);
  const std::size_t counts[2] = {static_cast<std::size_t>(mesh.vertices.cols()),
                                 static_cast<std::size_t>(mesh.triangles.cols())};
  append(bytes_, counts, 2);
  append(bytes_, mesh.vertices.data(), static_cast<std::size_t>(mesh.vertices.size()));
  append(bytes_, mesh.triangles.data(), static_cast<std::size_t>(mesh.triangles.size()));
}

std::string PlacementKey::path(const std::string& directory) const {
  const XXH128_hash_t hash = XXH3_128bits(bytes_.data(), bytes_.size());
  char hex[33];
  std::snprintf(hex, sizeof hex, "%016llx%016llx", static_cast<unsigned long long>(hash.high64),
                static_cast<unsigned long long>(hash.low64));
  return (std::filesystem::path(directory) / (std::string(hex) + ".json")).string();
}

std::optional<StoredSolve> readStoredSolve(const std::string& path, std::size_t bodies,
                                           std::size_t variables, std::size_t clearances) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::stringstream text;
  text << in.rdbuf();
  const Json file = Json::parse(text.str(), nullptr, /*allow_exceptions=*/false);
  if (!file.is_object() || file.value("format", std::string()) != kStoreVersion)
    return std::nullopt;
  StoredSolve solve;
  const Json poses = file.value("body_poses", Json());
  if (!poses.is_array() || poses.size() != bodies) return std::nullopt;
  for (const Json& matrix : poses) {
    const std::optional<Pose> pose = poseFrom(matrix);
    if (!pose) return std::nullopt;
    solve.body_poses.push_back(*pose);
  }
  std::optional<std::vector<double>> values =
      numbersFrom(file.value("variables", Json()), variables);
  std::optional<std::vector<double>> distances =
      numbersFrom(file.value("clearances", Json()), clearances);
  std::optional<std::vector<double>> report = numbersFrom(file.value("report", Json()), 4);
  if (!values || !distances || !report) return std::nullopt;
  solve.variables = std::move(*values);
  solve.clearances = std::move(*distances);
  solve.equations = static_cast<int>((*report)[0]);
  solve.parameters = static_cast<int>((*report)[1]);
  solve.iterations = static_cast<int>((*report)[2]);
  solve.change = (*report)[3];
  return solve;
}

void writeStoredSolve(const std::string& path, const StoredSolve& solve) {
  Json poses = Json::array();
  for (const Pose& pose : solve.body_poses)
    poses.push_back(poseJson(pose));
  const Json file = {
      {"format", kStoreVersion},
      {"body_poses", poses},
      {"variables", solve.variables},
      {"clearances", solve.clearances},
      {"report", {solve.equations, solve.parameters, solve.iterations, solve.change}}};
  std::error_code ec;
  std::filesystem::create_directories(std::filesystem::path(path).parent_path(), ec);
  static std::atomic<unsigned> written{0};
  const std::string partial =
      path + ".partial." + std::to_string(getpid()) + "." + std::to_string(written++);
  {
    std::ofstream out(partial, std::ios::binary | std::ios::trunc);
    // nlohmann writes each double in the shortest form that reads back to the same value.
    out << file.dump();
    if (!out) {
      std::filesystem::remove(partial, ec);
      return;
    }
  }
  std::filesystem::rename(partial, path, ec);
  if (ec) std::filesystem::remove(partial, ec);
}

}  // namespace collido::scene_reading
