#include <collido/study/not_applicable.h>

#include <map>

#include <collido/runner/text_table.h>

namespace collido::study {
namespace {

nlohmann::json kindNames(QueryKindSet set) {
  nlohmann::json names = nlohmann::json::array();
  for (const QueryKindInfo& kind : kQueryKinds)
    if (set.contains(kind.kind)) names.push_back(kind.name);
  return names;
}

Result<QueryKindSet> kindsFromNames(const nlohmann::json& names, const std::string& where) {
  QueryKindSet set;
  for (const nlohmann::json& name : names) {
    const std::optional<QueryKind> kind = parseQueryKind(name.get<std::string>());
    if (!kind) {
      return Status(StatusCode::kInvalidArgument,
                    where + ": unknown query kind '" + name.get<std::string>() + "'");
    }
    set |= *kind;
  }
  return set;
}

std::string answersText(const SettingAbility& ability) {
  return ability.builds_meshes ? queryKindsText(ability.queries) : "no triangle meshes";
}

}  // namespace

std::string NotApplicable::reason() const {
  return "answers " + answersText(ability) + "; the scene asks " + queryKindsText(asks);
}

nlohmann::json notApplicableToJson(const std::vector<NotApplicable>& list) {
  nlohmann::json array = nlohmann::json::array();
  for (const NotApplicable& n : list) {
    array.push_back({{"backend", n.backend},
                     {"scene", n.scene},
                     {"asks", kindNames(n.asks)},
                     {"answers", kindNames(n.ability.queries)},
                     {"builds_meshes", n.ability.builds_meshes}});
  }
  return array;
}

Result<std::vector<NotApplicable>> notApplicableFromJson(const nlohmann::json& json,
                                                         const std::string& label) {
  std::vector<NotApplicable> list;
  try {
    for (std::size_t i = 0; i < json.size(); ++i) {
      const nlohmann::json& entry = json.at(i);
      const std::string where = label + ": /not_applicable/" + std::to_string(i);
      NotApplicable n;
      n.backend = entry.at("backend").get<std::string>();
      n.scene = entry.at("scene").get<std::string>();
      Result<QueryKindSet> asks = kindsFromNames(entry.at("asks"), where + "/asks");
      if (!asks.ok()) return asks.status();
      Result<QueryKindSet> answers = kindsFromNames(entry.at("answers"), where + "/answers");
      if (!answers.ok()) return answers.status();
      n.asks = asks.value();
      n.ability = {answers.value(), entry.at("builds_meshes").get<bool>()};
      list.push_back(std::move(n));
    }
  } catch (const nlohmann::json::exception& e) {
    return Status(StatusCode::kInvalidArgument, label + ": not_applicable: " + e.what());
  }
  return list;
}

std::string notApplicableText(const std::vector<NotApplicable>& list) {
  if (list.empty()) return "";
  // One row per setting, its scenes in plan order.
  std::vector<std::string> order;
  std::map<std::string, std::vector<const NotApplicable*>> by_backend;
  for (const NotApplicable& n : list) {
    auto& scenes = by_backend[n.backend];
    if (scenes.empty()) order.push_back(n.backend);
    scenes.push_back(&n);
  }
  std::vector<std::vector<std::string>> rows;
  for (const std::string& backend : order) {
    const std::vector<const NotApplicable*>& scenes = by_backend.at(backend);
    std::string where;
    for (const NotApplicable* n : scenes)
      where += (where.empty() ? "" : ", ") + n->scene + " (" + queryKindsText(n->asks) + ")";
    rows.push_back({backend, answersText(scenes.front()->ability), where});
  }
  return formatTextTable({"backend", "answers", "not planned on (the scene asks)"}, rows, 3);
}

}  // namespace collido::study
