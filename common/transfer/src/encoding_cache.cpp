#include "slicereuse/transfer/encoding_cache.h"

#include "slicereuse/transfer/transfer_contours.h"

namespace slicereuse {
namespace {

template <class Array>
size_t array_bytes(const Array& a) {
  return a.size() * sizeof(typename Array::value_type);
}

size_t entry_bytes(const CachedEncoding* e) {
  if (!e) return 0;
  const Slices& s = e->encoding;
  return array_bytes(s.layer_z) + array_bytes(s.layer_begin) + array_bytes(s.contour_begin) +
         array_bytes(s.contour_open) + array_bytes(s.xyz) + array_bytes(s.face) + array_bytes(s.edge) +
         array_bytes(s.t) + array_bytes(e->edge_ends);
}

}  // namespace

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

size_t EncodingCache::bytes() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return entry_bytes(entry_.get());
}

size_t EncodingCache::clear() {
  std::lock_guard<std::mutex> lock(mutex_);
  const size_t freed = entry_bytes(entry_.get());
  entry_.reset();
  return freed;
}

}  // namespace slicereuse
