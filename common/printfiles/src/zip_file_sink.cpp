#include "zip_file_sink.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <vector>

namespace slicereuse {
namespace {

struct Sink {
  std::string path;
  int fd = -1;
  zip_error_t error;
  std::vector<uint8_t> buffer;  // bytes [start, start + buffer.size()) of the file, not written yet
  uint64_t start = 0;
  uint64_t pos = 0;  // where the next write goes
  uint64_t end = 0;  // the archive's length so far

  Sink() { zip_error_init(&error); }
  ~Sink() {
    close();
    zip_error_fini(&error);
  }

  zip_int64_t fail(int zip_code, int system_code) {
    zip_error_set(&error, zip_code, system_code);
    return -1;
  }

  void close() {
    if (fd >= 0) ::close(fd);
    fd = -1;
  }

  // Writes the buffer out and starts its writeback.
  bool flush() {
    size_t done = 0;
    while (done < buffer.size()) {
      const ssize_t n = ::pwrite(fd, buffer.data() + done, buffer.size() - done, off_t(start + done));
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) {
        fail(ZIP_ER_WRITE, n < 0 ? errno : ENOSPC);
        return false;
      }
      done += size_t(n);
    }
    if (buffer.size() >= kWritebackBytes)
      ::sync_file_range(fd, off_t(start), off_t(buffer.size()), SYNC_FILE_RANGE_WRITE);  // only starts it
    start += buffer.size();
    buffer.clear();
    return true;
  }

  zip_int64_t write(const void* data, size_t n) {
    // Within or right after the buffer: into it; elsewhere (a header whose entry's data was
    // written out already), the buffer is written first and starts anew there.
    if (pos < start || pos > start + buffer.size()) {
      if (!flush()) return -1;
      start = pos;
    }
    const size_t at = size_t(pos - start);
    buffer.resize(std::max(buffer.size(), at + n));
    std::memcpy(buffer.data() + at, data, n);
    pos += n;
    end = std::max(end, pos);
    if (buffer.size() >= kWritebackBytes && pos == start + buffer.size() && !flush()) return -1;
    return zip_int64_t(n);
  }
};

zip_int64_t sink_call(Sink& s, void* data, zip_uint64_t len, zip_source_cmd_t cmd) {
  switch (cmd) {
    case ZIP_SOURCE_SUPPORTS:
      return ZIP_SOURCE_SUPPORTS_WRITABLE;
    case ZIP_SOURCE_STAT:  // a new archive: nothing to read
      return s.fail(ZIP_ER_READ, ENOENT);
    case ZIP_SOURCE_ERROR:
      return zip_error_to_data(&s.error, data, len);
    case ZIP_SOURCE_BEGIN_WRITE:
      s.fd = ::open(s.path.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
      if (s.fd < 0) return s.fail(ZIP_ER_OPEN, errno);
      s.buffer.clear();
      s.start = s.pos = s.end = 0;
      return 0;
    case ZIP_SOURCE_WRITE:
      return s.write(data, size_t(len));
    case ZIP_SOURCE_SEEK_WRITE: {
      const zip_int64_t to = zip_source_seek_compute_offset(s.pos, s.end, data, len, &s.error);
      if (to < 0) return -1;
      s.pos = uint64_t(to);
      return 0;
    }
    case ZIP_SOURCE_TELL_WRITE:
      return zip_int64_t(s.pos);
    case ZIP_SOURCE_COMMIT_WRITE: {
      if (!s.flush()) return -1;
      const int fd = s.fd;
      s.fd = -1;
      if (::close(fd) != 0) return s.fail(ZIP_ER_WRITE, errno);
      return 0;
    }
    case ZIP_SOURCE_ROLLBACK_WRITE:  // the staged file is removed by its owner
      s.close();
      return 0;
    case ZIP_SOURCE_REMOVE:  // an archive without entries: left empty
      return 0;
    case ZIP_SOURCE_FREE:
      delete &s;
      return 0;
    default:  // reading: never asked of a new archive
      return s.fail(ZIP_ER_OPNOTSUPP, 0);
  }
}

zip_int64_t sink_cb(void* ud, void* data, zip_uint64_t len, zip_source_cmd_t cmd) {
  Sink& s = *static_cast<Sink*>(ud);
  try {
    return sink_call(s, data, len, cmd);
  } catch (...) {  // the buffer's growth; exceptions must not unwind through libzip's C frames
    return s.fail(ZIP_ER_MEMORY, 0);
  }
}

}  // namespace

zip_source_t* zip_file_sink(const std::string& path, zip_error_t* error) {
  Sink* s = new Sink;
  s->path = path;
  zip_source_t* src = zip_source_function_create(sink_cb, s, error);
  if (!src) delete s;
  return src;
}

}  // namespace slicereuse
