#pragma once
// CellGrid: items (indices) by their (x, y) in square cells of side reach, so that the items
// within reach of a point are among those of the 3 x 3 cells around it. near: those items, in
// increasing order (the stages that ask take them in the order a scan of all would);
// for_each_near: f(item) for each of them, in no fixed order, without a list.
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

namespace slicereuse {

class CellGrid {
 public:
  explicit CellGrid(double reach) : reach_(reach) {}
  void add(size_t item, double x, double y) { cells_[cell(x, y)].push_back(item); }
  std::vector<size_t> near(double x, double y) const;
  template <class F>
  void for_each_near(double x, double y, F f) const {
    const Cell c = cell(x, y);
    for (int64_t dy = -1; dy <= 1; ++dy)
      for (int64_t dx = -1; dx <= 1; ++dx) {
        const auto it = cells_.find({c.first + dx, c.second + dy});
        if (it != cells_.end())
          for (const size_t item : it->second) f(item);
      }
  }

 private:
  using Cell = std::pair<int64_t, int64_t>;
  struct CellHash {
    size_t operator()(const Cell& c) const { return size_t(uint64_t(c.first) * 0x9E3779B1u + uint64_t(c.second)); }
  };
  Cell cell(double x, double y) const { return {int64_t(std::floor(x / reach_)), int64_t(std::floor(y / reach_))}; }
  double reach_;
  std::unordered_map<Cell, std::vector<size_t>, CellHash> cells_;
};

}  // namespace slicereuse
