#include <collido/study/oracle_store.h>

#include <filesystem>
#include <iostream>

#include <nlohmann/json.hpp>

#include <collido/io/files.h>
#include <collido/study/result_store.h>

namespace collido::study {

using Json = nlohmann::json;

StoredOracle::StoredOracle(const std::string& directory, OracleCache& cache) : cache_(cache) {
  if (directory.empty()) return;
  path_ = oracleStorePath(directory, cache);
  if (Status s = loadOracleAnswers(path_, cache); !s.ok())
    std::cerr << "note: " << s.message() << "; computing the answers afresh\n";
  known_ = cache.computed();
}

void StoredOracle::keepNew() const {
  if (path_.empty() || cache_.computed() == known_) return;
  if (Status s = saveOracleAnswers(path_, cache_); !s.ok())
    std::cerr << "note: " << s.message() << "\n";
}

std::string oracleStorePath(const std::string& directory, const OracleCache& cache) {
  return (std::filesystem::path(directory) / (cache.fingerprint() + ".json")).string();
}

Status loadOracleAnswers(const std::string& path, OracleCache& cache) {
  // No stored answers yet (or none readable): the oracle computes them.
  const Result<std::string> text = io::readTextFile(path);
  if (!text.ok()) return {};
  const auto bad = [&](const std::string& why) {
    return Status(StatusCode::kInvalidArgument, path + ": " + why);
  };
  try {
    const Json document = Json::parse(text.value());
    if (document.at("fingerprint").get<std::string>() != cache.fingerprint()) {
      return bad("the stored answers are for another scene (fingerprint differs)");
    }
    // Equal digests of different inputs are astronomically unlikely; equal sizes make sure.
    if (document.at("sizes").get<std::string>() != cache.inputSizes()) {
      return bad("the stored answers are for another scene (its sizes, " +
                 document.at("sizes").get<std::string>() + ", differ)");
    }
    // Read everything before adding anything: a file broken half-way adds nothing.
    std::vector<std::pair<OracleCache::Key, OracleAnswer>> read;
    for (const Json& entry : document.at("answers")) {
      OracleAnswer answer;
      const OracleCache::Key key{entry.at(0).get<std::size_t>(), entry.at(1).get<std::size_t>(),
                                 entry.at(2).get<std::size_t>()};
      answer.intersecting = entry.at(3).get<bool>();
      answer.candidate_pairs = entry.at(4).get<std::size_t>();
      answer.exact_tests = entry.at(5).get<std::size_t>();
      const Json& flat = entry.at(6);
      if (flat.size() % 2 != 0) return bad("a pair list of odd length");
      for (std::size_t i = 0; i < flat.size(); i += 2) {
        answer.pairs.push_back(
            TrianglePair{flat.at(i).get<std::int32_t>(), flat.at(i + 1).get<std::int32_t>()});
      }
      if (answer.intersecting == answer.pairs.empty()) {
        return bad("an answer whose pairs contradict its verdict");
      }
      if (entry.size() > 7 && !entry.at(7).is_null()) {
        // [distance, pair a, pair b, point a xyz, point b xyz, candidates, exact tests]
        const Json& d = entry.at(7);
        MeshDistance distance;
        distance.distance = d.at(0).get<double>();
        distance.pair = TrianglePair{d.at(1).get<std::int32_t>(), d.at(2).get<std::int32_t>()};
        for (int k = 0; k < 3; ++k) {
          distance.point_a[k] = d.at(3 + k).get<double>();
          distance.point_b[k] = d.at(6 + k).get<double>();
        }
        distance.candidate_pairs = d.at(9).get<std::size_t>();
        distance.exact_tests = d.at(10).get<std::size_t>();
        if (!(distance.distance >= 0.0) || (distance.distance == 0.0) != answer.intersecting) {
          return bad("a distance that contradicts its verdict");
        }
        answer.distance = distance;
      }
      if (entry.size() > 8) {
        // [outcome, t_lo, t_hi, witness a, witness b, width, distances, intersection tests]
        const Json& c = entry.at(8);
        ExactFirstContact contact;
        const int outcome = c.at(0).get<int>();
        if (outcome < 0 || outcome > static_cast<int>(ExactFirstContact::Outcome::kUndecided)) {
          return bad("a first contact of unknown outcome " + std::to_string(outcome));
        }
        contact.outcome = static_cast<ExactFirstContact::Outcome>(outcome);
        contact.t_lo = c.at(1).get<double>();
        contact.t_hi = c.at(2).get<double>();
        contact.witness = TrianglePair{c.at(3).get<std::int32_t>(), c.at(4).get<std::int32_t>()};
        answer.first_contact_width = c.at(5).get<double>();
        contact.distance_evaluations = c.at(6).get<std::size_t>();
        contact.intersection_tests = c.at(7).get<std::size_t>();
        if (!(0.0 <= contact.t_lo && contact.t_lo <= contact.t_hi && contact.t_hi <= 1.0) ||
            !(answer.first_contact_width > 0.0)) {
          return bad("a first contact whose bracket is not within the step");
        }
        answer.first_contact = contact;
      }
      read.emplace_back(key, std::move(answer));
    }
    for (auto& [key, answer] : read)
      cache.add(key, std::move(answer));
  } catch (const Json::exception& e) {
    return bad(std::string("not a stored oracle answer file: ") + e.what());
  }
  return {};
}

Status saveOracleAnswers(const std::string& path, const OracleCache& cache) {
  Json answers = Json::array();
  for (const auto& [key, answer] : cache.answers()) {
    Json flat = Json::array();
    for (const TrianglePair& p : answer.pairs) {
      flat.push_back(p.a);
      flat.push_back(p.b);
    }
    Json entry =
        Json::array({std::get<0>(key), std::get<1>(key), std::get<2>(key), answer.intersecting,
                     answer.candidate_pairs, answer.exact_tests, std::move(flat)});
    if (answer.distance) {
      const MeshDistance& d = *answer.distance;
      entry.push_back(Json::array({d.distance, d.pair.a, d.pair.b, d.point_a.x(), d.point_a.y(),
                                   d.point_a.z(), d.point_b.x(), d.point_b.y(), d.point_b.z(),
                                   d.candidate_pairs, d.exact_tests}));
    }
    if (answer.first_contact) {
      if (!answer.distance) entry.push_back(nullptr);
      const ExactFirstContact& c = *answer.first_contact;
      entry.push_back(
          Json::array({static_cast<int>(c.outcome), c.t_lo, c.t_hi, c.witness.a, c.witness.b,
                       answer.first_contact_width, c.distance_evaluations, c.intersection_tests}));
    }
    answers.push_back(std::move(entry));
  }
  std::error_code ec;
  std::filesystem::create_directories(std::filesystem::path(path).parent_path(), ec);
  if (ec) return Status(StatusCode::kInvalidArgument, path + ": " + ec.message());
  const Json document{{"fingerprint", cache.fingerprint()},
                      {"sizes", cache.inputSizes()},
                      {"answers", std::move(answers)}};
  return io::writeFileAtomically(path, document.dump());
}

}  // namespace collido::study
