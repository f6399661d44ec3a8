// Contour and encoding files (text and binary): exact round trips, validation, and rejection of
// corrupted, truncated or mismatched files with messages that name the problem.
#include <gtest/gtest.h>
#include <signal.h>
#include <stdlib.h>
#include <sys/resource.h>
#include <xxhash.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "error_of.h"
#include "slicereuse/formats/slice_files.h"
#include "slicereuse/util/atomic_file.h"
#include "slicereuse/util/error.h"
#include "test_files.h"

using namespace slicereuse;
using namespace slicereuse::test;
namespace fs = std::filesystem;

namespace {

Slices sample() { return make_slices({5, 3, 4, -1, -1, 7, 2, 1, -1, 30, 3, 3, 9}, 42); }

class SliceFiles : public test::FileTest {};

uint64_t u64_at(const std::string& b, size_t at) {
  uint64_t v;
  std::memcpy(&v, b.data() + at, 8);
  return v;
}
template <class T>
void set_at(std::string& b, size_t at, T v) {
  std::memcpy(&b[at], &v, sizeof v);
}
// Rewrites the header checksum so that only the deliberate change is seen.
void reseal(std::string& b) {
  uint32_t sections;
  std::memcpy(&sections, b.data() + 72, 4);
  const size_t table_end = 80 + 32 * size_t(sections);
  set_at<uint64_t>(b, table_end, XXH3_64bits(b.data(), table_end));
}

const FileFormat kFormats[] = {FileFormat::Text, FileFormat::Binary};
const char* ext(FileFormat f, bool encoding) {
  return f == FileFormat::Binary ? ".srb" : encoding ? ".enc" : ".ctr";
}

}  // namespace

TEST_F(SliceFiles, ContourRoundTripIsBitExact) {
  for (FileFormat f : kFormats) {
    const Slices s = sample();
    const std::string p = path(std::string("a") + ext(f, false));
    write_contour_file(p, s, f);
    const Slices r = read_contour_file(p);
    expect_same_structure(s, r);
    EXPECT_TRUE(same_bits(s.xyz, r.xyz));
    EXPECT_TRUE(r.face.empty() && r.edge.empty() && r.t.empty());
    EXPECT_EQ(r.fingerprint, Fingerprint{});
    EXPECT_EQ(r.points(), 67u);
    EXPECT_EQ(r.layers(), 4u);
    EXPECT_EQ(r.open_contours(), 3u);
  }
}

TEST_F(SliceFiles, EncodingRoundTripIsBitExact) {
  for (FileFormat f : kFormats) {
    const Slices s = sample();
    const std::string p = path(std::string("a") + ext(f, true));
    write_encoding_file(p, s, f);
    const Slices r = read_encoding_file(p);
    expect_same_structure(s, r);
    EXPECT_EQ(r.fingerprint, s.fingerprint);
    EXPECT_TRUE(same_bits(s.face, r.face));
    EXPECT_TRUE(same_bits(s.edge, r.edge));
    EXPECT_TRUE(same_bits(s.t, r.t));
    EXPECT_TRUE(r.xyz.empty());
  }
}

TEST_F(SliceFiles, EveryEdgeAndEndpointDecodesExactly) {
  Slices s = make_slices({9}, 1);
  for (size_t p = 0; p < 9; ++p) {
    s.edge[p] = uint8_t(p % 3);
    s.t[p] = p < 3 ? 1.0 : p < 6 ? 0x1p-1074 : 1 - 0x1p-53;
  }
  write_encoding_file(path("e.enc"), s, FileFormat::Text);
  const Slices r = read_encoding_file(path("e.enc"));
  EXPECT_TRUE(same_bits(s.edge, r.edge));
  EXPECT_TRUE(same_bits(s.t, r.t));
}

TEST_F(SliceFiles, EmptySlicesRoundTrip) {
  Slices s;
  s.thickness = 0.1;
  s.layer_begin = {0};
  s.contour_begin = {0};
  s.fingerprint = {12, 34};
  for (FileFormat f : kFormats) {
    write_contour_file(path("c"), s, f);
    write_encoding_file(path("e"), s, f);
    const Slices c = read_contour_file(path("c")), e = read_encoding_file(path("e"));
    EXPECT_EQ(c.layers() + c.contours() + c.points(), 0u);
    EXPECT_EQ(e.layers() + e.contours() + e.points(), 0u);
    EXPECT_EQ(e.fingerprint, s.fingerprint);
  }
}

