#pragma once
// UnionFind: n elements 0..n-1, each first in a set of its own; join(a, b) merges the sets of a
// and b, find(a) gives the representative of a's set (path halving keeps finds short).
// add() appends one more element in a set of its own and returns it.
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <vector>

namespace slicereuse {

struct UnionFind {
  std::vector<uint32_t> parent;
  explicit UnionFind(size_t n = 0) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
  uint32_t add() {
    parent.push_back(uint32_t(parent.size()));
    return parent.back();
  }
  uint32_t find(uint32_t a) {
    while (parent[a] != a) a = parent[a] = parent[parent[a]];
    return a;
  }
  void join(uint32_t a, uint32_t b) { parent[find(a)] = find(b); }
};

}  // namespace slicereuse
