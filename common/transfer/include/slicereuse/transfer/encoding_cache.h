#pragma once
// EncodingCache: the last encoding file read, kept in memory with its edge ends
// (encoded_edge_ends), so that a loop over a family's members, in pymeshlab or in a
// meshlabserver script, reads and prepares the source's encoding once instead of per member.
//
// In: an encoding file's path and the meshes the job will transfer it to (its members; the
// first of the encoding's family gives the edge ends: encoded_edge_ends needs its faces).
// Out: the shared entry, read on a miss. One entry: the key is the path plus the file's size
// and content checksum (slice_file_identity), so a file rewritten with other content is read
// again however coarse the file system's clock, and one rewritten with the same bytes is not;
// another key replaces the entry. An entry read for members none of which is of the family has
// no edge ends (those members are sliced directly); it is read again, with them, for a call that
// brings a member of the family. Memory while it is kept: the encoding (13 bytes per point)
// and the edge ends (8 bytes per point), about 1.5 GB for the 73 M points of a 545k-face part
// at 1 um; bytes() reports it, clear() releases it and returns what it freed. Thread safe.
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "slicereuse/formats/slice_files.h"
#include "slicereuse/mesh/mesh.h"
#include "slicereuse/slicing/slices.h"
#include "slicereuse/util/buffer.h"
#include "slicereuse/util/progress.h"

namespace slicereuse {

struct CachedEncoding {
  std::string path;
  FileIdentity identity;
  Slices encoding;
  Buffer<uint32_t> edge_ends;  // encoded_edge_ends(encoding, a member of its family), or empty
};

class EncodingCache {
 public:
  // *hit tells whether the entry was already there. Throws Error for an unreadable file or an
  // invalid member (validate_mesh).
  std::shared_ptr<const CachedEncoding> get(const std::string& path, const std::vector<const Mesh*>& members,
                                            bool* hit = nullptr, const Progress& progress = {});
  // The bytes the entry holds (its arrays), 0 when empty.
  size_t bytes() const;
  // Drops the entry; returns its bytes.
  size_t clear();
  // clear(), unless another thread holds the cache right now (reading an entry): 0 then,
  // without waiting. What a memory reclaimer calls (memory_budget.h): check_memory_for may run
  // on any thread, also inside a reading get(), where waiting for the cache would never end.
  size_t try_clear();

 private:
  size_t drop_entry();  // with mutex_ held

  mutable std::mutex mutex_;
  std::shared_ptr<const CachedEncoding> entry_;
};

}  // namespace slicereuse
