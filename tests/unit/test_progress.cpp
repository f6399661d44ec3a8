// sub_progress: a part of a job reported on [from, to] of the whole, cancellation passed through.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "slicereuse/util/error.h"
#include "slicereuse/util/progress.h"

using namespace slicereuse;

TEST(Progress, SubProgressMapsAPartOntoItsShare) {
  std::vector<double> seen;
  std::string phase;
  const Progress whole = [&](double f, const char* p) {
    seen.push_back(f);
    phase = p;
    return f < 0.6;
  };
  const Progress part = sub_progress(whole, 0.25, 0.75);
  report_progress(part, 0, "reading");
  report_progress(part, 0.5, "reading");
  EXPECT_EQ(seen, (std::vector<double>{0.25, 0.5}));
  EXPECT_EQ(phase, "reading");
  EXPECT_THROW(report_progress(part, 1, "reading"), Cancelled);  // 0.75: the whole cancels
  // No progress: the part has none either, and reporting to it does nothing.
  const Progress none = sub_progress(Progress(), 0.2, 0.6);
  EXPECT_FALSE(none);
  EXPECT_NO_THROW(report_progress(none, 1, "reading"));
}
