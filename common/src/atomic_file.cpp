#include "slicereuse/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <vector>

#include "slicereuse/error.h"

namespace slicereuse {
namespace {

std::string why() { return std::strerror(errno); }

std::string folder_of(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  return slash == 0 ? "/" : path.substr(0, slash);
}

// mkstemp creates files with mode 0600; a saved file should get the mode any other program's
// output would get (0666 minus umask), or keep the mode of the file it replaces. umask() itself
// cannot be read without setting it, which would race with other threads.
mode_t final_mode(const std::string& path) {
  struct stat st;
  if (::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode)) return st.st_mode & 07777;
  mode_t mask = 022;
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.compare(0, 6, "Umask:") == 0) {
      mask = mode_t(std::strtoul(line.c_str() + 6, nullptr, 8));
      break;
    }
  }
  return 0666 & ~mask;
}

}  // namespace

AtomicFile::AtomicFile(const std::string& path) : path_(path) {
  std::vector<char> name(path.begin(), path.end());
  const char suffix[] = ".tmp-XXXXXX";
  name.insert(name.end(), suffix, suffix + sizeof suffix);
  const int fd = ::mkstemp(name.data());
  if (fd < 0) throw Error("cannot create a temporary file next to '" + path + "': " + why());
  temp_ = name.data();
  ::fchmod(fd, final_mode(path));
  file_ = ::fdopen(fd, "w+b");  // readable too, for writers (libzip) that read back
  if (!file_) {
    const std::string reason = why();
    ::close(fd);
    ::unlink(temp_.c_str());
    throw Error("cannot open temporary file '" + temp_ + "': " + reason);
  }
}

AtomicFile::~AtomicFile() {
  if (file_) std::fclose(file_);
  // temp_ is cleared once renamed into place; otherwise the partial output must not survive.
  if (!temp_.empty()) ::unlink(temp_.c_str());
}

void AtomicFile::write(const void* data, size_t n) {
  if (!file_) throw Error("cannot write '" + path_ + "': file already closed");
  if (n && std::fwrite(data, 1, n, file_) != n)
    throw Error("cannot write '" + path_ + "': " + why());
}

void AtomicFile::commit() {
  if (!file_) throw Error("cannot commit '" + path_ + "': file already closed");
  FILE* f = file_;
  file_ = nullptr;
  const bool flushed = std::fflush(f) == 0;
  const std::string flush_error = flushed ? std::string() : why();
  if (std::fclose(f) != 0 || !flushed)
    throw Error("cannot write '" + path_ + "': " + (flushed ? why() : flush_error));
  if (::rename(temp_.c_str(), path_.c_str()) != 0)
    throw Error("cannot rename '" + temp_ + "' to '" + path_ + "': " + why());
  temp_.clear();
}

void check_writable(const std::string& path) {
  if (path.empty()) throw Error("no output path given");
  const std::string folder = folder_of(path);
  struct stat st;
  if (::stat(folder.c_str(), &st) != 0)
    throw Error("cannot write '" + path + "': folder '" + folder + "': " + why());
  if (!S_ISDIR(st.st_mode))
    throw Error("cannot write '" + path + "': '" + folder + "' is not a folder");
  if (::access(folder.c_str(), W_OK | X_OK) != 0)
    throw Error("cannot write '" + path + "': folder '" + folder + "' is not writable: " + why());
  if (::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode))
    throw Error("cannot write '" + path + "': it is a folder");
}

}  // namespace slicereuse
