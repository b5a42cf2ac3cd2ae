#include <collido/study/oracle_store.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include <collido/study/result_store.h>

namespace collido::study {

using Json = nlohmann::json;

std::string oracleStorePath(const std::string& directory, const OracleCache& cache) {
  return (std::filesystem::path(directory) / (cache.fingerprint() + ".json")).string();
}

Status loadOracleAnswers(const std::string& path, OracleCache& cache) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return {};
  std::stringstream text;
  text << in.rdbuf();
  const auto bad = [&](const std::string& why) {
    return Status(StatusCode::kInvalidArgument, path + ": " + why);
  };
  try {
    const Json document = Json::parse(text.str());
    if (document.at("fingerprint").get<std::string>() != cache.fingerprint()) {
      return bad("the stored answers are for another scene (fingerprint differs)");
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
    answers.push_back(
        Json::array({std::get<0>(key), std::get<1>(key), std::get<2>(key), answer.intersecting,
                     answer.candidate_pairs, answer.exact_tests, std::move(flat)}));
  }
  std::error_code ec;
  std::filesystem::create_directories(std::filesystem::path(path).parent_path(), ec);
  if (ec) return Status(StatusCode::kInvalidArgument, path + ": " + ec.message());
  const Json document{{"fingerprint", cache.fingerprint()}, {"answers", std::move(answers)}};
  return writeFileAtomically(path, document.dump());
}

}  // namespace collido::study
