#include "file_read_at.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "slicereuse/util/error.h"

namespace slicereuse {

uint64_t file_size(int fd, const std::string& path) {
  struct stat st;
  if (::fstat(fd, &st) != 0) throw Error("cannot read '" + path + "': " + std::strerror(errno));
  return uint64_t(st.st_size);
}

void read_at(int fd, uint64_t offset, uint8_t* to, size_t n, const std::string& path, const std::string& what) {
  size_t done = 0;
  while (done < n) {
    const ssize_t got = ::pread(fd, to + done, n - done, off_t(offset + done));
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) throw Error("cannot read '" + path + "': " + std::strerror(errno));
    if (got == 0) throw Error("'" + path + "' is truncated: it ends inside " + what);
    done += size_t(got);
  }
}

}  // namespace slicereuse
