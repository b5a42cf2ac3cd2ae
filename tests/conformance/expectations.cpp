#include "expectations.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

namespace collido::conformance {
namespace {

using Json = nlohmann::json;

constexpr const char* kFields[] = {"disagreeing_frames",  "false_negatives",  "false_positives",
                                   "missed_pairs",        "extra_pairs",      "invalid_pairs",
                                   "false_contact_pairs", "contacts_off_set", "malformed_contacts"};
// Written only where non-zero, so records of queries without contacts keep their six counts.
constexpr std::size_t kContactFieldsFrom = 6;

std::size_t* field(Disagreement& d, const std::string& name) {
  if (name == "disagreeing_frames") return &d.disagreeing_frames;
  if (name == "false_negatives") return &d.false_negatives;
  if (name == "false_positives") return &d.false_positives;
  if (name == "missed_pairs") return &d.missed_pairs;
  if (name == "extra_pairs") return &d.extra_pairs;
  if (name == "invalid_pairs") return &d.invalid_pairs;
  if (name == "false_contact_pairs") return &d.false_contact_pairs;
  if (name == "contacts_off_set") return &d.contacts_off_set;
  if (name == "malformed_contacts") return &d.malformed_contacts;
  return nullptr;
}

Json toJson(Disagreement d) {
  Json j = Json::object();
  std::size_t index = 0;
  for (const char* name : kFields) {
    if (index++ < kContactFieldsFrom || *field(d, name) != 0) j[name] = *field(d, name);
  }
  return j;
}

}  // namespace

bool Disagreement::none() const {
  return *this == Disagreement{};
}

bool Disagreement::operator==(const Disagreement& o) const {
  return disagreeing_frames == o.disagreeing_frames && false_negatives == o.false_negatives &&
         false_positives == o.false_positives && missed_pairs == o.missed_pairs &&
         extra_pairs == o.extra_pairs && invalid_pairs == o.invalid_pairs &&
         false_contact_pairs == o.false_contact_pairs && contacts_off_set == o.contacts_off_set &&
         malformed_contacts == o.malformed_contacts;
}

std::string Disagreement::toString() const {
  std::ostringstream out;
  out << "disagreeing frames " << disagreeing_frames << ", false negatives " << false_negatives
      << ", false positives " << false_positives << ", missed pairs " << missed_pairs
      << ", extra pairs " << extra_pairs << ", invalid pairs " << invalid_pairs;
  if (false_contact_pairs + contacts_off_set + malformed_contacts != 0) {
    out << ", contacts naming false pairs " << false_contact_pairs << ", contacts off their set "
        << contacts_off_set << ", malformed contacts " << malformed_contacts;
  }
  return out.str();
}

Disagreement disagreementOf(const FrameRecord& f, QueryKind kind) {
  Disagreement d;
  d.false_negatives = f.oracle_intersecting && !f.reported_intersecting ? 1 : 0;
  d.false_positives = !f.oracle_intersecting && f.reported_intersecting ? 1 : 0;
  d.disagreeing_frames = f.disagrees(kind) ? 1 : 0;
  // A distance answer's points that do not hold together are a false witness too.
  d.invalid_pairs = f.invalid_pairs + (f.invalid_distance_witness ? 1 : 0);
  if (queryKindInfo(kind).has(AnswerPart::kPairSet)) {
    // A truncated answer leaves pairs out on purpose; only its wrong pairs count.
    if (!f.truncated) d.missed_pairs = f.oracle_pairs - f.matched_pairs;
    d.extra_pairs = f.reported_pairs - f.matched_pairs;
  }
  if (f.contact) {
    d.false_contact_pairs = f.contact->false_pairs;
    d.contacts_off_set = f.contact->off_set;
    d.malformed_contacts = f.contact->bad_normals + f.contact->bad_depths;
  }
  return d;
}

Disagreement disagreementOf(const QueryMeasurement& m) {
  Disagreement sum;
  for (const FrameRecord& f : m.frames) {
    const Disagreement d = disagreementOf(f, m.kind);
    sum.disagreeing_frames += d.disagreeing_frames;
    sum.false_negatives += d.false_negatives;
    sum.false_positives += d.false_positives;
    sum.missed_pairs += d.missed_pairs;
    sum.extra_pairs += d.extra_pairs;
    sum.invalid_pairs += d.invalid_pairs;
    sum.false_contact_pairs += d.false_contact_pairs;
    sum.contacts_off_set += d.contacts_off_set;
    sum.malformed_contacts += d.malformed_contacts;
  }
  return sum;
}

Disagreement Expectations::expectedFor(const std::string& key) const {
  if (exact) return {};
  const auto found = measured.find(key);
  return found == measured.end() ? Disagreement{} : found->second;
}

std::string expectationsFileName(const std::string& variant) {
  std::string name = variant;
  for (char& c : name) {
    if (c == ':' || c == '/' || c == '[' || c == ']' || c == '=' || c == ';') c = '_';
  }
  return name + ".json";
}

Result<Expectations> loadExpectations(const std::string& directory, const std::string& variant) {
  Expectations out;
  if (directory.empty()) return out;
  const std::string path = directory + "/" + expectationsFileName(variant);
  std::ifstream in(path);
  if (!in) return out;
  out.file = path;
  try {
    const Json j = Json::parse(in);
    if (j.at("variant").get<std::string>() != variant) {
      return Status(StatusCode::kInvalidArgument, path + ": /variant: names '" +
                                                      j.at("variant").get<std::string>() +
                                                      "', not '" + variant + "'");
    }
    out.exact = j.at("exact").get<bool>();
    if (j.contains("measured")) {
      for (const auto& [key, counts] : j.at("measured").items()) {
        Disagreement d;
        for (const auto& [name, value] : counts.items()) {
          std::size_t* slot = field(d, name);
          if (slot == nullptr) {
            return Status(StatusCode::kInvalidArgument,
                          path + ": /measured/" + key + ": unknown count '" + name + "'");
          }
          *slot = value.get<std::size_t>();
        }
        out.measured[key] = d;
      }
    }
  } catch (const Json::exception& e) {
    return Status(StatusCode::kInvalidArgument, path + ": " + e.what());
  }
  return out;
}

Status recordMeasurement(const std::string& directory, const std::string& variant,
                         const std::string& key, const Disagreement& counts) {
  std::filesystem::create_directories(directory);
  const std::string path = directory + "/" + expectationsFileName(variant);
  Json j = {{"variant", variant}, {"exact", false}, {"measured", Json::object()}};
  if (std::ifstream in(path); in) {
    try {
      j = Json::parse(in);
    } catch (const Json::exception& e) {
      return Status(StatusCode::kInvalidArgument, path + ": " + e.what());
    }
  }
  if (!counts.none()) j["measured"][key] = toJson(counts);
  bool all_exact = true;
  for (const auto& item : j["measured"].items()) {
    for (const char* name : kFields)
      all_exact = all_exact && item.value().value(name, 0) == 0;
  }
  j["exact"] = all_exact;
  std::ofstream out(path, std::ios::trunc);
  out << j.dump(2) << "\n";
  if (!out) return Status(StatusCode::kInvalidArgument, "cannot write " + path);
  return {};
}

}  // namespace collido::conformance
