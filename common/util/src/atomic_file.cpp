#include "slicereuse/util/atomic_file.h"

#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "slicereuse/util/error.h"

namespace slicereuse {
namespace {

std::string why() { return std::strerror(errno); }

// "out/masks/" names the folder "out/masks": its parent is "out", its staged twin a sibling.
std::string without_trailing_slash(std::string path) {
  while (path.size() > 1 && path.back() == '/') path.pop_back();
  return path;
}

std::string folder_of(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  return slash == 0 ? "/" : path.substr(0, slash);
}

mode_t umask_of_process() {
  // umask() itself cannot be read without setting it, which would race with other threads.
  mode_t mask = 022;
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.compare(0, 6, "Umask:") == 0) {
      mask = mode_t(std::strtoul(line.c_str() + 6, nullptr, 8));
      break;
    }
  }
  return mask;
}

// mkstemp creates files with mode 0600 and mkdtemp folders with 0700; an output should get the
// mode any other program's output would get, or keep the mode of the file it replaces.
mode_t final_mode(const std::string& path, bool folder) {
  struct stat st;
  if (!folder && ::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode)) return st.st_mode & 07777;
  return (folder ? 0777 : 0666) & ~umask_of_process();
}

std::vector<char> template_for(const std::string& path) {
  std::vector<char> name(path.begin(), path.end());
  const char suffix[] = ".tmp-XXXXXX";
  name.insert(name.end(), suffix, suffix + sizeof suffix);
  return name;
}

void remove_staged(const std::string& staged, bool folder) {
  if (folder) {
    std::error_code ec;
    std::filesystem::remove_all(staged, ec);
  } else {
    ::unlink(staged.c_str());
  }
}

// Moves every entry of folder `from` into folder `to` (replacing entries of the same name),
// then removes the emptied `from`.
void merge_folder(const std::string& from, const std::string& to) {
  DIR* dir = ::opendir(from.c_str());
  if (dir == nullptr) throw Error("cannot read folder '" + from + "': " + why());
  std::vector<std::string> names;
  while (const dirent* e = ::readdir(dir))
    if (std::strcmp(e->d_name, ".") != 0 && std::strcmp(e->d_name, "..") != 0) names.push_back(e->d_name);
  ::closedir(dir);
  for (const std::string& name : names) {
    const std::string a = from + "/" + name, b = to + "/" + name;
    if (::rename(a.c_str(), b.c_str()) != 0) throw Error("cannot move '" + a + "' to '" + b + "': " + why());
  }
  ::rmdir(from.c_str());
}

// Puts what was written to path on the disk, by sync (fsync(2) or syncfs(2)) on a descriptor of
// it. A rename is journalled on its own, so without this a power loss soon after a commit can
// leave a final name on an empty or partly written file (ext4, XFS), or lose the rename. A file
// system that cannot sync (EINVAL: some FUSE and network file systems) has nothing more to give.
void sync_to_disk(const std::string& path, int (*sync)(int) = ::fsync) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw Error("cannot open '" + path + "' to write it to disk: " + why());
  const int r = sync(fd);
  const int e = errno;
  ::close(fd);
  if (r != 0 && e != EINVAL) throw Error("cannot write '" + path + "' to disk: " + std::strerror(e));
}

}  // namespace

StagedOutputs::~StagedOutputs() {
  for (const Output& o : outputs_)
    if (!o.staged.empty()) remove_staged(o.staged, o.is_folder);  // empty: already in place
}

std::string StagedOutputs::file(const std::string& final_path) {
  // Refused now rather than by the rename in commit(), after other outputs have been renamed.
  struct stat st;
  if (::stat(final_path.c_str(), &st) == 0 && S_ISDIR(st.st_mode))
    throw Error("cannot write '" + final_path + "': it is a folder");
  std::vector<char> name = template_for(final_path);
  const int fd = ::mkstemp(name.data());
  if (fd < 0) throw Error("cannot create a temporary file next to '" + final_path + "': " + why());
  ::fchmod(fd, final_mode(final_path, false));
  ::close(fd);
  outputs_.push_back({name.data(), final_path, false});
  return outputs_.back().staged;
}

std::string StagedOutputs::folder(const std::string& path) {
  const std::string final_path = without_trailing_slash(path);
  struct stat st;
  if (::stat(final_path.c_str(), &st) == 0 && !S_ISDIR(st.st_mode))
    throw Error("cannot write '" + final_path + "': it exists and is not a folder");
  std::vector<char> name = template_for(final_path);
  if (::mkdtemp(name.data()) == nullptr)
    throw Error("cannot create a folder next to '" + final_path + "': " + why());
  ::chmod(name.data(), final_mode(final_path, true));
  outputs_.push_back({name.data(), final_path, true});
  return outputs_.back().staged;
}

void StagedOutputs::commit() {
  // On the disk before renamed: a final name never refers to data that a power loss can take.
  // A folder (thousands of mask images) by one syncfs of its file system: an fsync per image
  // would wait for a journal commit and a disk cache flush each. syncfs also writes what other
  // programs left in that file system's cache, and reports a write error of theirs as well.
  for (const Output& o : outputs_) sync_to_disk(o.staged, o.is_folder ? ::syncfs : ::fsync);
  std::vector<std::string> changed;  // folders whose entries the renames changed
  for (Output& o : outputs_) {
    if (::rename(o.staged.c_str(), o.final_path.c_str()) != 0) {
      if (!o.is_folder || (errno != ENOTEMPTY && errno != EEXIST))
        throw Error("cannot rename '" + o.staged + "' to '" + o.final_path + "': " + why());
      merge_folder(o.staged, o.final_path);
      changed.push_back(o.final_path);
    }
    changed.push_back(folder_of(o.final_path));
    o.staged.clear();
  }
  outputs_.clear();
  // The renames themselves on the disk.
  std::sort(changed.begin(), changed.end());
  changed.erase(std::unique(changed.begin(), changed.end()), changed.end());
  for (const std::string& folder : changed) sync_to_disk(folder);
}

AtomicFile::AtomicFile(const std::string& path) : path_(path) {
  const std::string staged = staged_.file(path);
  file_ = std::fopen(staged.c_str(), "wb");
  if (file_ == nullptr) throw Error("cannot open temporary file '" + staged + "': " + why());
}

AtomicFile::~AtomicFile() {
  if (file_) std::fclose(file_);
}

void AtomicFile::write(const void* data, size_t n) {
  if (!file_) throw Error("cannot write '" + path_ + "': file already closed");
  if (n && std::fwrite(data, 1, n, file_) != n) throw Error("cannot write '" + path_ + "': " + why());
}

void AtomicFile::write_at(uint64_t offset, const void* data, size_t n) {
  if (!file_) throw Error("cannot write '" + path_ + "': file already closed");
  const off_t end = ::ftello(file_);
  if (end < 0 || offset > uint64_t(end) || n > uint64_t(end) - offset)
    throw Error("cannot write '" + path_ + "': bytes " + std::to_string(offset) + ".." + std::to_string(offset + n) +
                " are not within the " + std::to_string(end) + " bytes written");
  if (::fseeko(file_, off_t(offset), SEEK_SET) != 0 || (n && std::fwrite(data, 1, n, file_) != n) ||
      ::fseeko(file_, end, SEEK_SET) != 0)
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
  staged_.commit();
}

void check_writable(const std::string& path) {
  if (path.empty()) throw Error("no output path given");
  const std::string folder = folder_of(without_trailing_slash(path));
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
