// Buffer and ReuseBuffers: while a ReuseBuffers lives, a freed large buffer is handed out again,
// also for a slightly larger request (the next family member), and only once.
#include <gtest/gtest.h>

#include "slicereuse/util/buffer.h"

using namespace slicereuse;

TEST(ReuseBuffers, KeepsFreedLargeBuffersForTheNextMember) {
  const size_t n = size_t(50) << 20;  // 50 M doubles: 400 MB of address space
  const void* first;
  {
    const ReuseBuffers keep;
    {
      Buffer<double> a(n);
      a.front() = 1;
      a.back() = 2;
      first = a.data();
    }
    Buffer<double> b(n + n / 20);  // 5 % larger: still fits the kept one
    EXPECT_EQ(b.data(), first);
    b.back() = 3;  // the whole requested size is usable
    Buffer<double> c(n);  // the kept one is taken: a fresh one
    EXPECT_NE(c.data(), first);
  }
}

TEST(ReuseBuffers, KeptBuffersAreReleasedOnDemandAndKeepingGoesOn) {
  const size_t n = size_t(4) << 20;  // 32 MB: large enough to be kept
  const ReuseBuffers keep;
  release_kept_buffers();
  { Buffer<double> a(n); }
  const size_t kept = kept_buffer_bytes();
  EXPECT_GE(kept, n * sizeof(double));
  EXPECT_EQ(release_kept_buffers(), kept);
  EXPECT_EQ(kept_buffer_bytes(), 0u);
  { Buffer<double> b(n); }
  EXPECT_EQ(kept_buffer_bytes(), kept);  // still keeping while `keep` lives
  release_kept_buffers();
}
