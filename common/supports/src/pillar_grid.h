#pragma once
// PillarGrid: pillars by their axes' (x, y) in square cells of side reach, so that the pillars
// within reach of a point are among those of the 3 x 3 cells around it (near, in increasing
// pillar order: the stages that ask take them in the order a scan of all would).
#include <cmath>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

namespace slicereuse {

class PillarGrid {
 public:
  explicit PillarGrid(double reach) : reach_(reach) {}
  void add(size_t pillar, double x, double y) { cells_[cell(x, y)].push_back(pillar); }
  std::vector<size_t> near(double x, double y) const;

 private:
  using Cell = std::pair<int64_t, int64_t>;
  Cell cell(double x, double y) const { return {int64_t(std::floor(x / reach_)), int64_t(std::floor(y / reach_))}; }
  double reach_;
  std::map<Cell, std::vector<size_t>> cells_;
};

}  // namespace slicereuse
