// The text formats' tokenizer (text_tokens.h): lines, numbers as whole tokens, words, quoting.
#include <gtest/gtest.h>

#include <string>
#include <string_view>

#include "error_of.h"
#include "slicereuse/util/text_tokens.h"

using namespace slicereuse::detail;

TEST(TextTokens, LinesDropTheirCarriageReturnAndAreNumberedFromOne) {
  const std::string text = "a b\r\n\nlast";
  LineReader r(text.data(), text.data() + text.size());
  Line l;
  std::string got;
  while (r.next(l)) got += std::to_string(l.number) + "[" + std::string(l.b, l.e) + "]";
  EXPECT_EQ(got, "1[a b]2[]3[last]");
}

TEST(TextTokens, ANumberIsAWholeToken) {
  const std::string line = " 1.5\t-2 7x 0x1 +3 1e999";
  const char* p = line.data();
  const char* e = p + line.size();
  double d = 0;
  int64_t i = 0;
  ASSERT_TRUE(parse_number(p, e, d));
  EXPECT_EQ(d, 1.5);
  ASSERT_TRUE(parse_number(p, e, i));
  EXPECT_EQ(i, -2);
  const char* at = p;
  EXPECT_FALSE(parse_number(p, e, i));  // "7x"
  EXPECT_EQ(p, at);                     // p stays where it was
  EXPECT_EQ(quoted_token(p, e), "'7x'");
  p = at + 3;
  EXPECT_FALSE(parse_number(p, e, i));  // "0x1": no hexadecimal in base 10
  p += 4;
  EXPECT_FALSE(parse_number(p, e, i));  // "+3": no '+'
  p += 3;
  EXPECT_FALSE(parse_number(p, e, d));  // out of range
  uint64_t h = 0;
  const std::string hex = "00ff";
  p = hex.data();
  ASSERT_TRUE(parse_number<16>(p, p + hex.size(), h));
  EXPECT_EQ(h, 255u);
}

TEST(TextTokens, WordsEndsAndQuoting) {
  const std::string line = "  layer 3  ";
  const char* p = line.data();
  const char* e = p + line.size();
  std::string_view w;
  ASSERT_TRUE(next_word(p, e, w));
  EXPECT_EQ(w, "layer");
  EXPECT_FALSE(at_end(p, e));
  ASSERT_TRUE(next_word(p, e, w));
  EXPECT_TRUE(at_end(p, e));
  EXPECT_FALSE(next_word(p, e, w));
  // Blanks across lines are CLI's only.
  EXPECT_TRUE(is_blank<true>('\n'));
  EXPECT_FALSE(is_blank('\n'));
  // At most 40 bytes, unprintable ones as '?'.
  const std::string junk = std::string("a\x01\xc3\xa9") + std::string(50, 'z');
  EXPECT_EQ(quoted_token(junk.data(), junk.data() + junk.size()), "'a???" + std::string(36, 'z') + "'");
  EXPECT_ERROR(fail_at_line("f.ctr", 7, "bad"), "'f.ctr', line 7: bad");
}
