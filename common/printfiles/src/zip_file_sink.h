#pragma once
// zip_file_sink: a libzip source to create an archive in an existing file (a staged output,
// atomic_file.h): zip_open_from_source(sink, ZIP_CREATE | ZIP_TRUNCATE, ...), and zip_close
// writes the archive straight into that file.
//
// Why not zip_open(path): libzip then writes into a temporary file of its own, which zip_close
// renames onto path, and the fsync that commits the output waits for the whole archive to reach
// the disk after its last entry, then for the rename. Here the archive's writeback starts as it
// is written, every kWritebackBytes (sync_file_range, which only starts it), while the later
// layers are still being drawn, so the commit waits for the last few MB.
//
// Writes are gathered in a buffer of at least kWritebackBytes and written with pwrite; libzip's
// rewrite of each entry's header after its data lands in the buffer while it is there. A failed
// write sets ZIP_ER_WRITE with the system's reason (zip_strerror says it: "Write error: No
// space left on device"). The source reads nothing (a new archive: it stats as missing) and is
// freed by libzip (zip_open_from_source's caller frees it when that fails). Returns null, with
// error set, when it cannot be made.
#include <zip.h>

#include <cstddef>
#include <string>

namespace slicereuse {

constexpr size_t kWritebackBytes = size_t(1) << 20;

zip_source_t* zip_file_sink(const std::string& path, zip_error_t* error);

}  // namespace slicereuse
