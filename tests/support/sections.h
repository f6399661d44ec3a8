#pragma once
// expect_same_sections: GoogleTest assertions that two slicings describe the same sections:
// per layer the same contours as cyclic sequences of bit-identical points on the same edges,
// whatever the order of the contours and the start of each loop.
#include "slicereuse/slicing/slices.h"

namespace slicereuse::test {

void expect_same_sections(const Slices& a, const Slices& b);

}  // namespace slicereuse::test
