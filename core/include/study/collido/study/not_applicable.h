#pragma once

#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <collido/query.h>
#include <collido/status.h>

namespace collido::study {

/// What a backend setting can be asked, as an instance of it reported when the probe created it.
struct SettingAbility {
  QueryKindSet queries;        ///< the kinds it answers
  bool builds_meshes = false;  ///< it builds triangle meshes (every scene's objects are meshes)
};

/// The abilities of the backend settings a probe could create, by backend text. A setting
/// missing here (not probed, or refused when created) is planned everywhere: its worker then
/// reports what went wrong.
using SettingAbilities = std::map<std::string, SettingAbility>;

/// A backend setting the study did not plan on a scene because it answers none of the query
/// kinds the scene asks (or builds no triangle meshes): listed once, not run as skipped queries.
struct NotApplicable {
  std::string backend;  ///< backend text
  std::string scene;    ///< scene name
  QueryKindSet asks;    ///< the kinds the scene asks
  SettingAbility ability;

  /// "answers boolean, all_pairs, contacts; the scene asks distance".
  std::string reason() const;
};

nlohmann::json notApplicableToJson(const std::vector<NotApplicable>& list);
/// Reads notApplicableToJson's array; errors name `label` and the entry.
Result<std::vector<NotApplicable>> notApplicableFromJson(const nlohmann::json& json,
                                                         const std::string& label);

/// table.txt's section: one line per backend setting with the scenes it was not planned on;
/// empty for an empty list.
std::string notApplicableText(const std::vector<NotApplicable>& list);

}  // namespace collido::study