// Several writer chunks and many reader blocks, so the parallel paths are exercised.
TEST_F(SliceFiles, LargeRoundTrip) {
  std::vector<int> sizes;
  for (int k = 0; k < 60; ++k) {
    for (int c = 0; c < 5; ++c) sizes.push_back(1000 + 37 * c + k);
    sizes.push_back(-1);
  }
  sizes.pop_back();
  const Slices s = make_slices(sizes, 7);
  ASSERT_GT(s.points(), 300000u);
  for (FileFormat f : kFormats) {
    write_contour_file(path("big.c"), s, f);
    write_encoding_file(path("big.e"), s, f);
    const Slices c = read_contour_file(path("big.c")), e = read_encoding_file(path("big.e"));
    expect_same_structure(s, c);
    expect_same_structure(s, e);
    EXPECT_TRUE(same_bits(s.xyz, c.xyz));
    EXPECT_TRUE(same_bits(s.face, e.face) && same_bits(s.edge, e.edge) && same_bits(s.t, e.t));
  }
}

TEST_F(SliceFiles, TextLayoutIsAsDocumented) {
  Slices s;
  s.thickness = 0.5;
  s.z_start = 0;
  s.layer_z = {0.25, 0.75};
  s.layer_begin = {0, 2, 2};
  s.contour_begin = {0, 3, 5};
  s.contour_open = {0, 1};
  s.xyz = {1, 0, 0.25, 0, 1, 0.25, -1, -0.5, 0.25, 2, 2, 0.25, 3, 2.5, 0.25};
  s.fingerprint = {8, 0x1f};
  s.face = {0, 1, 2, 7, 7};
  s.edge = {0, 1, 2, 0, 2};
  s.t = {0.25, 1, 0.5, 0.75, 0.125};
  write_contour_file(path("x.ctr"), s, FileFormat::Text);
  write_encoding_file(path("x.enc"), s, FileFormat::Text);
  EXPECT_EQ(slurp(path("x.ctr")),
            "# slicereuse contours 1\n# thickness 0.5\n# z_start 0\n"
            "# layers 2 contours 2 points 5\n"
            "layer 0 0.25 2\n1 0 0.25 0 1 0.25 -1 -0.5 0.25\nopen 2 2 0.25 3 2.5 0.25\n"
            "layer 1 0.75 0\n");
  EXPECT_EQ(slurp(path("x.enc")),
            "# slicereuse encoding 1\n# thickness 0.5\n# z_start 0\n"
            "# layers 2 contours 2 points 5\n# fingerprint 8 000000000000001f\n"
            "layer 0 0.25 2\n0 0.75 0.25 0 1 0 0 1 2 0.5 0 0.5\nopen 7 0.25 0.75 0 7 0.125 0 0.875\n"
            "layer 1 0.75 0\n");
}

