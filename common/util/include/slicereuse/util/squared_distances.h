#pragma once
// squared_distances: the exact Euclidean distance transform of a grid (Felzenszwalb and
// Huttenlocher's lower envelopes of parabolas, one pass along the rows, one along the columns).
//
// Input: a w x h grid, row after row, cells set (non-zero) in `from`. Output: for every cell, the
// squared distance in cells from its centre to the nearest set cell's centre; kNoCellSet
// everywhere when no cell is set. Time and memory linear in the cells.
#include <cstdint>
#include <vector>

namespace slicereuse {

constexpr double kNoCellSet = 1e20;

std::vector<double> squared_distances(const std::vector<uint8_t>& from, int w, int h);

}  // namespace slicereuse
