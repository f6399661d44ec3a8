#pragma once
// LayerView: one layer's contours, drawn from one or more slicings without copying them: part i
// is layer parts[i].layer of *parts[i].slices. A build plate's layer is its members' layers at
// that height, each member's slicing a part; LayerView(s, k) is layer k of s alone. The parts
// (and the slicings) must outlive the view.
#include <cstddef>

#include "slicereuse/slicing/slices.h"

namespace slicereuse {

struct LayerPart {
  const Slices* slices;
  size_t layer;
  bool support = false;  // the layer of a support (a print's masks treat supports' air apart)
};

class LayerView {
 public:
  LayerView(const Slices& s, size_t k) : one_{&s, k} {}
  LayerView(const LayerPart* parts, size_t n) : parts_(parts), n_(n) {}

  const LayerPart* begin() const { return parts_ ? parts_ : &one_; }
  const LayerPart* end() const { return begin() + n_; }

 private:
  LayerPart one_{nullptr, 0};
  const LayerPart* parts_ = nullptr;  // null: the view is one_
  size_t n_ = 1;
};

}  // namespace slicereuse
