// libFuzzer target for one file reader, chosen at build time: SLICEREUSE_FUZZ_READ names the reader
// and its header is force-included (see fuzz/CMakeLists.txt). The readers take paths, as the plugins call them, so every input is
// written to a file in /dev/shm first, named with SLICEREUSE_FUZZ_EXTENSION for the readers
// that go by the extension. A reader may refuse an input only with slicereuse::Error
// (a clear message); anything else (a crash, a sanitizer report, another exception such as
// std::bad_alloc from trusting a header, a hang) is a finding.
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "slicereuse/util/error.h"

namespace {

const std::string& input_path() {
  static const std::string path = "/dev/shm/slicereuse_fuzz_" + std::to_string(::getpid()) + SLICEREUSE_FUZZ_EXTENSION;
  return path;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string& path = input_path();
  FILE* f = std::fopen(path.c_str(), "wb");
  if (f == nullptr) std::abort();
  if (size != 0 && std::fwrite(data, 1, size, f) != size) std::abort();
  std::fclose(f);
  try {
    slicereuse::SLICEREUSE_FUZZ_READ(path);
  } catch (const slicereuse::Error&) {
    // A refusal with a message is the expected answer to a bad file.
  }
  return 0;
}
