// available_memory and check_memory_for: the smallest of MemAvailable, the cgroup's headroom and
// SLICEREUSE_MEMORY_LIMIT, and refusals that give the figures.
#include <gtest/gtest.h>
#include <stdlib.h>

#include <memory>
#include <string>

#include "error_of.h"
#include "shapes.h"
#include "slicereuse/slicing/slice_layers.h"
#include "slicereuse/transfer/transfer_contours.h"
#include "slicereuse/util/buffer.h"
#include "slicereuse/util/memory_budget.h"

using namespace slicereuse;

namespace {

// Sets SLICEREUSE_MEMORY_LIMIT for one test and removes it afterwards.
class MemoryLimit : public ::testing::Test {
 protected:
  void TearDown() override { ::unsetenv("SLICEREUSE_MEMORY_LIMIT"); }
  static void set(const char* value) { ::setenv("SLICEREUSE_MEMORY_LIMIT", value, 1); }
};

}  // namespace

TEST_F(MemoryLimit, CapsWhatIsAvailable) {
  const uint64_t machine = available_memory();
  ASSERT_GT(machine, uint64_t(64) << 20);  // /proc/meminfo is readable here
  set("64M");
  EXPECT_EQ(available_memory(), uint64_t(64) << 20);
  set("0.5G");
  EXPECT_EQ(available_memory(), std::min(machine, uint64_t(512) << 20));
  set("1000000");
  EXPECT_EQ(available_memory(), 1000000u);
  set("1000000000G");  // more than the machine has: the machine's figure
  EXPECT_LE(available_memory(), machine + (uint64_t(256) << 20));
}

TEST_F(MemoryLimit, RefusesAJobAboveItWithTheFigures) {
  set("1G");
  EXPECT_NO_THROW(check_memory_for(uint64_t(1) << 29, "slicing 10 layers", "use a thicker layer"));
  const std::string e =
      test::error_of([] { check_memory_for(uint64_t(3) << 30, "slicing 10 layers", "use a thicker layer"); });
  EXPECT_EQ(e, "slicing 10 layers needs 3.2 GB of memory, but only 1.1 GB are available; use a thicker layer");
}

TEST_F(MemoryLimit, AValueThatIsNoSizeIsNamed) {
  for (const char* bad : {"lots", "4GB", "-1G", "0", "1e30G", "G"}) {
    set(bad);
    const std::string e = test::error_of([] { available_memory(); });
    EXPECT_NE(e.find("SLICEREUSE_MEMORY_LIMIT is '" + std::string(bad) + "'"), std::string::npos) << e;
  }
}

TEST_F(MemoryLimit, TransferRefusesAnOutputAboveItWithTheFigures) {
  const Mesh box = test::make_box(0, 0, 0, 10, 10, 10, 4);
  SliceOptions o;
  o.thickness = 0.5;
  const Slices encoding = slice_layers(box, o);
  set("1K");  // the 20 layers' points take more than 1 KiB
  const std::string e = test::error_of([&] { transfer_contours(encoding, box, TransferOptions()); });
  EXPECT_NE(e.find("transferring " + std::to_string(encoding.points()) + " contour points needs"), std::string::npos)
      << e;
  ::unsetenv("SLICEREUSE_MEMORY_LIMIT");
  EXPECT_EQ(transfer_contours(encoding, box, TransferOptions()).points(), encoding.points());
}

// A job short of memory first gives back what caches keep (reclaim_memory), then refuses if it
// still does not fit; each freed byte is counted once, also when it passed through the kept
// buffers.
TEST_F(MemoryLimit, ReclaimersAreCalledBeforeARefusalAndCountedOnce) {
  auto calls = std::make_shared<int>(0);
  auto cached = std::make_shared<Buffer<double>>();
  add_memory_reclaimer([calls, cached] {
    ++*calls;
    const uint64_t bytes = cached->size() * sizeof(double);
    Buffer<double>().swap(*cached);
    return bytes;
  });
  const ReuseBuffers keep;
  release_kept_buffers();
  cached->resize(size_t(4) << 20);  // 32 MB that the cache frees into the kept buffers
  const uint64_t freed = reclaim_memory();
  EXPECT_EQ(*calls, 1);
  EXPECT_GE(freed, uint64_t(32) << 20);
  EXPECT_LT(freed, uint64_t(64) << 20);  // not once from the cache and again from the kept buffers
  set("1M");
  EXPECT_ERROR(check_memory_for(uint64_t(2) << 20, "a job of 2 MB", "try less"), "a job of 2 MB needs");
  EXPECT_EQ(*calls, 2);
  check_memory_for(uint64_t(1) << 19, "a job of 0.5 MB", "try less");
  EXPECT_EQ(*calls, 2);  // it fit: nothing reclaimed
}
