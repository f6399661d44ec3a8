#include "pillar_grid.h"

#include <algorithm>

namespace slicereuse {

std::vector<size_t> PillarGrid::near(double x, double y) const {
  std::vector<size_t> out;
  const Cell c = cell(x, y);
  for (int64_t dy = -1; dy <= 1; ++dy)
    for (int64_t dx = -1; dx <= 1; ++dx) {
      const auto it = cells_.find({c.first + dx, c.second + dy});
      if (it != cells_.end()) out.insert(out.end(), it->second.begin(), it->second.end());
    }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace slicereuse
