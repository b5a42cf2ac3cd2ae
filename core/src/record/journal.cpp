#include "journal.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

namespace collido::record {
namespace {

// Reads one block's lines into `replay`, checking ids as it goes; `fail` names the line.
class BlockReader {
 public:
  BlockReader(Replay& replay, std::string path) : replay_(replay), path_(std::move(path)) {}

  // Applies a complete block (its lines up to "E"). Throws on a malformed line.
  void apply(const std::vector<std::pair<std::size_t, std::string>>& block) {
    const std::size_t frame = replay_.frames;
    for (const auto& [number, line] : block) {
      line_ = number;
      std::istringstream in(line);
      char tag = 0;
      in >> tag;
      if (tag == 'O') {
        addObject(in, frame);
      } else if (tag == 'X') {
        long long last = 0;
        Replay::Object& o = replay_.objects[objectId(in)];
        if (!(in >> last) || last < -1) fail("expected the last frame, or -1");
        o.end = std::max(o.first, static_cast<std::size_t>(last + 1));
      } else if (tag == 'Q') {
        addQuery(in);
      } else if (tag == 'P') {
        Replay::Object& o = replay_.objects[objectId(in)];
        PoseNumbers pose{};
        for (double& v : pose) {
          if (!(in >> v) || !std::isfinite(v)) fail("expected 12 finite numbers");
        }
        pending_poses_.emplace_back(&o - replay_.objects.data(), pose);
      } else if (tag == 'A') {
        std::size_t id = 0;
        while (in >> id) {
          if (id >= replay_.queries.size()) fail("unknown query " + std::to_string(id));
          std::vector<std::size_t>& frames = replay_.queries[id].frames;
          if (frames.empty() || frames.back() != frame) frames.push_back(frame);
        }
      } else if (tag != 'E') {
        fail(std::string("unknown line kind '") + tag + "'");
      }
    }
    // Every existing object's pose in this frame: the last set, identity at first.
    for (std::size_t id = 0; id < replay_.objects.size(); ++id) {
      Replay::Object& o = replay_.objects[id];
      if (o.first > frame) continue;
      o.poses.push_back(o.poses.empty() ? PoseNumbers{1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0}
                                        : o.poses.back());
    }
    for (const auto& [id, pose] : pending_poses_) {
      Replay::Object& o = replay_.objects[static_cast<std::size_t>(id)];
      if (o.first <= frame) o.poses.back() = pose;
    }
    pending_poses_.clear();
    ++replay_.frames;
  }

  [[noreturn]] void fail(const std::string& problem) const {
    throw RecordError(path_ + ":" + std::to_string(line_) + ": " + problem);
  }

 private:
  std::size_t objectId(std::istringstream& in) const {
    std::size_t id = 0;
    if (!(in >> id) || id >= replay_.objects.size()) fail("expected an object id");
    return id;
  }

  void addObject(std::istringstream& in, std::size_t frame) {
    std::size_t id = 0;
    Replay::Object o;
    if (!(in >> id >> o.mesh_file) || id != replay_.objects.size())
      fail("expected the next object id and a mesh file");
    in.get();  // the one space before the name, which may hold spaces of its own
    std::getline(in, o.name);
    if (const std::string problem = nameProblem(o.name); !problem.empty()) fail(problem);
    o.first = frame;
    replay_.objects.push_back(std::move(o));
  }

  void addQuery(std::istringstream& in) {
    std::size_t id = 0;
    std::string kind;
    Replay::Query q;
    if (!(in >> id >> q.a >> q.b >> kind >> q.tolerance) || id != replay_.queries.size() ||
        q.a >= replay_.objects.size() || q.b >= replay_.objects.size() || q.a == q.b) {
      fail("expected a query: id, two object ids, a kind and a tolerance");
    }
    bool known = false;
    for (const RecordedKind k : {RecordedKind::kBoolean, RecordedKind::kAllPairs,
                                 RecordedKind::kContacts, RecordedKind::kDistance}) {
      if (kind == kindName(k)) {
        q.kind = k;
        known = true;
      }
    }
    if (!known) fail("unknown query kind '" + kind + "'");
    replay_.queries.push_back(q);
  }

  Replay& replay_;
  std::string path_;
  std::size_t line_ = 0;
  std::vector<std::pair<std::ptrdiff_t, PoseNumbers>> pending_poses_;
};

}  // namespace

std::string nameProblem(const std::string& name) {
  if (name.empty()) return "an object needs a name";
  if (name.front() == ' ' || name.back() == ' ') return "the name begins or ends with a space";
  for (std::size_t i = 0; i < name.size();) {
    const auto c = static_cast<unsigned char>(name[i]);
    if (c < 0x20 || c == 0x7f)
      return "the name has a control character at byte " + std::to_string(i);
    // A UTF-8 sequence: its lead byte gives its length, each further byte is 10xxxxxx.
    const std::size_t length = c < 0x80           ? 1
                               : (c >> 5) == 0x6  ? 2
                               : (c >> 4) == 0xe  ? 3
                               : (c >> 3) == 0x1e ? 4
                                                  : 0;
    bool valid = length != 0 && i + length <= name.size() && !(c == 0xc0 || c == 0xc1);
    for (std::size_t k = 1; valid && k < length; ++k)
      valid = (static_cast<unsigned char>(name[i + k]) & 0xc0) == 0x80;
    if (!valid) return "the name is not UTF-8 (byte " + std::to_string(i) + ")";
    i += length;
  }
  return "";
}

const char* kindName(RecordedKind kind) {
  switch (kind) {
    case RecordedKind::kBoolean:
      return "boolean";
    case RecordedKind::kAllPairs:
      return "all_pairs";
    case RecordedKind::kContacts:
      return "contacts";
    case RecordedKind::kDistance:
      return "distance";
  }
  return "boolean";
}

std::string numberText(double value) {
  char text[32];
  const std::to_chars_result end = std::to_chars(text, text + sizeof text, value);
  return std::string(text, end.ptr);
}

Replay replayJournal(const std::string& folder) {
  const std::string path = folder + "/" + kJournalFile;
  std::ifstream file(path, std::ios::binary);
  if (!file) throw RecordError(path + ": cannot be read (is this a recording folder?)");
  std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  Replay replay;
  BlockReader reader(replay, path);
  std::vector<std::pair<std::size_t, std::string>> block;
  std::size_t number = 0;
  std::size_t start = 0;
  // Only lines ended by a newline count: a torn last line belongs to a block cut short.
  for (std::size_t end = text.find('\n'); end != std::string::npos;
       start = end + 1, end = text.find('\n', start)) {
    const std::string line = text.substr(start, end - start);
    if (++number == 1) {
      if (line != kJournalHeader) {
        std::string problem = path + ":1: expected '" + kJournalHeader + "', got '";
        problem += line;
        throw RecordError(problem + "'");
      }
      continue;
    }
    block.emplace_back(number, line);
    if (line.rfind("E ", 0) != 0) continue;
    if (line != "E " + std::to_string(replay.frames)) {
      throw RecordError(path + ":" + std::to_string(number) + ": expected 'E " +
                        std::to_string(replay.frames) + "'");
    }
    reader.apply(block);
    block.clear();
  }
  if (number == 0) throw RecordError(path + ": empty (no header line)");
  return replay;
}

}  // namespace collido::record
