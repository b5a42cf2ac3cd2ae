#include <collido/view/view_page.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <map>

#include <nlohmann/json.hpp>

#include <collido/io/files.h>
#include <collido/io/html_page.h>

namespace collido::view {
namespace {

using Json = nlohmann::json;

// The page's binary part: float32 vertex positions and uint32 triangle indices, back to back,
// each block at a multiple of 4 bytes so the page reads it through typed arrays in place.
class GeometryBuffer {
 public:
  /// Appends a mesh's vertices; returns [byte offset, float count].
  Json addVertices(const Eigen::Matrix3Xd& vertices) {
    const std::size_t offset = bytes_.size();
    const auto count = static_cast<std::size_t>(vertices.size());
    bytes_.resize(offset + 4 * count);
    for (std::size_t k = 0; k < count; ++k) {
      const auto value = static_cast<float>(vertices.data()[k]);
      std::memcpy(&bytes_[offset + 4 * k], &value, 4);
    }
    return Json::array({offset, count});
  }

  /// Appends a mesh's triangles; returns [byte offset, index count].
  Json addTriangles(const Eigen::Matrix3Xi& triangles) {
    const std::size_t offset = bytes_.size();
    const auto count = static_cast<std::size_t>(triangles.size());
    bytes_.resize(offset + 4 * count);
    for (std::size_t k = 0; k < count; ++k) {
      const auto value = static_cast<std::uint32_t>(triangles.data()[k]);
      std::memcpy(&bytes_[offset + 4 * k], &value, 4);
    }
    return Json::array({offset, count});
  }

  const std::string& bytes() const { return bytes_; }

