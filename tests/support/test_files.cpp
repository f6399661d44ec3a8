#include "test_files.h"

#include <zip.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "slicereuse/util/error.h"

namespace fs = std::filesystem;

namespace slicereuse::test {

double random_double(std::mt19937_64& rng) {
  static const double special[] = {0.0, -0.0, 0.1, -0.1, 1e-300, -5e-324, 2.2250738585072014e-308,
                                   1.7976931348623157e308, -123456.789, 1.0 / 3};
  if (rng() % 4 == 0) return special[rng() % std::size(special)];
  for (;;) {
    const uint64_t bits = rng();
    double d;
    std::memcpy(&d, &bits, sizeof d);
    if (std::isfinite(d)) return d;
  }
}

double random_t(std::mt19937_64& rng) {
  static const double special[] = {1.0, 0.5, 5e-324, 1e-300, 1 - 0x1p-53, 0x1p-52};
  if (rng() % 4 == 0) return special[rng() % std::size(special)];
  for (;;) {
    const double t = std::uniform_real_distribution<double>(0, 1)(rng);
    if (t > 0) return t;
  }
}

Slices make_slices(const std::vector<int>& sizes, uint64_t seed, size_t open_every) {
  std::mt19937_64 rng(seed);
  Slices s;
  s.thickness = 0.05;
  s.z_start = -1.2345678901234567;
  s.fingerprint = {1000, 0x00ab'cdef'0123'4567ull};  // leading zeros must survive in hex
  s.layer_begin = {0};
  s.contour_begin = {0};
  auto end_layer = [&] {
    s.layer_z.push_back(s.z_start + (double(s.layers()) + 0.5) * s.thickness);
    s.layer_begin.push_back(s.contour_open.size());
  };
  for (int n : sizes) {
    if (n < 0) {
      end_layer();
      continue;
    }
    s.contour_open.push_back(s.contour_open.size() % open_every == 1);
    s.contour_begin.push_back(s.contour_begin.back() + uint64_t(n));
  }
  end_layer();
  const size_t P = s.points();
  s.xyz.resize(3 * P);
  for (double& v : s.xyz) v = random_double(rng);
  s.face.resize(P);
  s.edge.resize(P);
  s.t.resize(P);
  for (size_t p = 0; p < P; ++p) {
    s.face[p] = uint32_t(p % 7 == 0 ? 999 : rng() % 1000);
    s.edge[p] = uint8_t(rng() % 3);
    s.t[p] = random_t(rng);
  }
  return s;
}

void expect_same_structure(const Slices& a, const Slices& b) {
  EXPECT_EQ(std::memcmp(&a.thickness, &b.thickness, 8), 0);
  EXPECT_EQ(std::memcmp(&a.z_start, &b.z_start, 8), 0);
  EXPECT_TRUE(same_bits(a.layer_z, b.layer_z));
  EXPECT_EQ(a.layer_begin, b.layer_begin);
  EXPECT_EQ(a.contour_begin, b.contour_begin);
  EXPECT_EQ(a.contour_open, b.contour_open);
}

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

std::string zip_entry(const std::string& archive, const std::string& name) {
  int err = 0;
  zip_t* z = zip_open(archive.c_str(), ZIP_RDONLY, &err);
  if (z == nullptr) {
    ADD_FAILURE() << "cannot open " << archive;
    return "";
  }
  zip_stat_t st;
  std::string bytes;
  if (zip_stat(z, name.c_str(), 0, &st) == 0) {
    bytes.resize(st.size);
    zip_file_t* f = zip_fopen(z, name.c_str(), 0);
    EXPECT_EQ(zip_fread(f, bytes.data(), st.size), zip_int64_t(st.size));
    zip_fclose(f);
  } else {
    ADD_FAILURE() << archive << " has no entry " << name;
  }
  zip_discard(z);
  return bytes;
}

void spit(const std::string& path, const std::string& bytes) {
  fs::remove(path);
  std::ofstream(path, std::ios::binary) << bytes;
}

std::vector<std::string> FileTest::leftovers() const {
  std::vector<std::string> found;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().filename().string().find(".tmp-") != std::string::npos)
      found.push_back(e.path().string());
  return found;
}

}  // namespace slicereuse::test
