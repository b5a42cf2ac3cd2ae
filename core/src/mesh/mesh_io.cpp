// Mesh import, with the reader picked by extension from a table:
//  - our own strict readers for OBJ, OFF, PLY and STL (obj_reader.cpp, off_reader.cpp,
//    ply_reader.cpp, stl_reader.cpp): they read coordinates as the doubles of the text
//    (std::from_chars) or the floats of the binary data, so the geometry is the file's own
//    numbers (the exact oracle decides on them), and name the line, vertex or face of an error;
//  - assimp for every other format: Debian builds it with 32-bit floats (ai_real = float), which
//    loses digits of text formats, so it is used only where the format holds floats anyway
//    (glTF, FBX, ...), and the report says so. assimp never reads the four formats above, not
//    even as a second opinion: its PLY reader hangs on a header without 'end_header' and aborts
//    the process on truncated ASCII data, and its STL reader leaks.
#include <collido/mesh/mesh_io.h>

#include "mesh_import.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <iterator>
#include <new>
#include <utility>

#include <assimp/Importer.hpp>

#include <collido/mesh/input_file.h>

namespace collido {
namespace {

using detail::Imported;
using detail::readError;

std::string lowerExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  if (!ext.empty() && ext.front() == '.') ext.erase(0, 1);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

struct Reader {
  const char* extension;
  Result<Imported> (*read)(const std::string& path);
};

// The formats our own readers take; everything else goes to assimp.
constexpr Reader kOwnReaders[] = {{"obj", detail::readObj},
                                  {"off", detail::readOff},
                                  {"ply", detail::readPly},
                                  {"stl", detail::readStl}};

}  // namespace

Result<TriangleMesh> loadMesh(const std::string& path, MeshReport* report) {
  if (Status s = checkInputFile(path, "mesh file"); !s.ok()) return s;
  std::error_code ec;
  if (std::filesystem::file_size(path, ec) == 0 && !ec) return readError(path, "the file is empty");

  const std::string ext = lowerExtension(path);
  const auto reader = std::find_if(std::begin(kOwnReaders), std::end(kOwnReaders),
                                   [&](const Reader& r) { return ext == r.extension; });
  if (reader == std::end(kOwnReaders) &&
      (ext.empty() || !Assimp::Importer().IsExtensionSupported("." + ext))) {
    // assimp would guess a format from the content; a file's format is what its name says.
    return readError(path, ext.empty() ? "no file extension, so no known mesh format"
                                       : "unknown mesh format '." + ext +
                                             "' (neither our obj/off/ply/stl readers nor "
                                             "assimp read this extension)");
  }
  // A file within the size limit can still describe more than memory holds (a header that
  // promises a billion faces); the error then names the file instead of a bare bad_alloc.
  try {
    Result<Imported> imported =
        reader != std::end(kOwnReaders) ? reader->read(path) : detail::readWithAssimp(path);
    if (!imported.ok()) return imported.status();
    Imported& result = imported.value();
    if (Status s = validateMesh(result.mesh, path); !s.ok()) return s;
    if (report != nullptr) {
      *report = result.report;
      report->source = path;
      inspectMesh(result.mesh, *report);
    }
    return std::move(result.mesh);
  } catch (const std::bad_alloc&) {
    return Status(StatusCode::kOutOfMemory, path + ": out of memory reading the mesh");
  }
}

}  // namespace collido
