#include "slicereuse/slicing/layer_chunks.h"

#include "slicereuse/slicing/straddling_faces.h"

namespace slicereuse {

std::vector<size_t> layer_chunks(const Mesh& mesh, const std::vector<double>& planes, uint64_t budget_bytes,
                                 size_t bytes_per_point) {
  return layer_chunks(std::vector<const Mesh*>{&mesh}, planes, budget_bytes, bytes_per_point);
}

std::vector<size_t> layer_chunks(const std::vector<const Mesh*>& meshes, const std::vector<double>& planes,
                                 uint64_t budget_bytes, size_t bytes_per_point) {
  const size_t L = planes.size();
  if (budget_bytes == 0 || L == 0) return {0, L};
  // A layer's points: one per face its plane crosses, in every mesh.
  std::vector<uint64_t> crossed(L, 0);
  for (const Mesh* mesh : meshes) {
    const std::vector<uint64_t> counts = straddling_face_counts(*mesh, planes);
    for (size_t k = 0; k < L; ++k) crossed[k] += counts[k];
  }
  return layer_chunks(crossed, budget_bytes, bytes_per_point);
}

std::vector<size_t> layer_chunks(const std::vector<uint64_t>& layer_points, uint64_t budget_bytes,
                                 size_t bytes_per_point) {
  const size_t L = layer_points.size();
  if (budget_bytes == 0 || L == 0) return {0, L};
  std::vector<size_t> starts{0};
  uint64_t bytes = 0;
  for (size_t k = 0; k < L; ++k) {
    const uint64_t layer = layer_points[k] * bytes_per_point;
    if (bytes > 0 && bytes + layer > budget_bytes) {
      starts.push_back(k);
      bytes = 0;
    }
    bytes += layer;
  }
  starts.push_back(L);
  return starts;
}

}  // namespace slicereuse
