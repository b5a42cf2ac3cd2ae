// closeRecording: the journal's completed frames written as a scene file (scenes/README.md).
// The JSON is emitted here rather than by a JSON library because this component promises to
// depend on the standard library and Eigen only; what it writes is read back by the scene
// loader (nlohmann::json), which every test of a recording goes through.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <set>
#include <string>

#include <collido/record/recorder.h>

#include "files.h"
#include "journal.h"

namespace collido {
namespace {

using record::numberText;
using record::PoseNumbers;
using record::Replay;

// A JSON string of UTF-8 text (object names are checked to be; the folder's name is replaced
// when it is not).
std::string jsonString(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (static_cast<unsigned char>(c) < 0x20) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\u%04x", static_cast<unsigned>(c));
      out += escaped;
      continue;
    }
    if (c == '"' || c == '\\') out.push_back('\\');
    out.push_back(c);
  }
  return out + "\"";
}

std::string poseJson(const PoseNumbers& p) {
  std::string out = "{\"translation\": [" + numberText(p[9]) + ", " + numberText(p[10]) + ", " +
                    numberText(p[11]) + "], \"rotation\": {\"matrix\": [";
  for (std::size_t row = 0; row < 3; ++row) {
    out += row == 0 ? "[" : ", [";
    for (std::size_t col = 0; col < 3; ++col)
      out += (col == 0 ? "" : ", ") + numberText(p[3 * row + col]);
    out += "]";
  }
  return out + "]}}";
}

// Ascending frames as [first, last] ranges.
std::string rangesJson(const std::vector<std::size_t>& frames) {
  std::string out = "[";
  for (std::size_t i = 0; i < frames.size();) {
    std::size_t j = i;
    while (j + 1 < frames.size() && frames[j + 1] == frames[j] + 1)
      ++j;
    out +=
        (i == 0 ? "[" : ", [") + std::to_string(frames[i]) + ", " + std::to_string(frames[j]) + "]";
    i = j + 1;
  }
  return out + "]";
}

// One object: its mesh, its pose (one, when it never moves) or one pose per frame (the first
// known pose stands in for frames before it existed), and the frames it exists in.
std::string objectJson(const Replay::Object& o, std::size_t frames) {
  std::string out = "    {\"name\": " + jsonString(o.name) +
                    ", \"shape\": {\"mesh\": " + jsonString(o.mesh_file) + "}";
  const std::size_t end = std::min(o.end, frames);
  if (o.first > 0 || end < frames) {
    out += ", \"frames\": [[" + std::to_string(o.first) + ", " + std::to_string(end - 1) + "]]";
  }
  const bool still =
      std::all_of(o.poses.begin(), o.poses.begin() + static_cast<long>(end - o.first),
                  [&](const PoseNumbers& p) { return p == o.poses[0]; });
  if (still) return out + ", \"pose\": " + poseJson(o.poses[0]) + "}";
  out += ",\n     \"motion\": {\"poses\": [";
  for (std::size_t f = 0; f < frames; ++f) {
    const std::size_t k = std::min(f < o.first ? 0 : f - o.first, end - o.first - 1);
    out += (f == 0 ? "\n       " : ",\n       ") + poseJson(o.poses[k]);
  }
  return out + "]}}";
}

}  // namespace

std::size_t closeRecording(const std::string& folder) {
  const Replay replay = record::replayJournal(folder);
  const std::string where = folder + "/" + record::kJournalFile;
  if (replay.frames == 0) throw RecordError(where + ": no frame was completed: no scene to write");
  if (replay.queries.empty()) throw RecordError(where + ": no query was asked: no scene to write");

  // Objects that never existed in a completed frame are left out; the rest keep their order.
  std::vector<std::size_t> written;
  for (std::size_t id = 0; id < replay.objects.size(); ++id) {
    const Replay::Object& o = replay.objects[id];
    if (o.first < replay.frames && o.end > o.first) written.push_back(id);
  }
  std::string objects;
  for (const std::size_t id : written)
    objects += (objects.empty() ? "" : ",\n") + objectJson(replay.objects[id], replay.frames);

  // A query is named after its objects and kind; a second of the same gets its tolerance.
  std::set<std::string> seen;
  std::string queries;
  for (const Replay::Query& q : replay.queries) {
    std::string name =
        replay.objects[q.a].name + "-" + replay.objects[q.b].name + " " + record::kindName(q.kind);
    if (seen.count(name) != 0) name += " (tolerance " + numberText(q.tolerance) + ")";
    const std::string base = name;
    for (int copy = 2; seen.count(name) != 0; ++copy)
      name = base + " #" + std::to_string(copy);
    seen.insert(name);
    queries += std::string(queries.empty() ? "" : ",\n") + "    {\"name\": " + jsonString(name) +
               ", \"a\": " + jsonString(replay.objects[q.a].name) +
               ", \"b\": " + jsonString(replay.objects[q.b].name) + ", \"kind\": \"" +
               record::kindName(q.kind) + "\"";
    if (q.tolerance > 0.0) queries += ", \"abs_tolerance\": " + numberText(q.tolerance);
    if (q.frames.size() < replay.frames) queries += ", \"frames\": " + rangesJson(q.frames);
    queries += "}";
  }

  std::filesystem::path path = std::filesystem::absolute(folder).lexically_normal();
  if (path.filename().empty()) path = path.parent_path();
  std::string name = path.filename().string();
  if (!record::nameProblem(name).empty()) name = "recording";
  const std::string scene = "{\n  \"name\": " + jsonString(name) +
                            ",\n  \"description\": \"recorded by collido::Recorder\",\n" +
                            "  \"frames\": " + std::to_string(replay.frames) +
                            ",\n  \"objects\": [\n" + objects + "\n  ],\n  \"queries\": [\n" +
                            queries + "\n  ]\n}\n";
  record::writeFileAtomically(folder + "/scene.json", scene);
  return replay.frames;
}

}  // namespace collido
