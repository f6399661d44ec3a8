#pragma once
// Helpers shared by the file tests: test slices with random data, a temporary folder per test,
// whole-file read/write; EXPECT_ERROR comes from error_of.h.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "error_of.h"
#include "slicereuse/slicing/slices.h"
#include "temp_folder.h"

namespace slicereuse::test {

// Finite doubles over the whole range: random bit patterns, plus values that stress printing.
double random_double(std::mt19937_64& rng);
// t in (0, 1], with the endpoints and extremes that stress decoding.
double random_t(std::mt19937_64& rng);

// Layers with closed and open contours, an empty layer, a one-point contour; xyz and encoding.
// sizes: points per contour, layers separated by -1; every open_every-th contour (from the
// second) is open. Layer k is at z_start + (k + 1/2) thickness; points are random doubles.
Slices make_slices(const std::vector<int>& sizes, uint64_t seed, size_t open_every = 3);

// Arrays of equal length and identical bytes (doubles compared bit for bit: -0, NaN payloads).
template <class A, class B>
bool same_bits(const A& a, const B& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof a[0]) == 0);
}
// EXPECTs that a and b have bit-identical thickness, z_start and layer_z and the same layers,
// contours and open flags.
void expect_same_structure(const Slices& a, const Slices& b);

std::string slurp(const std::string& path);
// Removes first: truncating a file in place makes ext4 flush it to disk on close, which slows
// the tests that rewrite a file thousands of times by an order of magnitude.
void spit(const std::string& path, const std::string& bytes);
// The bytes of one entry of a zip archive (an .sl1); "" and a test failure when it is missing.
std::string zip_entry(const std::string& archive, const std::string& name);

// TempFolderTest (a fresh folder per test) that can also list what atomic writers left behind.
class FileTest : public TempFolderTest {
 protected:
  // Temporary files (".tmp-") an atomic writer left behind.
  std::vector<std::string> leftovers() const;
};

}  // namespace slicereuse::test
