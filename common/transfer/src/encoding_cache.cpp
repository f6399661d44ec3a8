#include "slicereuse/transfer/encoding_cache.h"

#include "slicereuse/transfer/transfer_contours.h"

namespace slicereuse {

std::shared_ptr<const CachedEncoding> EncodingCache::get(const std::string& path, const Mesh& member, bool* hit,
                                                         const Progress& progress) {
  std::lock_guard<std::mutex> lock(mutex_);
  const FileIdentity identity = slice_file_identity(path);
  if (entry_ && entry_->path == path && entry_->identity == identity) {
    if (hit) *hit = true;
    return entry_;
  }
  if (hit) *hit = false;
  entry_.reset();  // free the old entry before reading the new one
  auto fresh = std::make_shared<CachedEncoding>();
  fresh->path = path;
  fresh->identity = identity;
  fresh->encoding = read_encoding_file(path, progress);
  fresh->edge_ends = encoded_edge_ends(fresh->encoding, member);
  entry_ = std::move(fresh);
  return entry_;
}

void EncodingCache::clear() {
  std::lock_guard<std::mutex> lock(mutex_);
  entry_.reset();
}

}  // namespace slicereuse
