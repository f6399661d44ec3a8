#include "slicereuse/util/squared_distances.h"

#include <cstddef>

namespace slicereuse {
namespace {

// f[start + q stride], q < n, replaced by min over p of f[p] + (q - p)^2.
void lower_envelope(std::vector<double>& f, size_t n, size_t stride, size_t start, std::vector<double>& g,
                    std::vector<double>& z, std::vector<size_t>& v) {
  g.resize(n), z.resize(n + 1), v.resize(n);
  for (size_t q = 0; q < n; ++q) g[q] = f[start + q * stride];
  size_t k = 0;
  v[0] = 0, z[0] = -kNoCellSet, z[1] = kNoCellSet;
  for (size_t q = 1; q < n; ++q) {
    double s;
    while (true) {
      s = ((g[q] + double(q * q)) - (g[v[k]] + double(v[k] * v[k]))) / (2.0 * double(q) - 2.0 * double(v[k]));
      if (s > z[k] || k == 0) break;
      --k;
    }
    if (s <= z[k]) {  // k == 0, and q's parabola lies under v[0]'s everywhere
      v[0] = q, z[1] = kNoCellSet;
      continue;
    }
    ++k, v[k] = q, z[k] = s, z[k + 1] = kNoCellSet;
  }
  k = 0;
  for (size_t q = 0; q < n; ++q) {
    while (z[k + 1] < double(q)) ++k;
    const double dq = double(q) - double(v[k]);
    f[start + q * stride] = dq * dq + g[v[k]];
  }
}

}  // namespace

std::vector<double> squared_distances(const std::vector<uint8_t>& from, int w, int h) {
  std::vector<double> d(from.size());
  bool any = false;
  for (size_t i = 0; i < d.size(); ++i) d[i] = from[i] ? 0 : kNoCellSet, any = any || from[i];
  if (!any) return d;
  std::vector<double> g, z;
  std::vector<size_t> v;
  for (int y = 0; y < h; ++y) lower_envelope(d, size_t(w), 1, size_t(y) * size_t(w), g, z, v);
  for (int x = 0; x < w; ++x) lower_envelope(d, size_t(h), size_t(w), size_t(x), g, z, v);
  return d;
}

}  // namespace slicereuse
