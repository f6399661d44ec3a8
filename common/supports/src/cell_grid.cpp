#include "cell_grid.h"

#include <algorithm>

namespace slicereuse {

std::vector<size_t> CellGrid::near(double x, double y) const {
  std::vector<size_t> out;
  for_each_near(x, y, [&](size_t item) { out.push_back(item); });
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace slicereuse