TEST(ValidateSlices, CatchesEachInconsistency) {
  const Slices good = sample();
  EXPECT_NO_THROW(validate_slices(good));
  struct Case {
    const char* expected;
    std::function<void(Slices&)> damage;
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const Case cases[] = {
      {"thickness", [](Slices& s) { s.thickness = 0; }},
      {"thickness", [&](Slices& s) { s.thickness = nan; }},
      {"z_start", [&](Slices& s) { s.z_start = INFINITY; }},
      {"layer_z[2] is not finite", [&](Slices& s) { s.layer_z[2] = nan; }},
      {"layer_begin has 4 entries, expected 5", [](Slices& s) { s.layer_begin.pop_back(); }},
      {"layer_begin[0] is 1", [](Slices& s) { s.layer_begin[0] = 1; }},
      {"layer_begin is not increasing at layer 1", [](Slices& s) { s.layer_begin[2] = 1; }},
      {"layer_begin ends at 12", [](Slices& s) { s.layer_begin.back() = 12; }},
      {"contour_begin has", [](Slices& s) { s.contour_begin.push_back(70); }},
      {"contour_begin[0] is 2", [](Slices& s) { s.contour_begin[0] = 2; }},
      {"contour_begin is not increasing at contour 1", [](Slices& s) { s.contour_begin[2] = 4; }},
      {"it has no points", [](Slices& s) { s.contour_begin[2] = s.contour_begin[1]; }},
      {"contour_open[3] is 2", [](Slices& s) { s.contour_open[3] = 2; }},
      {"xyz has 200 numbers", [](Slices& s) { s.xyz.pop_back(); }},
      {"xyz[17] is not finite", [&](Slices& s) { s.xyz[17] = -INFINITY; }},
      {"encoding arrays face/edge/t have 67/67/66", [](Slices& s) { s.t.pop_back(); }},
      {"face[5] = 1000 is not below the mesh's 1000 faces", [](Slices& s) { s.face[5] = 1000; }},
      {"edge[6] = 3", [](Slices& s) { s.edge[6] = 3; }},
      {"t[7] = 0 is outside (0, 1]", [](Slices& s) { s.t[7] = 0; }},
      {"t[8] = 1.5 is outside", [](Slices& s) { s.t[8] = 1.5; }},
      {"t[9] = nan is outside", [&](Slices& s) { s.t[9] = nan; }},
      {"t[0] = -0.25", [](Slices& s) { s.t[0] = -0.25; }},
  };
  for (const Case& c : cases) {
    Slices s = good;
    c.damage(s);
    EXPECT_ERROR(validate_slices(s), c.expected);
  }
}

TEST_F(SliceFiles, BinaryTruncatedAnywhereIsRejected) {
  for (bool encoding : {false, true}) {
    const std::string p = path("t.srb"), q = path("cut.srb");
    encoding ? write_encoding_file(p, sample(), FileFormat::Binary)
             : write_contour_file(p, sample(), FileFormat::Binary);
    const std::string bytes = slurp(p);
    for (size_t n = 0; n < bytes.size(); ++n) {
      spit(q, bytes.substr(0, n));
      const std::string m = error_of([&] { encoding ? read_encoding_file(q) : read_contour_file(q); });
      SCOPED_TRACE("truncated at " + std::to_string(n) + ": " + m);
      EXPECT_NE(m.find(q), std::string::npos);
      if (n >= 8) EXPECT_NE(m.find("truncated"), std::string::npos);
    }
  }
}

TEST_F(SliceFiles, BinaryFlippedByteAnywhereIsRejected) {
  for (bool encoding : {false, true}) {
    const std::string p = path("f.srb"), q = path("flipped.srb");
    encoding ? write_encoding_file(p, sample(), FileFormat::Binary)
             : write_contour_file(p, sample(), FileFormat::Binary);
    const std::string bytes = slurp(p);
    const size_t sections = encoding ? 7 : 5, table_end = 80 + 32 * sections;
    const char* names[] = {"layer_z", "layer_begin", "contour_begin", "contour_open",
                           "xyz",     "face",        "edge",          "t"};
    for (size_t at = 0; at < bytes.size(); ++at) {
      std::string b = bytes;
      b[at] ^= 0x10;
      spit(q, b);
      const std::string m = error_of([&] { encoding ? read_encoding_file(q) : read_contour_file(q); });
      SCOPED_TRACE("byte " + std::to_string(at) + ": " + m);
      if (at < 8) {
        EXPECT_NE(m.find("not a slicereuse file"), std::string::npos);
      } else if (at < 12) {
        EXPECT_NE(m.find("format version"), std::string::npos);
      } else if (at < 16) {
        EXPECT_NE(m.find("kind"), std::string::npos);
      } else if (at >= 72 && at < 76) {
        EXPECT_NE(m.find("sections"), std::string::npos);
      } else if (at < table_end + 8) {
        EXPECT_NE(m.find("header checksum mismatch"), std::string::npos);
      } else {
        // Find the section holding the byte, or the padding in front of it.
        for (size_t i = 0; i < sections; ++i) {
          const size_t entry = 80 + 32 * i;
          const uint64_t id = uint32_t(u64_at(bytes, entry)), off = u64_at(bytes, entry + 8),
                         size = u64_at(bytes, entry + 16);
          if (at < off) {
            EXPECT_NE(m.find(std::string("nonzero padding before section ") + names[id - 1]),
                      std::string::npos);
            break;
          }
          if (at < off + size) {
            EXPECT_NE(m.find(std::string("section ") + names[id - 1] + ": checksum mismatch"),
                      std::string::npos);
            break;
          }
        }
      }
    }
  }
}

TEST_F(SliceFiles, BinaryBadHeadersAreRejected) {
  const std::string p = path("h.srb"), q = path("bad.srb");
  write_contour_file(p, sample(), FileFormat::Binary);
  const std::string bytes = slurp(p);
  auto with = [&](const std::function<void(std::string&)>& change) {
    std::string b = bytes;
    change(b);
    spit(q, b);
    return q;
  };
  EXPECT_ERROR(read_contour_file(with([](std::string& b) { b[1] = 'X'; })), "not a slicereuse file");
  EXPECT_ERROR(read_contour_file(with([](std::string& b) { set_at<uint32_t>(b, 8, 2); })),
               "format version 2 is not supported");
  EXPECT_ERROR(read_contour_file(with([](std::string& b) { set_at<uint32_t>(b, 12, 7); })),
               "unknown file kind 7");
  // Counts claiming far more than the file holds: refused before any allocation.
  EXPECT_ERROR(read_contour_file(with([](std::string& b) {
                 set_at<uint64_t>(b, 48, uint64_t(1) << 50);
                 reseal(b);
               })),
               "more than the file's");
  EXPECT_ERROR(read_contour_file(with([](std::string& b) {
                 set_at<uint64_t>(b, 40, u64_at(b, 40) + 1);
                 reseal(b);
               })),
               "section 2 (contour_begin) has 88 bytes, the header's counts need 96");
  // A consistent header and table that point past the end of the file.
  EXPECT_ERROR(read_contour_file(with([](std::string& b) {
                 const uint64_t P = u64_at(b, 48) + 1000;
                 set_at<uint64_t>(b, 48, P);
                 set_at<uint64_t>(b, 80 + 32 * 4 + 16, 24 * P);
                 reseal(b);
               })),
               "beyond the end of the file");
  EXPECT_ERROR(read_contour_file(with([](std::string& b) { b += std::string(8, '\0'); })),
               "8 unexpected bytes after the last section");
}

TEST_F(SliceFiles, BinaryContentIsValidated) {
  Slices s = sample();
  write_encoding_file(path("v.srb"), s, FileFormat::Binary);
  std::string b = slurp(path("v.srb"));
  // Edge byte of point 3 set to 5, with the section checksum fixed so only validation can tell.
  const size_t entry = 80 + 32 * 5, off = u64_at(b, entry + 8), size = u64_at(b, entry + 16);
  b[off + 3] = 5;
  set_at<uint64_t>(b, entry + 24, XXH3_64bits(b.data() + off, size));
  reseal(b);
  spit(path("v.srb"), b);
  EXPECT_ERROR(read_encoding_file(path("v.srb")), "edge[3] = 5 is not 0, 1 or 2");
}

TEST_F(SliceFiles, TextDamageIsRejectedWithLineNumbers) {
  const Slices s = make_slices({2, 1, -1, 2}, 3);
  write_contour_file(path("c.ctr"), s, FileFormat::Text);
  write_encoding_file(path("e.enc"), s, FileFormat::Text);
  const std::string c = slurp(path("c.ctr")), e = slurp(path("e.enc"));
  // Lines: 1-4 header, 5 "layer 0", 6-7 contours, 8 "layer 1", 9 contour.
  auto lines_of = [](const std::string& text) {
    std::vector<std::string> l;
    size_t at = 0;
    for (size_t nl; (nl = text.find('\n', at)) != std::string::npos; at = nl + 1)
      l.push_back(text.substr(at, nl - at));
    return l;
  };
  auto join = [](const std::vector<std::string>& l) {
    std::string t;
    for (const auto& x : l) t += x + "\n";
    return t;
  };
  auto read_c = [&](const std::function<void(std::vector<std::string>&)> change) {
    auto l = lines_of(c);
    change(l);
    spit(path("bad.ctr"), join(l));
    return read_contour_file(path("bad.ctr"));
  };
  auto read_e = [&](const std::function<void(std::vector<std::string>&)> change) {
    auto l = lines_of(e);
    change(l);
    spit(path("bad.enc"), join(l));
    return read_encoding_file(path("bad.enc"));
  };
  // Unchanged, with comments, blank lines and CRLF added: still valid.
  EXPECT_NO_THROW(read_c([](auto& l) {
    l.insert(l.begin() + 4, "# made by hand");
    l.insert(l.begin() + 7, "");
    l[5] += "\r";
  }));
  EXPECT_ERROR(read_c([](auto& l) { l[3] = "# layers 3 contours 3 points 5"; }),
               "announces 3 layers and 3 contours, the file has 2 and 3");
  EXPECT_ERROR(read_c([](auto& l) { l[3] = "# layers 2 contours 3 points 6"; }),
               "announces 6 points, the file has 5");
  EXPECT_ERROR(read_c([](auto& l) { l.erase(l.begin() + 3); }),
               "lacks the line '# layers <L> contours <C> points <P>'");
  EXPECT_ERROR(read_c([](auto& l) { l.erase(l.begin()); }), "not a slicereuse file");
  EXPECT_ERROR(read_c([](auto& l) { l[0] = "# slicereuse contours 2"; }),
               "line 1: format version 2 is not supported");
  EXPECT_ERROR(read_c([](auto& l) { l[5] = "abc" + l[5].substr(l[5].find(' ')); }),
               "line 6: point 1: 'abc' is not a finite number");
  EXPECT_ERROR(read_c([](auto& l) { l[8] += " 7"; }),
               "line 9: 7 numbers, expected whole triples");
  EXPECT_ERROR(read_c([](auto& l) { l[8] = l[8].substr(0, l[8].rfind(' ')) + " nan"; }),
               "line 9: point 2: 'nan' is not a finite number");
  EXPECT_ERROR(read_c([](auto& l) { l[7] = "layer 2 0.1 1"; }),
               "line 8: layer 2 where layer 1 was expected");
  EXPECT_ERROR(read_c([](auto& l) { l.pop_back(); }), "ends inside layer 1");
  EXPECT_ERROR(read_c([](auto& l) { l[6] = "open"; }), "line 7: contour line has no points");
  EXPECT_ERROR(read_c([](auto& l) { l[4] = "layers 0 0.1 2"; }), "line 5: expected 'layer <k> <z> <n>'");
  EXPECT_ERROR(read_c([](auto& l) { l[0] = "# slicereuse encoding 1"; }),
               "this is an encoding file, expected a contour file");

  // Encoding lines: 1-5 header, 6 "layer 0", 7-8 contours.
  EXPECT_ERROR(read_e([](auto& l) { l.erase(l.begin() + 4); }), "lacks the line '# fingerprint");
  EXPECT_ERROR(read_e([](auto& l) { l[6] = "3 0.5 0.25 0.25 1 0 1 0"; }),
               "line 7: point 1: point not on a face edge");
  EXPECT_ERROR(read_e([](auto& l) { l[6] = "3 0 1 0 1000 0 1 0"; }),
               "line 7: point 2: face 1000 does not exist: the mesh has 1000 faces");
  EXPECT_ERROR(read_e([](auto& l) { l[6] = "3 -0.5 1.5 0 1 0 1 0"; }),
               "line 7: point 1: negative area coordinate '-0.5'");
  EXPECT_ERROR(read_e([](auto& l) { l[6] = "3 0 0 0 1 0 1 0"; }), "area coordinates are all 0");
  EXPECT_ERROR(read_e([](auto& l) { l[6] = "3 0.5 0.6 0 1 0 1 0"; }), "do not sum to 1");
  EXPECT_ERROR(read_e([](auto& l) { l[6] = "-3 0.5 0.5 0 1 0 1 0"; }), "'-3' is not a face id");
  EXPECT_ERROR(read_e([](auto& l) { l[6] = "3 0.5 0.5 0 1 0 1"; }),
               "line 7: 7 numbers, expected whole quads");
}

TEST_F(SliceFiles, WrongKindIsRejectedClearly) {
  for (FileFormat f : kFormats) {
    write_contour_file(path("c"), sample(), f);
    write_encoding_file(path("e"), sample(), f);
    EXPECT_ERROR(read_encoding_file(path("c")), "this is a contour file, expected an encoding file");
    EXPECT_ERROR(read_contour_file(path("e")), "this is an encoding file, expected a contour file");
  }
  spit(path("junk"), "solid cube\nfacet normal 0 0 1\n");
  EXPECT_ERROR(read_contour_file(path("junk")), "not a slicereuse file");
  spit(path("empty"), "");
  EXPECT_ERROR(read_contour_file(path("empty")), "empty file");
  EXPECT_ERROR(read_contour_file(path("missing")), "cannot open '" + path("missing") + "'");
}

TEST_F(SliceFiles, UnwritablePathThrowsAndLeavesNoFile) {
  spit(path("plain"), "x");
  const std::string bad[] = {dir + "/no/such/folder/a.srb", path("plain") + "/a.ctr"};
  for (const std::string& p : bad) {
    EXPECT_ERROR(check_writable(p), p);
    for (FileFormat f : kFormats) EXPECT_ERROR(write_contour_file(p, sample(), f), p);
    EXPECT_FALSE(fs::exists(p));
  }
  EXPECT_ERROR(check_writable(dir), "it is a folder");
  EXPECT_NO_THROW(check_writable(path("new.ctr")));
  EXPECT_TRUE(leftovers().empty());
}

// A write that fails after the temporary file has data must leave the old file untouched.
TEST_F(SliceFiles, CancelledWriteKeepsTheOldFile) {
  for (FileFormat f : kFormats) {
    const std::string p = path(std::string("keep") + ext(f, false));
    write_contour_file(p, make_slices({3, -1, 4}, 5), f);
    const std::string before = slurp(p);
    // Cancels as soon as the temporary file holds data (earlier calls may see it buffered).
    bool saw_partial = false;
    auto cancel = [&](double, const char*) {
      for (const std::string& t : leftovers()) saw_partial |= fs::file_size(t) > 0;
      return !saw_partial;
    };
    EXPECT_THROW(write_contour_file(p, make_slices(std::vector<int>(50, 100), 6), f, cancel),
                 Cancelled);
    EXPECT_TRUE(saw_partial);
    EXPECT_EQ(slurp(p), before);
    EXPECT_TRUE(leftovers().empty());
    // And an invalid structure is refused before anything is written.
    Slices broken = sample();
    broken.t[0] = 2;
    EXPECT_ERROR(write_encoding_file(p, broken, f), "t[0] = 2 is outside (0, 1]");
    EXPECT_EQ(slurp(p), before);
  }
}

// A real write failure (file size limit, like a full disk) midway through a large file.
TEST_F(SliceFiles, FailedWriteKeepsTheOldFile) {
  std::vector<int> sizes(200, 100);
  const Slices big = make_slices(sizes, 9);
  for (FileFormat f : kFormats) {
    const std::string p = path(std::string("limit") + ext(f, false));
    write_contour_file(p, make_slices({3}, 5), f);
    const std::string before = slurp(p);
    rlimit old;
    ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &old), 0);
    rlimit small = old;
    small.rlim_cur = 64 * 1024;
    auto* previous = ::signal(SIGXFSZ, SIG_IGN);
    ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
    const std::string m = error_of([&] { write_contour_file(p, big, f); });
    ::setrlimit(RLIMIT_FSIZE, &old);
    ::signal(SIGXFSZ, previous);
    EXPECT_NE(m.find("cannot write '" + p + "': File too large"), std::string::npos) << m;
    EXPECT_EQ(slurp(p), before);
    EXPECT_TRUE(leftovers().empty());
  }
}
