#include "slicereuse/util/input_file.h"

#include <cerrno>
#include <cstring>

#include "slicereuse/util/error.h"

namespace slicereuse::detail {

InputFile open_input_file(const std::string& path, const std::string& what) {
  InputFile in;
  in.file.reset(std::fopen(path.c_str(), "rb"));
  if (!in.file)
    throw Error("cannot open " + (what.empty() ? "" : what + " ") + "'" + path + "': " + std::strerror(errno));
  if (::fstat(::fileno(in.get()), &in.st) != 0 || !S_ISREG(in.st.st_mode))
    throw Error("cannot read '" + path + "': not a regular file");
  return in;
}

}  // namespace slicereuse::detail
