// FRep case files: named solids (possibly animated), the pairs to test, frames and precision.
#include <collido/scene/frep_file.h>

#include <map>
#include <memory>

#include "frep_solid_reader.h"
#include "scene_reader.h"

namespace collido {
namespace {

using scene_reading::Json;
using scene_reading::Node;
using scene_reading::Reader;
using scene_reading::SceneError;

std::vector<double> frameTimes(const Reader& r, const Node& root) {
  if (!root.has("frames")) return {0.0};
  const Node frames = root.at("frames");
  r.expectObject(frames, {"count", "duration"});
  const auto count = r.integer(frames, "count", 1, 1, 100000);
  const double duration = r.number(frames, "duration", 1.0);
  if (duration < 0) r.fail(frames.at("duration"), "duration must be >= 0");
  std::vector<double> times;
  for (std::int64_t i = 0; i < count; ++i)
    times.push_back(
        count == 1 ? 0.0 : duration * static_cast<double>(i) / static_cast<double>(count - 1));
  return times;
}

}  // namespace

Result<FrepFile> parseFrepFile(const std::string& text, const std::string& label) {
  Result<Json> parsed = scene_reading::parseDocument(text, label);
  if (!parsed.ok()) return parsed.status();
  auto document = std::make_shared<const Json>(std::move(parsed.value()));
  try {
    const Reader r(label, 1.0);
    const Node root{*document, ""};
    r.expectObject(root, {"name", "precision", "frames", "solids", "pairs"});
    FrepFile file;
    file.name = root.has("name") ? r.string(root.at("name")) : label;
    file.precision = r.positive(root, "precision", 1e-3);
    file.times = frameTimes(r, root);
    if (!root.has("solids")) r.fail(root, "missing 'solids'");
    const Node list = root.at("solids");
    r.expectArray(list);
    if (list.value.empty()) r.fail(list, "no solids");
    std::map<std::string, std::size_t> index;
    for (std::size_t i = 0; i < list.value.size(); ++i) {
      const Node entry = list.at(i);
      r.expectObject(entry, {"name", "solid"});
      if (!entry.has("name")) r.fail(entry, "missing 'name'");
      if (!entry.has("solid")) r.fail(entry, "missing 'solid'");
      FrepSolidEntry solid;
      solid.name = r.string(entry.at("name"));
      if (!index.emplace(solid.name, i).second)
        r.fail(entry.at("name"), "duplicate solid name '" + solid.name + "'");
      const Node description = entry.at("solid");
      solid.animated = scene_reading::frepIsAnimated(description);
      solid.evaluation_cost = scene_reading::frepEvaluationCost(description.value);
      // Build at every frame time now, so that a bad value at any time fails the load.
      for (double time : file.times)
        scene_reading::readFrepSolid(r, description, time);
      const std::string pointer = description.pointer;
      solid.at = [document, label, pointer](double time) {
        const Reader reader(label, 1.0);
        const Node node{document->at(Json::json_pointer(pointer)), pointer};
        return scene_reading::readFrepSolid(reader, node, time);
      };
      file.solids.push_back(std::move(solid));
    }
    if (root.has("pairs")) {
      const Node pairs = root.at("pairs");
      r.expectArray(pairs);
      for (std::size_t i = 0; i < pairs.value.size(); ++i) {
        const Node pair = pairs.at(i);
        r.expectArray(pair);
        if (pair.value.size() != 2 && pair.value.size() != 3)
          r.fail(pair, "expected [\"a\", \"b\"] or [\"a\", \"b\", expected answer]");
        std::size_t ends[2];
        for (std::size_t k = 0; k < 2; ++k) {
          const std::string name = r.string(pair.at(k));
          const auto found = index.find(name);
          if (found == index.end()) r.fail(pair.at(k), "unknown solid '" + name + "'");
          ends[k] = found->second;
        }
        if (ends[0] == ends[1]) r.fail(pair, "a solid paired with itself");
        file.pairs.emplace_back(ends[0], ends[1]);
        std::string expected;
        if (pair.value.size() == 3) {
          expected = r.string(pair.at(2));
          if (expected != "colliding" && expected != "separated" && expected != "touching")
            r.fail(pair.at(2), "expected answer must be colliding, separated or touching");
        }
        file.expected.push_back(expected);
      }
    } else {
      for (std::size_t i = 0; i < file.solids.size(); ++i) {
        for (std::size_t j = i + 1; j < file.solids.size(); ++j) {
          file.pairs.emplace_back(i, j);
          file.expected.emplace_back();
        }
      }
    }
    if (file.pairs.empty()) r.fail(root, "no pairs to test (one solid)");
    return file;
  } catch (const SceneError& error) {
    return Status(StatusCode::kInvalidArgument, error.what());
  }
}

Result<FrepFile> loadFrepFile(const std::string& path) {
  Result<std::string> text = scene_reading::readTextFile(path, "FRep file");
  if (!text.ok()) return text.status();
  return parseFrepFile(text.value(), path);
}

}  // namespace collido
