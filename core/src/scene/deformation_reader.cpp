#include "deformation_reader.h"

#include <filesystem>
#include <map>

#include "drop_distance.h"

namespace collido::scene_reading {
namespace {

constexpr double kDegrees = 3.14159265358979323846 / 180.0;

Eigen::Vector3d unitVector(const Reader& r, const Node& parent, const std::string& key,
                           const Eigen::Vector3d& fallback) {
  if (!parent.has(key)) return fallback;
  const Eigen::Vector3d v = r.vector3(parent.at(key));
  if (!(v.norm() > 0.0)) r.fail(parent.at(key), key + " must not be the zero vector");
  return v.normalized();
}

DeformationTiming readTiming(const Reader& r, const Node& node) {
  DeformationTiming timing;
  const bool ramp = node.has("ramp");
  if (ramp) {
    if (!node.value.at("ramp").is_boolean() || !node.value.at("ramp").get<bool>())
      r.fail(node.at("ramp"), "ramp is true when given");
    if (node.has("period") || node.has("phase"))
      r.fail(node, "'ramp' and 'period'/'phase' exclude each other");
    return timing;  // period 0: the ramp
  }
  // Without a period, one cycle over the scene: the caller knows its frames.
  timing.period = node.has("period") ? r.positive(node, "period", 1.0) : -1.0;
  timing.phase = r.number(node, "phase", 0.0);
  return timing;
}

using RuleReader = void (*)(const Reader&, const Node&, const DeformContext&, DeformationRule&);

void readNoise(const Reader& r, const Node& n, const DeformContext& /*context*/,
               DeformationRule& rule) {
  r.expectObject(n, {"amplitude", "period", "phase", "seed"});
  rule.amplitude = r.number(n, "amplitude", 0.0);
  rule.seed = static_cast<std::uint64_t>(r.integer(n, "seed", 1, 0, INT64_MAX));
}

void readWave(const Reader& r, const Node& n, const DeformContext& /*context*/,
              DeformationRule& rule) {
  r.expectObject(n, {"amplitude", "wavelength", "period", "phase", "along", "direction", "origin"});
  rule.amplitude = r.number(n, "amplitude", 0.0);
  rule.wavelength = r.positive(n, "wavelength", 1.0);
  rule.along = unitVector(r, n, "along", Eigen::Vector3d::UnitX());
  rule.direction = unitVector(r, n, "direction", Eigen::Vector3d::UnitZ());
  if (n.has("origin")) rule.origin = r.vector3(n.at("origin"));
}

void readTwist(const Reader& r, const Node& n, const DeformContext& /*context*/,
               DeformationRule& rule) {
  r.expectObject(n, {"angle_deg", "length", "axis", "origin", "period", "phase", "ramp"});
  rule.angle = r.number(n, "angle_deg", 0.0) * kDegrees;
  rule.length = r.positive(n, "length", 1.0);
  rule.axis = unitVector(r, n, "axis", Eigen::Vector3d::UnitZ());
  if (n.has("origin")) rule.origin = r.vector3(n.at("origin"));
}

void readPulsate(const Reader& r, const Node& n, const DeformContext& /*context*/,
                 DeformationRule& rule) {
  r.expectObject(n, {"amplitude", "period", "phase", "ramp"});
  rule.amplitude = r.number(n, "amplitude", 0.0);
}

void readBend(const Reader& r, const Node& n, const DeformContext& /*context*/,
              DeformationRule& rule) {
  r.expectObject(n,
                 {"angle_deg", "length", "axis", "direction", "origin", "period", "phase", "ramp"});
  rule.angle = r.number(n, "angle_deg", 0.0) * kDegrees;
  if (std::abs(rule.angle) > 2.0 * 3.14159265358979323846)
    r.fail(n.at("angle_deg"), "a bend turns by at most 360 degrees");
  rule.length = r.positive(n, "length", 1.0);
  rule.axis = unitVector(r, n, "axis", Eigen::Vector3d::UnitZ());
  rule.direction = unitVector(r, n, "direction", Eigen::Vector3d::UnitX());
  if (std::abs(rule.direction.dot(rule.axis)) > 1.0 - 1e-9)
    r.fail(n.at("direction"), "the bend direction must not be along the axis");
  if (n.has("origin")) rule.origin = r.vector3(n.at("origin"));
}

void readSquash(const Reader& r, const Node& n, const DeformContext& /*context*/,
                DeformationRule& rule) {
  r.expectObject(n, {"amount", "axis", "origin", "period", "phase", "ramp"});
  rule.amount = r.number(n, "amount", 0.0);
  if (!(rule.amount >= 0.0 && rule.amount < 1.0))
    r.fail(n.has("amount") ? n.at("amount") : n, "amount must be in [0, 1)");
  rule.axis = unitVector(r, n, "axis", Eigen::Vector3d::UnitZ());
  if (n.has("origin")) rule.origin = r.vector3(n.at("origin"));
}

// A sheet settling onto an earlier object: each vertex's stop distance is cast in the world at
// frame 0 (both objects' first poses and shapes).
void readDrape(const Reader& r, const Node& n, const DeformContext& context,
               DeformationRule& rule) {
  r.expectObject(n, {"onto", "direction", "drop", "penetration", "period", "phase", "ramp"});
  const SceneObject& object = *context.object;
  if (object.states.size() > 1)
    r.fail(n, "a drape moves an object with one shape (its stop distances are per vertex)");
  if (!n.has("onto")) r.fail(n, "missing 'onto' (the object it settles onto)");
  const std::string name = r.string(n.at("onto"));
  const SceneObject* target = context.earlier ? context.earlier(name) : nullptr;
  if (target == nullptr)
    r.fail(n.at("onto"), "'" + name + "' is not an object defined before this one");
  const Eigen::Vector3d world_direction = unitVector(r, n, "direction", -Eigen::Vector3d::UnitZ());
  rule.amplitude = r.positive(n, "drop", 1.0);
  rule.penetration = r.number(n, "penetration", 0.0);
  if (rule.penetration < 0.0) r.fail(n.at("penetration"), "penetration must be >= 0");
  const Pose& pose = object.poseAt(0);
  const Eigen::Matrix3Xd world = pose * object.mesh->vertices;
  rule.stops = std::make_shared<const std::vector<double>>(
      dropDistances(world, world_direction, *target->shapeAt(0), target->poseAt(0)));
  rule.direction = pose.linear().transpose() * world_direction;
}

const std::map<std::string, std::pair<DeformationRule::Kind, RuleReader>>& ruleReaders() {
  static const std::map<std::string, std::pair<DeformationRule::Kind, RuleReader>> table = {
      {"noise", {DeformationRule::Kind::kNoise, &readNoise}},
      {"wave", {DeformationRule::Kind::kWave, &readWave}},
      {"twist", {DeformationRule::Kind::kTwist, &readTwist}},
      {"pulsate", {DeformationRule::Kind::kPulsate, &readPulsate}},
      {"bend", {DeformationRule::Kind::kBend, &readBend}},
      {"squash", {DeformationRule::Kind::kSquash, &readSquash}},
      {"drape", {DeformationRule::Kind::kDrape, &readDrape}}};
  return table;
}

DeformationRule readRule(const Reader& r, const Node& node, std::size_t frames,
                         const DeformContext& context) {
  if (!node.value.is_object() || node.value.size() - (node.has("comment") ? 1 : 0) != 1) {
    r.fail(node,
           "a rule is an object with one key, its kind (noise, wave, twist, pulsate, "
           "bend, squash)");
  }
  std::string kind;
  for (const auto& item : node.value.items()) {
    if (item.key() != "comment") kind = item.key();
  }
  const auto found = ruleReaders().find(kind);
  if (found == ruleReaders().end()) {
    r.fail(node,
           "unknown rule '" + kind + "' (known: noise, wave, twist, pulsate, bend, squash, drape)");
  }
  const Node body = node.at(kind);
  DeformationRule rule;
  rule.kind = found->second.first;
  found->second.second(r, body, context, rule);
  rule.timing = readTiming(r, body);
  if (rule.timing.period < 0.0) rule.timing.period = static_cast<double>(frames);
  return rule;
}

}  // namespace

std::shared_ptr<const Deformation> readDeformation(const Reader& r, const Node& node,
                                                   const std::string& base_directory,
                                                   std::size_t frames,
                                                   const DeformContext& context) {
  r.expectObject(node, {"rules", "recorded", "select"});
  auto deformation = std::make_shared<Deformation>();
  deformation->frames = frames;
  if (node.has("select")) {
    const Node select = node.at("select");
    r.expectObject(select, {"low", "high"});
    if (select.has("low")) deformation->select_low = r.vector3(select.at("low"));
    if (select.has("high")) deformation->select_high = r.vector3(select.at("high"));
    if (!(deformation->select_low.array() <= deformation->select_high.array()).all())
      r.fail(select, "low must not exceed high in any coordinate");
  }
  if (node.has("recorded")) {
    const Node file = node.at("recorded");
    const std::filesystem::path path =
        (std::filesystem::path(base_directory) / r.string(file)).lexically_normal();
    Result<RecordedPositions> recording = readRecordedPositions(path.string());
    if (!recording.ok()) r.fail(file, recording.status().message());
    if (recording.value().frames < frames) {
      r.fail(file, path.string() + " records " + std::to_string(recording.value().frames) +
                       " frames but the scene has " + std::to_string(frames));
    }
    deformation->recorded = std::make_shared<const RecordedPositions>(std::move(recording).value());
  }
  if (node.has("rules")) {
    const Node rules = node.at("rules");
    r.expectArray(rules);
    for (std::size_t i = 0; i < rules.value.size(); ++i)
      deformation->rules.push_back(readRule(r, rules.at(i), frames, context));
  }
  if (deformation->rules.empty() && !deformation->recorded)
    r.fail(node, "a deformation needs 'rules' or a 'recorded' file");
  const bool drapes = std::any_of(
      deformation->rules.begin(), deformation->rules.end(),
      [](const DeformationRule& rule) { return rule.kind == DeformationRule::Kind::kDrape; });
  if (drapes && deformation->recorded)
    r.fail(node, "a drape falls from the rest shape: it does not combine with 'recorded'");
  return deformation;
}

std::vector<std::size_t> readSchedule(const Reader& r, const Node* node, std::size_t states,
                                      std::size_t frames) {
  std::vector<std::size_t> schedule(frames);
  if (node == nullptr) {
    for (std::size_t f = 0; f < frames; ++f)
      schedule[f] = std::min(states - 1, f * states / frames);
    return schedule;
  }
  if (node->value.is_object()) {
    r.expectObject(*node, {"hold"});
    if (!node->has("hold")) r.fail(*node, "missing 'hold' (frames each state stays active)");
    const auto hold = static_cast<std::size_t>(r.integer(*node, "hold", 1, 1, INT64_MAX));
    for (std::size_t f = 0; f < frames; ++f)
      schedule[f] = (f / hold) % states;
    return schedule;
  }
  r.expectArray(*node);
  if (node->value.size() != frames) {
    r.fail(*node, "has " + std::to_string(node->value.size()) + " entries but the scene has " +
                      std::to_string(frames) + " frames");
  }
  for (std::size_t f = 0; f < frames; ++f) {
    schedule[f] =
        static_cast<std::size_t>(r.integer(node->at(f), 0, static_cast<std::int64_t>(states) - 1));
  }
  return schedule;
}

}  // namespace collido::scene_reading
