#include <collido/study/plan.h>

#include <cctype>
#include <cstdio>
#include <random>
#include <sstream>

namespace collido::study {
namespace {

std::string shortNumber(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

// Every digit a double needs, so that resolutions which print alike ("0.5" and 0.50000001)
// still get different ids; values people write (1, 0.5, 0.25) come out as short as before.
std::string exactNumber(double value) {
  std::ostringstream out;
  out.precision(17);
  out << value;
  return out.str();
}

// FNV-1a: a short, stable fingerprint that keeps ids unique after unsafe characters are folded.
std::uint32_t fingerprint(const std::string& text) {
  std::uint32_t hash = 2166136261u;
  for (const unsigned char c : text) {
    hash ^= c;
    hash *= 16777619u;
  }
  return hash;
}

std::string fileSafe(const std::string& text) {
  std::string out;
  for (const unsigned char c : text)
    out += std::isalnum(c) != 0 || c == '-' || c == '.' ? static_cast<char>(c) : '_';
  return out;
}

std::string makeId(const Combination& c) {
  std::string key = c.scene_path + "\n" + c.scene_name + "\n" + exactNumber(c.resolution) + "\n" +
                    c.backend + "\n" + needsModeName(c.needs) + "\n" + std::to_string(c.limit);
  if (!c.scene_digest.empty() || !c.plugin_identity.empty() || c.repetitions != 0) {
    key += "\n" + c.scene_digest + "\n" + c.plugin_identity + "\n" + std::to_string(c.repetitions);
  }
  if (c.protocol != TimingProtocol::kRepeated)
    key += "\n" + std::string(timingProtocolName(c.protocol));
  if (c.round != 0) key += "\nround " + std::to_string(c.round);
  if (c.kind != InputKind::kScene) {
    key += std::string("\n") + inputKindName(c.kind);
    for (const int size : c.grid)
      key += " " + std::to_string(size);
  }
  char hash[9];
  std::snprintf(hash, sizeof hash, "%08x", fingerprint(key));
  std::string readable =
      fileSafe((c.kind == InputKind::kScene ? "" : std::string(inputKindName(c.kind)) + "~") +
               c.scene_name + "~" + c.backend);
  if (readable.size() > 80) readable.resize(80);
  return readable + "~" + hash;
}

// Whether `only_scenes` lets `backend` run on `scene` (a setting it does not name runs anywhere).
bool onlyAllows(const std::map<std::string, std::set<std::string>>& only_scenes,
                const std::string& backend, const std::string& scene) {
  const auto only = only_scenes.find(backend);
  return only == only_scenes.end() || only->second.count(scene) != 0;
}

}  // namespace

const char* inputKindName(InputKind kind) {
  switch (kind) {
    case InputKind::kScene:
      return "scene";
    case InputKind::kSurfaces:
      return "surfaces";
    case InputKind::kFrep:
      return "frep";
  }
  return "scene";
}

std::optional<InputKind> parseInputKind(const std::string& name) {
  for (const InputKind kind : {InputKind::kScene, InputKind::kSurfaces, InputKind::kFrep}) {
    if (name == inputKindName(kind)) return kind;
  }
  return std::nullopt;
}

Combination inRound(Combination c, int round) {
  c.round = round;
  c.id = makeId(c);
  return c;
}

Combination withInputs(Combination c, const std::string& scene_digest,
                       const std::string& plugin_identity, int repetitions,
                       TimingProtocol protocol) {
  c.scene_digest = scene_digest;
  c.plugin_identity = plugin_identity;
  c.repetitions = repetitions;
  c.protocol = protocol;
  c.id = makeId(c);
  return c;
}

std::string Combination::settingText() const {
  std::string text;
  const auto add = [&text](const std::string& part) { text += (text.empty() ? "" : " ") + part; };
  if (needs != NeedsMode::kDeclared) add(std::string("needs=") + needsModeName(needs));
  if (resolution != 1.0) add("r=" + shortNumber(resolution));
  if (limit != 0) add("limit=" + std::to_string(limit));
  return text;
}

std::string Combination::gridText() const {
  std::string text;
  for (const int size : grid)
    text += (text.empty() ? "" : ",") + std::to_string(size);
  return text;
}

std::string Combination::label() const {
  const std::string setting = settingText();
  const std::string kind_text =
      kind == InputKind::kScene ? "" : std::string(" · ") + inputKindName(kind);
  return scene_name + " · " + backend + (setting.empty() ? "" : " · " + setting) + kind_text;
}

bool applies(const PlannedScene& scene, const std::string& backend,
             const SettingAbilities& abilities) {
  const auto known = abilities.find(backend);
  if (known == abilities.end() || scene.queries.empty()) return true;
  const SettingAbility& ability = known->second;
  return ability.builds_meshes && (ability.queries.bits() & scene.queries.bits()) != 0;
}

std::vector<Combination> planStudy(const std::vector<PlannedScene>& scenes,
                                   const std::vector<std::string>& backends, const Sweep& sweep,
                                   const std::map<std::string, std::set<std::string>>& only_scenes,
                                   const SettingAbilities& abilities) {
  std::vector<Combination> plan;
  for (const PlannedScene& scene : scenes) {
    for (const double resolution : sweep.resolutionsOf(scene.name)) {
      if (resolution != 1.0 && !scene.has_generated_shapes) continue;
      for (const std::string& backend : backends) {
        if (!onlyAllows(only_scenes, backend, scene.name)) continue;
        if (!applies(scene, backend, abilities)) continue;
        for (const NeedsMode needs : sweep.needsOf(scene.name)) {
          for (const std::uint64_t limit : sweep.limits) {
            Combination c;
            c.scene_path = scene.path;
            c.scene_name = scene.name;
            c.resolution = resolution;
            c.backend = backend;
            c.needs = needs;
            c.limit = limit;
            c.category = scene.category;
            c.id = makeId(c);
            plan.push_back(std::move(c));
          }
        }
      }
    }
  }
  return plan;
}

std::vector<NotApplicable> notApplicable(
    const std::vector<PlannedScene>& scenes, const std::vector<std::string>& backends,
    const std::map<std::string, std::set<std::string>>& only_scenes,
    const SettingAbilities& abilities) {
  std::vector<NotApplicable> list;
  for (const PlannedScene& scene : scenes) {
    for (const std::string& backend : backends) {
      if (!onlyAllows(only_scenes, backend, scene.name) || applies(scene, backend, abilities))
        continue;
      list.push_back({backend, scene.name, scene.queries, abilities.at(backend)});
    }
  }
  return list;
}

std::vector<Combination> planComparisons(const std::vector<PlannedScene>& files, InputKind kind,
                                         const std::vector<std::string>& backends,
                                         const std::vector<int>& grid) {
  std::vector<Combination> plan;
  for (const PlannedScene& file : files) {
    std::vector<std::string> settings{kSeedMethod};
    settings.insert(settings.end(), backends.begin(), backends.end());
    for (const std::string& backend : settings) {
      Combination c;
      c.kind = kind;
      c.scene_path = file.path;
      c.scene_name = file.name;
      c.backend = backend;
      if (backend != kSeedMethod) c.grid = grid;
      c.id = makeId(c);
      plan.push_back(std::move(c));
    }
  }
  return plan;
}

bool runsOnOneThread(const std::string& backend) {
  const auto parsed = parseBackendText(backend);
  if (!parsed.ok()) return true;
  const auto& options = parsed.value().second;
  const auto threads = options.find("threads");
  return threads == options.end() || threads->second == "1" || threads->second == "0";
}

bool answersBySubsteps(const std::string& backend) {
  const auto parsed = parseBackendText(backend);
  return parsed.ok() && parsed.value().second.count(kSubstepsOption) != 0;
}

std::vector<Combination> shardOf(const std::vector<Combination>& plan, std::size_t index,
                                 std::size_t count) {
  std::vector<Combination> part;
  for (std::size_t i = index; count != 0 && i < plan.size(); i += count)
    part.push_back(plan[i]);
  return part;
}

std::vector<Combination> inRounds(const std::vector<Combination>& plan, int rounds) {
  std::vector<Combination> all;
  for (const Combination& c : plan) {
    all.push_back(c);
    for (int round = 1; c.kind == InputKind::kScene && round < rounds; ++round)
      all.push_back(inRound(c, round));
  }
  return all;
}

std::vector<std::size_t> runOrder(std::size_t count, std::uint64_t seed) {
  std::vector<std::size_t> order(count);
  for (std::size_t i = 0; i < count; ++i)
    order[i] = i;
  // The generator's output is fixed by the standard; std::shuffle's use of it is not.
  std::mt19937_64 draws(seed);
  for (std::size_t i = count; i > 1; --i)
    std::swap(order[i - 1], order[static_cast<std::size_t>(draws() % i)]);
  return order;
}

Result<std::pair<std::size_t, std::size_t>> parseShard(const std::string& text) {
  const Status bad(StatusCode::kInvalidArgument,
                   "--shard '" + text + "': expected I/N with 0 <= I < N, e.g. 0/4");
  const std::size_t slash = text.find('/');
  if (slash == std::string::npos || slash == 0 || slash + 1 == text.size()) return bad;
  const std::string index_text = text.substr(0, slash);
  const std::string count_text = text.substr(slash + 1);
  const auto digits = [](const std::string& s) {
    for (const unsigned char c : s)
      if (std::isdigit(c) == 0) return false;
    return s.size() <= 9;
  };
  if (!digits(index_text) || !digits(count_text)) return bad;
  const std::size_t index = std::stoul(index_text);
  const std::size_t count = std::stoul(count_text);
  if (count == 0 || index >= count) return bad;
  return std::make_pair(index, count);
}

nlohmann::json combinationToJson(const Combination& c) {
  nlohmann::json json = {{"id", c.id},
                         {"scene_path", c.scene_path},
                         {"scene", c.scene_name},
                         {"resolution", c.resolution},
                         {"backend", c.backend},
                         {"needs", needsModeName(c.needs)},
                         {"limit", c.limit}};
  if (!c.category.empty()) json["category"] = c.category;
  if (!c.scene_digest.empty()) json["scene_digest"] = c.scene_digest;
  if (!c.plugin_identity.empty()) json["plugin"] = c.plugin_identity;
  if (c.repetitions != 0) json["repetitions"] = c.repetitions;
  json["protocol"] = timingProtocolName(c.protocol);
  if (c.round != 0) json["round"] = c.round;
  if (c.kind != InputKind::kScene) {
    json["kind"] = inputKindName(c.kind);
    json["grid"] = c.grid;
  }
  return json;
}

Result<Combination> combinationFromJson(const nlohmann::json& json) {
  try {
    Combination c;
    c.id = json.at("id").get<std::string>();
    c.scene_path = json.at("scene_path").get<std::string>();
    c.scene_name = json.at("scene").get<std::string>();
    c.resolution = json.at("resolution").get<double>();
    c.backend = json.at("backend").get<std::string>();
    const std::optional<NeedsMode> needs = parseNeedsMode(json.at("needs").get<std::string>());
    if (!needs) return Status(StatusCode::kInvalidArgument, "combination: unknown needs mode");
    c.needs = *needs;
    c.limit = json.at("limit").get<std::uint64_t>();
    // Written only for stress scenes (and absent from studies made before the stress suite).
    c.category = json.value("category", std::string());
    // Absent from studies made before combinations carried their inputs.
    c.scene_digest = json.value("scene_digest", std::string());
    c.plugin_identity = json.value("plugin", std::string());
    c.repetitions = json.value("repetitions", 0);
    // Absent from studies made before there was a choice, which timed repeated.
    const std::optional<TimingProtocol> protocol =
        parseTimingProtocol(json.value("protocol", std::string("repeated")));
    if (!protocol) return Status(StatusCode::kInvalidArgument, "combination: unknown protocol");
    c.protocol = *protocol;
    c.round = json.value("round", 0);
    // Absent for mesh scenes (and from studies made before surfaces and FRep joined them).
    const std::optional<InputKind> kind = parseInputKind(json.value("kind", std::string("scene")));
    if (!kind) return Status(StatusCode::kInvalidArgument, "combination: unknown kind");
    c.kind = *kind;
    c.grid = json.value("grid", std::vector<int>());
    return c;
  } catch (const nlohmann::json::exception& e) {
    return Status(StatusCode::kInvalidArgument, std::string("combination: ") + e.what());
  }
}

}  // namespace collido::study
