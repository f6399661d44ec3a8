#include "slicereuse/transfer/encoding_cache.h"

#include "slicereuse/transfer/transfer_contours.h"

namespace slicereuse {

namespace {

// The first of members whose faces are the encoding's mesh's, or null.
const Mesh* first_of_family(const Slices& encoding, const std::vector<const Mesh*>& members) {
  for (const Mesh* m : members) {
    validate_mesh(*m);
    if (family_difference(encoding, *m).empty()) return m;
  }
  return nullptr;
}

}  // namespace

std::shared_ptr<const CachedEncoding> EncodingCache::get(const std::string& path,
                                                         const std::vector<const Mesh*>& members, bool* hit,
                                                         const Progress& progress) {
  std::lock_guard<std::mutex> lock(mutex_);
  const FileIdentity identity = slice_file_identity(path);
  if (entry_ && entry_->path == path && entry_->identity == identity &&
      (!entry_->edge_ends.empty() || !first_of_family(entry_->encoding, members))) {
    if (hit) *hit = true;
    return entry_;
  }
  if (hit) *hit = false;
  entry_.reset();  // free the old entry before reading the new one
  auto fresh = std::make_shared<CachedEncoding>();
  fresh->path = path;
  fresh->identity = identity;
  fresh->encoding = read_encoding_file(path, progress);
  if (const Mesh* member = first_of_family(fresh->encoding, members))
    fresh->edge_ends = encoded_edge_ends(fresh->encoding, *member);
  entry_ = std::move(fresh);
  return entry_;
}

namespace {

template <class Array>
size_t bytes_of(const Array& a) {
  return a.size() * sizeof(a[0]);
}

size_t bytes_of_entry(const CachedEncoding& e) {
  const Slices& s = e.encoding;
  return bytes_of(s.layer_z) + bytes_of(s.layer_begin) + bytes_of(s.contour_begin) + bytes_of(s.contour_open) +
         bytes_of(s.xyz) + bytes_of(s.face) + bytes_of(s.edge) + bytes_of(s.t) + bytes_of(e.edge_ends);
}

}  // namespace

size_t EncodingCache::bytes() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return entry_ ? bytes_of_entry(*entry_) : 0;
}

size_t EncodingCache::clear() {
  std::lock_guard<std::mutex> lock(mutex_);
  return drop_entry();
}

size_t EncodingCache::try_clear() {
  std::unique_lock<std::mutex> lock(mutex_, std::try_to_lock);
  return lock.owns_lock() ? drop_entry() : 0;
}

size_t EncodingCache::drop_entry() {
  const size_t freed = entry_ ? bytes_of_entry(*entry_) : 0;
  entry_.reset();
  return freed;
}

}  // namespace slicereuse
