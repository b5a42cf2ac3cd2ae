#include "stress_reader.h"

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <vector>

#include <collido/mesh/mesh_io.h>
#include <collido/stress/stress_cases.h>

#include "shape_reader.h"

namespace collido::scene_reading {

void readStress(const Reader& r, const Node& root, const std::string& base_directory,
                const SceneLoadOptions& options, Scene& scene) {
  for (const char* key : {"objects", "queries", "frames", "constraints"}) {
    if (root.has(key)) {
      r.fail(root.at(key), std::string("'") + key +
                               "' is not allowed beside 'stress', which makes a stress scene's "
                               "objects, queries and its one frame, placed as its cases say");
    }
  }
  const Node node = root.at("stress");
  r.expectObject(node, {"category", "severities", "cases_per_severity", "seed", "meshes"});
  if (!node.has("category")) r.fail(node, "missing 'category'");
  const std::string name = r.string(node.at("category"));
  const std::optional<stress::Category> category = stress::parseCategory(name);
  if (!category) {
    std::string known;
    for (const stress::Category c : stress::allCategories())
      known += (known.empty() ? "" : ", ") + std::string(stress::categoryName(c));
    r.fail(node.at("category"), "unknown stress category '" + name + "' (known: " + known + ")");
  }
  const stress::SeverityRange range = stress::severityRange(*category);
  std::vector<int> severities;
  if (node.has("severities")) {
    const Node list = node.at("severities");
    r.expectArray(list);
    if (list.value.empty()) r.fail(list, "give at least one severity");
    for (std::size_t i = 0; i < list.value.size(); ++i) {
      const auto severity = static_cast<int>(
          r.integer(list.at(i), std::numeric_limits<int>::min(), std::numeric_limits<int>::max()));
      if (severity < range.min || severity > range.max) {
        r.fail(list.at(i), "severity " + std::to_string(severity) + " is outside [" +
                               std::to_string(range.min) + ", " + std::to_string(range.max) +
                               "] for " + name + " (" + range.meaning + ")");
      }
      if (std::find(severities.begin(), severities.end(), severity) != severities.end()) {
        r.fail(list.at(i), "severity " + std::to_string(severity) + " is listed twice");
      }
      severities.push_back(severity);
    }
  } else {
    severities = stress::defaultSeverities(*category);
  }
  const auto per_severity =
      static_cast<std::size_t>(r.integer(node, "cases_per_severity", 4, 1, 1000));
  const auto seed = static_cast<std::uint64_t>(r.integer(node, "seed", 1, 0, INT64_MAX));

  stress::StressInputs inputs;
  if (*category == stress::Category::kMeshDefects) {
    if (!node.has("meshes")) {
      r.fail(node, "mesh_defects needs 'meshes': the mesh files to pose (relative to the scene)");
    }
    const Node meshes = node.at("meshes");
    r.expectArray(meshes);
    if (meshes.value.empty()) r.fail(meshes, "give at least one mesh file");
    for (std::size_t i = 0; i < meshes.value.size(); ++i) {
      const std::filesystem::path file =
          (std::filesystem::path(base_directory) / r.string(meshes.at(i))).lexically_normal();
      Result<TriangleMesh> mesh = loadMesh(file.string());
      if (!mesh.ok()) r.fail(meshes.at(i), mesh.status().message());
      inputs.defect_meshes.push_back(
          {file.stem().string(), std::make_shared<const TriangleMesh>(std::move(mesh).value())});
    }
  } else if (node.has("meshes")) {
    r.fail(node.at("meshes"), "only the mesh_defects category takes 'meshes'");
  }

  scene.category = name;
  TriangleBudget budget(r, options.max_triangles);
  // The defect meshes are shared by many cases: inspect each mesh once.
  std::map<const TriangleMesh*, MeshReport> inspected;
  const auto add_object = [&](const std::string& object_name, const char* side,
                              const std::shared_ptr<const TriangleMesh>& mesh, const Pose& pose) {
    SceneObject object;
    object.name = object_name + "/" + side;
    object.mesh = mesh;
    auto found = inspected.find(mesh.get());
    if (found == inspected.end()) {
      MeshReport report;
      report.importer = "stress";
      inspectMesh(*mesh, report);
      found = inspected.emplace(mesh.get(), report).first;
    }
    object.report = found->second;
    object.report.source = name + " stress case, object " + side;
    object.poses = {pose};
    scene.objects.push_back(std::move(object));
    return scene.objects.size() - 1;
  };
  for (const int severity : severities) {
    Result<std::vector<stress::StressCase>> cases =
        stress::generateStressCases(*category, severity, per_severity, seed, inputs);
    if (!cases.ok()) r.fail(node, cases.status().message());
    for (const stress::StressCase& c : cases.value()) {
      budget.charge(node, "stress case " + c.name,
                    static_cast<double>(c.a->triangleCount() + c.b->triangleCount()));
      const std::size_t a = add_object(c.name, "a", c.a, c.pose_a);
      const std::size_t b = add_object(c.name, "b", c.b, c.pose_b);
      // The distance category asks for the distance where the others ask for the pairs.
      const QueryKind detailed =
          *category == stress::Category::kDistance ? QueryKind::kDistance : QueryKind::kAllPairs;
      for (const QueryKind kind : {detailed, QueryKind::kBoolean}) {
        SceneQuery query;
        query.name = c.name + " " + queryKindName(kind);
        query.a = a;
        query.b = b;
        query.request.kind = kind;
        scene.queries.push_back(query);
      }
    }
  }
}

}  // namespace collido::scene_reading
