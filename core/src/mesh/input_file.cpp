// Input files: checked for kind and size before anything reads them.
#include <collido/mesh/input_file.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <new>
#include <sstream>

namespace collido {
namespace {

constexpr std::uint64_t kMebibyte = 1024ull * 1024ull;

thread_local InputFileRecorder* active_recorder = nullptr;
constexpr std::uint64_t kDefaultLimitMebibytes = 1024;

Status refuse(const std::string& path, const std::string& problem) {
  return Status(StatusCode::kInvalidArgument, path + ": " + problem);
}

std::string mebibytes(std::uint64_t bytes) {
  std::ostringstream text;
  text.precision(bytes >= 10 * kMebibyte ? 0 : 1);
  text << std::fixed << static_cast<double>(bytes) / static_cast<double>(kMebibyte) << " MiB";
  return text.str();
}

}  // namespace

std::uint64_t inputLimitBytes() {
  const char* text = std::getenv("COLLIDO_MAX_INPUT_MB");
  if (text != nullptr && *text != '\0') {
    char* end = nullptr;
    errno = 0;
    const unsigned long long value = std::strtoull(text, &end, 10);
    // A malformed value keeps the default rather than lifting the limit.
    if (errno == 0 && end != nullptr && *end == '\0' && value > 0 &&
        value <= UINT64_MAX / kMebibyte) {
      return value * kMebibyte;
    }
  }
  return kDefaultLimitMebibytes * kMebibyte;
}

Status checkInputFile(const std::string& path, const std::string& what) {
  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::status(path, ec);
  if (!std::filesystem::exists(status)) return refuse(path, what + " not found");
  if (!std::filesystem::is_regular_file(status)) {
    return refuse(path, std::string("not a regular file (") +
                            (std::filesystem::is_directory(status) ? "a folder"
                                                                   : "a device, pipe or socket") +
                            "), so not a " + what);
  }
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec) return refuse(path, "the " + what + "'s size cannot be read: " + ec.message());
  const std::uint64_t limit = inputLimitBytes();
  if (size > limit) {
    return refuse(path, "the " + what + " holds " + mebibytes(size) +
                            ", more than the input limit of " + mebibytes(limit) +
                            " (raise it with COLLIDO_MAX_INPUT_MB or collido --max-input-mb)");
  }
  if (active_recorder != nullptr) active_recorder->add(path);
  return Status();
}

InputFileRecorder::InputFileRecorder() : enclosing_(active_recorder) {
  active_recorder = this;
}

InputFileRecorder::~InputFileRecorder() {
  active_recorder = enclosing_;
  if (enclosing_ != nullptr) {
    for (const std::string& file : files_)
      enclosing_->add(file);
  }
}

void InputFileRecorder::add(const std::string& path) {
  if (std::find(files_.begin(), files_.end(), path) == files_.end()) files_.push_back(path);
}

Result<std::string> readInputFile(const std::string& path, const std::string& what) {
  if (Status s = checkInputFile(path, what); !s.ok()) return s;
  std::ifstream in(path, std::ios::binary);
  if (!in) return refuse(path, "cannot open the " + what);
  try {
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  } catch (const std::bad_alloc&) {
    return Status(StatusCode::kOutOfMemory, path + ": out of memory reading the " + what);
  }
}

}  // namespace collido