 private:
  std::string bytes_;
};

// A pose as three.js's Matrix4.fromArray reads it: 16 numbers, column by column.
Json poseJson(const Pose& pose) {
  Json out = Json::array();
  const Eigen::Matrix4d& m = pose.matrix();
  for (int k = 0; k < 16; ++k)
    out.push_back(m.data()[k]);
  return out;
}

Json posesJson(const std::vector<Pose>& poses) {
  Json out = Json::array();
  for (const Pose& pose : poses)
    out.push_back(poseJson(pose));
  return out;
}

Json markersJson(const SceneObject& object) {
  if (!object.tracking) return nullptr;
  const MarkerTracking& tracking = *object.tracking;
  Json layout = Json::array();
  for (const auto& [id, at] : tracking.layout)
    layout.push_back({id, at.x(), at.y(), at.z()});
  Json observed = Json::array();
  Json lost = Json::array();
  for (std::size_t f = 0; f < tracking.frames.size(); ++f) {
    Json seen = Json::array();
    for (const pose::MarkerObservation& m : tracking.frames[f].observed)
      seen.push_back({m.id, m.position.x(), m.position.y(), m.position.z()});
    observed.push_back(std::move(seen));
    if (tracking.frames[f].lost) lost.push_back(f);
  }
  return {{"layout", layout}, {"observed", observed}, {"lost", lost}, {"source", tracking.source}};
}

// A mesh file as the scene names it (meshes/bunny.obj), not by where this machine keeps it: the
// page may be shared, and an absolute path says nothing to its reader.
std::string sourceRelativeToScene(const Scene& scene, const std::string& source) {
  if (scene.path.empty() || source.empty() || source.find('/') == std::string::npos) return source;
  std::error_code ec;
  const std::filesystem::path base =
      std::filesystem::absolute(std::filesystem::path(scene.path).parent_path(), ec);
  const std::filesystem::path relative =
      std::filesystem::absolute(source, ec).lexically_normal().lexically_relative(base);
  return ec || relative.empty() ? source : relative.string();
}

Json objectJson(const Scene& scene, const SceneObject& object, GeometryBuffer& buffer) {
  Json states = Json::array();
  for (std::size_t s = 0; s < object.stateCount(); ++s) {
    const TriangleMesh& mesh = *object.stateMesh(s);
    states.push_back({{"positions", buffer.addVertices(mesh.vertices)},
                      {"indices", buffer.addTriangles(mesh.triangles)},
                      {"triangles", mesh.triangleCount()}});
  }
  Json schedule = nullptr;
  if (object.states.size() > 1) {
    schedule = Json::array();
    for (std::size_t f = 0; f < scene.frames; ++f)
      schedule.push_back(object.stateAt(f));
  }
  // Movable nodes: the deformed vertices of every frame (the active state's topology).
  Json deformed = nullptr;
  if (object.deformation) {
    deformed = Json::array();
    for (std::size_t f = 0; f < scene.frames; ++f)
      deformed.push_back(buffer.addVertices(object.shapeAt(f)->vertices));
  }
  Json true_poses = nullptr;
  if (object.tracking || !object.inherited_true_poses.empty()) {
    true_poses = Json::array();
    for (std::size_t f = 0; f < scene.frames; ++f)
      true_poses.push_back(poseJson(object.truePoseAt(f)));
  }
  return {{"name", object.name},
          {"parent", object.parent ? Json(*object.parent) : Json(nullptr)},
          {"source", sourceRelativeToScene(scene, object.report.source)},
          {"states", std::move(states)},
          {"schedule", std::move(schedule)},
          {"deformed", std::move(deformed)},
          {"poses", posesJson(object.poses)},
          {"present", object.present.everyFrame() ? Json(nullptr) : Json(object.present.ranges)},
          {"true_poses", std::move(true_poses)},
          {"markers", markersJson(object)}};
}

Json queryJson(const SceneQuery& query) {
  return {{"name", query.name},
          {"kind", queryKindName(query.request.kind)},
          {"objects", query.objects()},
          {"side_b", query.side_b},
          {"asked", query.asked.everyFrame() ? Json(nullptr) : Json(query.asked.ranges)}};
}

// The page template and the scripts and style it inlines.
struct FrontEnd {
  std::string page;
  std::map<std::string, std::string> parts;
};

Result<FrontEnd> readFrontEnd(const std::string& web_directory) {
  const std::filesystem::path web(web_directory);
  Result<std::string> page =
      io::readTextFile((web / "view" / "template.html").string(), "not found");
  if (!page.ok()) return page.status();
  FrontEnd front_end{std::move(page).value(), {}};
  const std::filesystem::path three = web / "node_modules" / "three";
  const Status read = io::readPageParts(
      web,
      {{"@CSS@", web / "view" / "view.css", false},
       {"@THREE_CORE@", three / "build" / "three.core.js"},
       {"@THREE_MODULE@", three / "build" / "three.module.js"},
       {"@ORBIT_CONTROLS@", three / "examples" / "jsm" / "controls" / "OrbitControls.js"},
       {"@VIEW_JS@", web / "view" / "view.js"}},
      front_end.parts);
  if (!read.ok()) return read;
  return front_end;
}

}  // namespace

Result<std::string> renderViewPage(const Scene& scene, const std::vector<ViewBackend>& backends,
                                   const std::string& web_directory) {
  GeometryBuffer buffer;
  Json objects = Json::array();
  for (const SceneObject& object : scene.objects)
    objects.push_back(objectJson(scene, object, buffer));
  Json queries = Json::array();
  for (const SceneQuery& query : scene.queries)
    queries.push_back(queryJson(query));
  Json answers = Json::array();
  for (const ViewBackend& backend : backends) {
    Json entry = {{"label", backend.label}, {"problem", backend.problem}};
    if (!backend.answers_json.empty()) {
      Json parsed = Json::parse(backend.answers_json, nullptr, /*allow_exceptions=*/false);
      if (parsed.is_discarded()) {
        return Status(StatusCode::kInvalidArgument,
                      "view: the answers of " + backend.label + " are not valid JSON");
      }
      entry["answers"] = std::move(parsed);
    }
    answers.push_back(std::move(entry));
  }
  const Json data = {{"scene",
                      {{"name", scene.name},
                       {"description", scene.description},
                       {"path", scene.path},
                       {"up", {scene.up.x(), scene.up.y(), scene.up.z()}},
                       {"frames", scene.frames}}},
                     {"objects", std::move(objects)},
                     {"queries", std::move(queries)},
                     {"backends", std::move(answers)}};

  Result<FrontEnd> front_end = readFrontEnd(web_directory);
  if (!front_end.ok()) return front_end.status();
  std::map<std::string, std::string>& values = front_end.value().parts;
  values["@TITLE@"] = io::htmlText(scene.name);
  // An engine's log in a problem may hold bytes that are not UTF-8; they are replaced, not
  // allowed to lose the page.
  values["@DATA@"] = io::dataSafe(data.dump(-1, ' ', false, Json::error_handler_t::replace));
  values["@GEOMETRY@"] = io::base64(buffer.bytes());
  return io::fillTemplate(front_end.value().page, values);
}

Status checkViewFrontEnd(const std::string& web_directory) {
  const Result<FrontEnd> front_end = readFrontEnd(web_directory);
  return front_end.ok() ? Status() : front_end.status();
}

}  // namespace collido::view
