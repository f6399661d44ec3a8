// zip_file_sink: an archive created through it is the archive libzip writes itself into a file
// of its own, byte for byte, whatever its entries' sizes against the sink's buffer; a write the
// system refuses fails zip_close with the system's reason, and an .sl1 export then leaves
// nothing behind.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <zip.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

#include "error_of.h"
#include "slicereuse/printer/printer_profile.h"
#include "slicereuse/printfiles/export_masks.h"
#include "slicereuse/slicing/slice_layers.h"
#include "shapes.h"
#include "temp_folder.h"
#include "zip_file_sink.h"

using namespace slicereuse;

namespace {

class ZipFileSink : public test::TempFolderTest {};

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Entries around and across the sink's buffer: tiny, just under and over it, several times it;
// random (stored as they are) or runs of one byte (deflated).
std::vector<std::vector<uint8_t>> contents() {
  std::mt19937 random(5);
  std::vector<std::vector<uint8_t>> all;
  for (size_t n : {size_t(0), size_t(17), kWritebackBytes - 40, kWritebackBytes + 3, 3 * kWritebackBytes + 11,
                   size_t(65536), kWritebackBytes / 2}) {
    std::vector<uint8_t> random_bytes(n), runs(n, uint8_t(n % 251));
    for (uint8_t& b : random_bytes) b = uint8_t(random());
    all.push_back(random_bytes);
    all.push_back(runs);
  }
  return all;
}

// Writes the entries into za (the ones of even number stored) and closes it.
void write_entries(zip_t* za, const std::vector<std::vector<uint8_t>>& all) {
  for (size_t i = 0; i < all.size(); ++i) {
    zip_source_t* src = zip_source_buffer(za, all[i].data(), all[i].size(), 0);
    ASSERT_NE(src, nullptr);
    const zip_int64_t at = zip_file_add(za, ("entry" + std::to_string(i)).c_str(), src, 0);
    ASSERT_GE(at, 0) << zip_strerror(za);
    ASSERT_EQ(zip_set_file_compression(za, zip_uint64_t(at), i % 2 ? ZIP_CM_DEFLATE : ZIP_CM_STORE, 0), 0);
    ASSERT_EQ(zip_file_set_mtime(za, zip_uint64_t(at), 1700000000, 0), 0);
  }
}

}  // namespace

TEST_F(ZipFileSink, WritesTheArchiveLibzipWritesItself) {
  const std::vector<std::vector<uint8_t>> all = contents();
  int code = 0;
  zip_t* own = zip_open(path("own.zip").c_str(), ZIP_CREATE | ZIP_TRUNCATE, &code);
  ASSERT_NE(own, nullptr);
  write_entries(own, all);
  ASSERT_EQ(zip_close(own), 0);

  std::ofstream(path("sunk.zip")).close();  // the staged file the sink writes into
  zip_error_t error;
  zip_error_init(&error);
  zip_source_t* sink = zip_file_sink(path("sunk.zip"), &error);
  ASSERT_NE(sink, nullptr);
  zip_t* sunk = zip_open_from_source(sink, ZIP_CREATE | ZIP_TRUNCATE, &error);
  ASSERT_NE(sunk, nullptr) << zip_error_strerror(&error);
  zip_error_fini(&error);
  write_entries(sunk, all);
  ASSERT_EQ(zip_close(sunk), 0) << zip_strerror(sunk);

  const std::string a = slurp(path("own.zip")), b = slurp(path("sunk.zip"));
  EXPECT_GT(b.size(), 5 * kWritebackBytes);
  EXPECT_TRUE(a == b) << "sizes " << a.size() << " and " << b.size();
  // And it reads back, every entry checked against its CRC.
  zip_t* back = zip_open(path("sunk.zip").c_str(), ZIP_RDONLY | ZIP_CHECKCONS, &code);
  ASSERT_NE(back, nullptr);
  ASSERT_EQ(zip_get_num_entries(back, 0), zip_int64_t(all.size()));
  for (size_t i = 0; i < all.size(); ++i) {
    std::vector<uint8_t> read(all[i].size() + 1);
    zip_file_t* f = zip_fopen_index(back, i, 0);
    ASSERT_NE(f, nullptr);
    EXPECT_EQ(zip_fread(f, read.data(), read.size()), zip_int64_t(all[i].size()));
    read.pop_back();
    EXPECT_TRUE(read == all[i]) << "entry " << i;
    zip_fclose(f);
  }
  zip_discard(back);
}

// A write the system refuses midway (a file size limit, like a full disk): the export says why,
// and neither the archive nor its staged file is left.
TEST_F(ZipFileSink, AFailedWriteIsReportedWithItsReasonAndLeavesNothing) {
  PrinterProfile profile;
  profile.width_px = 2000;
  profile.height_px = 2000;
  profile.antialiasing = true;
  profile.gamma = 1;
  SliceOptions o;
  o.thickness = 0.05;
  o.encoding = false;
  const Slices s = slice_layers(test::make_sphere(20, 64, 32), o);
  rlimit old;
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &old), 0);
  rlimit small = old;
  small.rlim_cur = 3 * kWritebackBytes / 2;
  auto* previous = ::signal(SIGXFSZ, SIG_IGN);
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
  const std::string e = test::error_of([&] { export_masks(s, profile, path("big.sl1")); });
  ::setrlimit(RLIMIT_FSIZE, &old);
  ::signal(SIGXFSZ, previous);
  EXPECT_EQ(e, "cannot write '" + path("big.sl1") + "': Write error: File too large");
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}
