// Marker tracks as CSV, through Ben Strasser's Fast C++ CSV Parser (Debian's libfccp-dev) for
// the structure (header, columns, line numbers); numbers through strtod, which rounds
// correctly where the parser's own float reading does not.
#include <collido/scene/marker_tracks_file.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <set>
#include <sstream>
#include <tuple>

#include <collido/mesh/input_file.h>

// The parser copies file names for its messages with strncpy, which GCC flags where it is
// inlined into this file (the copy is bounded and terminated by the parser itself).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wstringop-truncation"
#endif
#define CSV_IO_NO_THREAD
#include <csv.h>

namespace collido {
namespace {

// The whole text as a finite double, or a message saying why not.
bool finiteNumber(const std::string& text, double& value) {
  if (text.empty()) return false;
  errno = 0;
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size() && errno != ERANGE && std::isfinite(value);
}

// An object name as a CSV cell: quoted when it holds a comma, a quote or spaces at its ends.
std::string cell(const std::string& text) {
  if (text.find_first_of(",\"") == std::string::npos &&
      (text.empty() || (text.front() != ' ' && text.back() != ' '))) {
    return text;
  }
  std::string quoted = "\"";
  for (const char c : text) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  return quoted + "\"";
}

}  // namespace

Result<MarkerTracks> readMarkerTracks(const std::string& path, const std::string& object,
                                      std::size_t frames, const pose::MarkerLayout& layout) {
  std::ifstream probe(path);
  if (!probe) return Status(StatusCode::kInvalidArgument, path + ": tracks file not found");
  probe.close();
  if (Status s = checkInputFile(path, "tracks file"); !s.ok()) return s;
  MarkerTracks tracks(frames);
  std::size_t rows = 0;
  std::set<std::tuple<std::size_t, int>> seen;
  try {
    io::CSVReader<7, io::trim_chars<' ', '\t'>, io::double_quote_escape<',', '"'>,
                  io::throw_on_overflow, io::single_line_comment<'#'>>
        in(path);
    in.read_header(io::ignore_missing_column, "frame", "object", "marker", "x", "y", "z", "weight");
    for (const char* required : {"frame", "object", "marker", "x", "y", "z"}) {
      if (!in.has_column(required)) {
        return Status(StatusCode::kInvalidArgument,
                      path + ": the header lacks column '" + required +
                          "' (expected frame,object,marker,x,y,z[,weight])");
      }
    }
    unsigned long long frame = 0;
    std::string name;
    int marker = 0;
    std::string x, y, z;
    std::string weight;
    while (in.read_row(frame, name, marker, x, y, z, weight)) {
      const std::string line = path + ": line " + std::to_string(in.get_file_line()) + ": ";
      const auto bad = [&](const std::string& problem) {
        return Status(StatusCode::kInvalidArgument, line + problem);
      };
      if (name != object) {
        weight.clear();
        continue;
      }
      if (frame >= frames) {
        return bad("frame " + std::to_string(frame) + " is outside the scene's " +
                   std::to_string(frames) + " frames");
      }
      if (layout.count(marker) == 0) {
        return bad("marker " + std::to_string(marker) + " is not in " + object +
                   "'s marker layout");
      }
      if (!seen.emplace(static_cast<std::size_t>(frame), marker).second) {
        return bad("marker " + std::to_string(marker) + " appears twice in frame " +
                   std::to_string(frame));
      }
      pose::MarkerObservation o;
      o.id = marker;
      const std::pair<const char*, const std::string*> coordinates[] = {
          {"x", &x}, {"y", &y}, {"z", &z}};
      for (int k = 0; k < 3; ++k) {
        if (!finiteNumber(*coordinates[k].second, o.position(k))) {
          return bad(std::string(coordinates[k].first) + " '" + *coordinates[k].second +
                     "' is not a finite number");
        }
      }
      if (!weight.empty() && (!finiteNumber(weight, o.weight) || !(o.weight > 0.0))) {
        return bad("weight '" + weight + "' is not a number > 0");
      }
      weight.clear();  // an empty cell (or no column) next time means 1
      tracks[static_cast<std::size_t>(frame)].push_back(o);
      ++rows;
    }
  } catch (const io::error::base& e) {
    return Status(StatusCode::kInvalidArgument, std::string("tracks file: ") + e.what());
  }
  if (rows == 0) {
    return Status(StatusCode::kInvalidArgument,
                  path + ": no rows for object '" + object + "' (column 'object')");
  }
  return tracks;
}

Status writeMarkerTracks(const std::string& path,
                         const std::vector<std::pair<std::string, MarkerTracks>>& objects) {
  std::ofstream out(path);
  if (!out) return {StatusCode::kInvalidArgument, path + ": cannot be written"};
  out << "frame,object,marker,x,y,z,weight\n" << std::setprecision(17);
  std::size_t frames = 0;
  for (const auto& [name, tracks] : objects)
    frames = std::max(frames, tracks.size());
  for (std::size_t f = 0; f < frames; ++f) {
    for (const auto& [name, tracks] : objects) {
      if (f >= tracks.size()) continue;
      for (const pose::MarkerObservation& o : tracks[f]) {
        out << f << ',' << cell(name) << ',' << o.id << ',' << o.position.x() << ','
            << o.position.y() << ',' << o.position.z() << ',' << o.weight << '\n';
      }
    }
  }
  out.flush();
  if (!out) return {StatusCode::kInvalidArgument, path + ": write failed"};
  return {};
}

}  // namespace collido
