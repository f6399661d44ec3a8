#pragma once
// Atomic outputs: the one way slicereuse writes results, so that a failed, cancelled or
// crashed run, or a power loss, never leaves a truncated file, a half-filled folder or a broken
// archive under a final name (nor replaces an older one).
//
// StagedOutputs: outputs that appear together. file(path) / folder(path) reserve a fresh name
//   next to path (PATH.tmp-XXXXXX, same file system, so renames are atomic) as an empty file or
//   folder and return it; the caller writes there by any means (stdio, plain writes into the
//   folder, libzip's zip_open on the staged file); commit() puts every staged output on the disk
//   (fsync of a file, syncfs of a folder's file system), renames each onto its final path, in the
//   order staged, then fsyncs the folders the renames changed: once commit() returns, a power
//   loss keeps the outputs. Destroyed without commit: every staged output is removed.
//   file(path) throws Error when path is an existing folder (folder(path): an existing
//   non-folder), before anything is written, so that no rename in commit() fails for that.
//   A staged file gets the mode of the file it replaces, else 0666 minus the umask. A staged
//   folder replaces a missing or empty folder in one rename; into a folder that has entries, its
//   entries are renamed one by one (other entries there are kept).
// AtomicFile: one file written through a stdio stream, a StagedOutputs of one file. write_at
//   rewrites bytes already written (a header whose figures are known only at the end) and then
//   goes on writing where it was.
// check_writable: refuses early an output path whose folder cannot take it.
// Folder paths may end in '/' ("out/masks/" is the folder "out/masks" in the folder "out").
// All throw Error naming the path (and the system's reason) on failure.
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace slicereuse {

class StagedOutputs {
 public:
  StagedOutputs() = default;
  StagedOutputs(const StagedOutputs&) = delete;
  StagedOutputs& operator=(const StagedOutputs&) = delete;
  ~StagedOutputs();

  std::string file(const std::string& final_path);
  std::string folder(const std::string& final_path);
  void commit();

 private:
  struct Output {
    std::string staged, final_path;
    bool is_folder;
  };
  std::vector<Output> outputs_;
};

class AtomicFile {
 public:
  explicit AtomicFile(const std::string& path);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  // Writes n bytes; throws Error naming the path on a short write.
  void write(const void* data, size_t n);
  // Writes n bytes at offset, which with n must lie within what was written; throws Error
  // naming the path when it does not.
  void write_at(uint64_t offset, const void* data, size_t n);
  // Flushes, closes and renames onto the final path.
  void commit();

 private:
  std::string path_;
  StagedOutputs staged_;
  FILE* file_ = nullptr;
};

// Throws Error naming path when its folder does not exist or is not writable, or path is a
// folder, so a filter can refuse before spending minutes on work whose result could not be saved.
void check_writable(const std::string& path);

}  // namespace slicereuse
