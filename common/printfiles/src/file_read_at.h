#pragma once
// The print file readers' (goo_stack.h, ctb_stack.h, photon_workshop_stack.h) access to a file by offset:
//   file_size(fd, path)                        its size in bytes
//   read_at(fd, offset, to, n, path, what)     n bytes at offset into to, or Error saying that
//                                              the file ends inside `what` (or the system's reason)
#include <cstddef>
#include <cstdint>
#include <string>

namespace slicereuse {

uint64_t file_size(int fd, const std::string& path);
void read_at(int fd, uint64_t offset, uint8_t* to, size_t n, const std::string& path, const std::string& what);

}  // namespace slicereuse
