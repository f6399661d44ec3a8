#pragma once
// open_input_file: the one way the readers open a file (internal, not part of the API).
// Opens path for binary reading and checks that it is a regular file (not a folder or a
// device), so that size() is what the reader may trust to check counts against before
// allocating. Throws Error naming the path: "cannot open the map file 'p': No such file or
// directory" (`what` names the kind of file; empty: "cannot open 'p': ...").
#include <sys/stat.h>

#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>

namespace slicereuse::detail {

struct FileCloser {
  void operator()(FILE* f) const { std::fclose(f); }
};

struct InputFile {
  std::unique_ptr<FILE, FileCloser> file;
  struct stat st;
  FILE* get() const { return file.get(); }
  uint64_t size() const { return uint64_t(st.st_size); }
};

InputFile open_input_file(const std::string& path, const std::string& what = "");

}  // namespace slicereuse::detail
