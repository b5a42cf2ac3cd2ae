// mesh_import_fuzz: the mesh reader (collido::loadMesh) on arbitrary file contents.
//
// Why: mesh files come from anywhere (scans, CAD exports, other tools), and a file that does not
// parse must end as an error naming it, never as a crash of the study.
// What it checks: the first byte picks the extension, so the reader (obj, off, ply, stl: one of
// our four strict readers, each in every variant it reads, with seeds for each in the corpus);
// the other bytes are the file, written to a temporary folder (removed at exit) and read with
// loadMesh. Whatever the bytes:
//  - no crash, out-of-bounds access, undefined behaviour or leak (ASan, UBSan, LeakSanitizer);
//  - an error names the file (mesh_io.h promises it);
//  - a mesh that loads is valid (validateMesh: triangles, finite coordinates, indices in range),
//    and the report's counts agree with it.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include <collido/mesh/mesh_io.h>
#include <collido/mesh/mesh_report.h>
#include <collido/mesh/triangle_mesh.h>

namespace {

constexpr const char* kExtensions[] = {"obj", "off", "ply", "stl"};

/// The folder the input files go to, made on first use and removed at exit.
class InputFolder {
 public:
  InputFolder()
      : path_(std::filesystem::temp_directory_path() /
              ("collido_mesh_fuzz." + std::to_string(::getpid()))) {
    std::filesystem::create_directories(path_);
  }
  ~InputFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  InputFolder(const InputFolder&) = delete;
  InputFolder& operator=(const InputFolder&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

const std::filesystem::path& inputFolder() {
  static const InputFolder folder;
  return folder.path();
}

[[noreturn]] void broken(const std::string& what) {
  std::fprintf(stderr, "mesh_import_fuzz: the reader broke its promise: %s\n", what.c_str());
  std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string path =
      (inputFolder() / (std::string("input.") + kExtensions[data[0] % 4])).string();
  {
    std::ofstream file(path, std::ios::binary | std::ios::trunc);
    file.write(reinterpret_cast<const char*>(data + 1), static_cast<std::streamsize>(size - 1));
  }
  collido::MeshReport report;
  const collido::Result<collido::TriangleMesh> mesh = collido::loadMesh(path, &report);
  if (!mesh.ok()) {
    if (mesh.status().message().find(path) == std::string::npos)
      broken("an error that does not name the file: " + mesh.status().message());
    return 0;
  }
  if (collido::Status s = collido::validateMesh(mesh.value(), path); !s.ok())
    broken("it loaded an invalid mesh: " + s.message());
  if (report.vertices != mesh.value().vertexCount() ||
      report.triangles != mesh.value().triangleCount())
    broken("the report's counts differ from the mesh's");
  return 0;
}
