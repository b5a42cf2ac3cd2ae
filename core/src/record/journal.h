// The recording's journal (journal.txt): one block of lines per completed frame, appended and
// flushed as the frame ends, so that a process killed mid-run leaves whole frames and at most
// one torn block at the end, which replay drops.
//
//   collido-recording 1                 first line
//   O <id> <mesh file> <name>           an object added (the name is the rest of the line)
//   X <id> <last frame or -1>           an object removed: the last frame it exists in
//   Q <id> <a> <b> <kind> <tolerance>   a query, before the first frame that asks it
//   P <id> <r00 ... r22> <t0 t1 t2>     a pose changed (rotation row by row, translation)
//   A <query id> ...                    the queries this frame asks
//   E <frame>                           the block is complete
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <collido/record/recorder.h>

namespace collido::record {

constexpr const char* kJournalFile = "journal.txt";
constexpr const char* kJournalHeader = "collido-recording 1";

/// Rotation row by row, then translation.
using PoseNumbers = std::array<double, 12>;

const char* kindName(RecordedKind kind);

/// Why `name` cannot name an object, or "": it must be non-empty UTF-8 without control
/// characters or surrounding spaces, since it is the last field of a journal line and a JSON
/// string in the scene.
std::string nameProblem(const std::string& name);

/// The shortest text that reads back as the same double.
std::string numberText(double value);

/// What replaying a journal gives: the completed frames' objects, poses and queries.
struct Replay {
  struct Object {
    std::string name;
    std::string mesh_file;           ///< relative to the folder
    std::size_t first = 0;           ///< the first frame it exists in
    std::size_t end = SIZE_MAX;      ///< one past the last (removed); SIZE_MAX: never removed
    std::vector<PoseNumbers> poses;  ///< one per frame from `first`
  };
  struct Query {
    std::size_t a = 0;
    std::size_t b = 0;
    RecordedKind kind = RecordedKind::kBoolean;
    double tolerance = 0.0;
    std::vector<std::size_t> frames;  ///< ascending
  };
  std::size_t frames = 0;
  std::vector<Object> objects;  ///< by id
  std::vector<Query> queries;   ///< by id
};

/// Reads FOLDER/journal.txt; throws RecordError naming the file and line of a malformed line
/// within the completed frames.
Replay replayJournal(const std::string& folder);

}  // namespace collido::record
