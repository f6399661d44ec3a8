#pragma once
// AtomicFile: writes a file under a temporary name in the destination folder and renames it
// into place on commit(). If commit() is never reached (error, cancel, exception) the
// temporary is removed, so a failed run never leaves a truncated file under the final name.
#include <cstdio>
#include <string>

namespace slicereuse {

class AtomicFile {
 public:
  // Opens PATH.tmp-XXXXXX next to path; throws Error naming path when it cannot be created.
  explicit AtomicFile(const std::string& path);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  FILE* stream() { return file_; }
  const std::string& temp_path() const { return temp_; }
  // Writes n bytes; throws Error naming the path on a short write.
  void write(const void* data, size_t n);
  // Flushes, closes and renames onto the final path; throws Error on failure.
  void commit();

 private:
  std::string path_, temp_;
  FILE* file_ = nullptr;
};

// Throws Error naming path when its folder does not exist or is not writable, so a filter can
// refuse before spending minutes on work whose result could not be saved.
void check_writable(const std::string& path);

}  // namespace slicereuse
