#include <collido/io/files.h>

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

namespace collido::io {

Result<std::string> readTextFile(const std::string& path, const std::string& missing) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return Status(StatusCode::kInvalidArgument, path + ": " + missing);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

Result<nlohmann::json> readJsonFile(const std::string& path, const std::string& missing) {
  Result<std::string> text = readTextFile(path, missing);
  if (!text.ok()) return text.status();
  try {
    return nlohmann::json::parse(text.value());
  } catch (const nlohmann::json::exception& e) {
    return Status(StatusCode::kInvalidArgument, path + ": not valid JSON: " + e.what());
  }
}

Status writeFileAtomically(const std::string& path, const std::string& text) {
  static std::atomic<unsigned long> serial{0};
  static const std::string host = [] {
    char name[256] = {};
    return ::gethostname(name, sizeof(name) - 1) == 0 ? std::string(name) : std::string("host");
  }();
  const std::string temporary = path + ".partial." + host + "." + std::to_string(::getpid()) + "." +
                                std::to_string(serial.fetch_add(1));
  const auto failed = [&](const std::string& what, int error) {
    ::unlink(temporary.c_str());
    return Status(StatusCode::kInvalidArgument, what + ": " + std::strerror(error));
  };
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) {
    return Status(StatusCode::kInvalidArgument,
                  temporary + ": cannot be written: " + std::strerror(errno));
  }
  for (std::size_t done = 0; done < text.size();) {
    const ::ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      const int error = errno;
      ::close(fd);
      return failed(temporary + ": cannot be written", error);
    }
    done += static_cast<std::size_t>(n);
  }
  // Without this, a crash of the machine soon after the rename could leave the new name on a
  // file whose data never reached the disk (an empty result that would stop --resume).
  if (::fdatasync(fd) != 0) {
    const int error = errno;
    ::close(fd);
    return failed(temporary + ": cannot be flushed to disk", error);
  }
  if (::close(fd) != 0) return failed(temporary + ": cannot be written", errno);
  if (::rename(temporary.c_str(), path.c_str()) != 0) {
    return failed(path + ": cannot be replaced", errno);
  }
  return Status();
}

}  // namespace collido::io
