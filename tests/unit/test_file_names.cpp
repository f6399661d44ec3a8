// The naming rules (file_names.h): .srb in any case is binary; the encoding beside a contour file.
#include <gtest/gtest.h>

#include "slicereuse/formats/file_names.h"

using namespace slicereuse;

TEST(FileNames, SrbInAnyCaseIsBinary) {
  for (const char* name : {"m0.srb", "M0.SRB", "out/a.b/m0.Srb", ".srb"}) EXPECT_TRUE(is_binary_file_name(name)) << name;
  for (const char* name : {"m0.ctr", "m0.enc", "m0.map", "m0.srb.ctr", "m0srb", "srb", "", "m0.srbx"})
    EXPECT_FALSE(is_binary_file_name(name)) << name;
}

TEST(FileNames, EncodingBesideAContourFile) {
  EXPECT_EQ(encoding_file_beside("out/m0.srb"), "out/m0_enc.srb");
  EXPECT_EQ(encoding_file_beside("out/m0.SRB"), "out/m0_enc.srb");
  EXPECT_EQ(encoding_file_beside("out/m0.ctr"), "out/m0.enc");
  EXPECT_EQ(encoding_file_beside("out/m0.ctr", FileFormat::Binary), "out/m0_enc.srb");
  EXPECT_EQ(encoding_file_beside("out/m0.srb", FileFormat::Text), "out/m0.enc");
  // Only the extension goes: dots in folders and in the name stay.
  EXPECT_EQ(encoding_file_beside("a.b/m0"), "a.b/m0.enc");
  EXPECT_EQ(encoding_file_beside("a.b/m0.v2.srb"), "a.b/m0.v2_enc.srb");
}
