// quoteUserText: what user text may reach a terminal in a message.
#include <gtest/gtest.h>

#include <string>

#include "compiler/literal.hpp"

namespace {

using wg::quoteUserText;

TEST(QuoteUserText, ControlCharactersAreEscaped) {
  EXPECT_EQ(quoteUserText("a\nb\x1b[31m\x7f"), "a\\x0ab\\x1b[31m\\x7f");
  EXPECT_EQ(quoteUserText("\xc2\x9b" "1m"), "\\u009b1m");  // C1 CSI, well-formed UTF-8
}

TEST(QuoteUserText, WellFormedUtf8IsKept) {
  const std::string text = "caf\xc3\xa9 \xe9\x9b\xaa \xf0\x9f\x8c\xa7 \xc2\xa0";
  EXPECT_EQ(quoteUserText(text), text);
}

TEST(QuoteUserText, BytesThatAreNotUtf8AreEscaped) {
  EXPECT_EQ(quoteUserText("\x9b" "31m"), "\\x9b31m");               // a lone CSI byte
  EXPECT_EQ(quoteUserText("\xff\xfe"), "\\xff\\xfe");
  EXPECT_EQ(quoteUserText("\xc0\xaf"), "\\xc0\\xaf");               // overlong '/'
  EXPECT_EQ(quoteUserText("\xed\xa0\x80"), "\\xed\\xa0\\x80");      // a surrogate
  EXPECT_EQ(quoteUserText("\xf4\x90\x80\x80"), "\\xf4\\x90\\x80\\x80");  // above U+10FFFF
  EXPECT_EQ(quoteUserText("\xe9\x9b"), "\\xe9\\x9b");               // cut short at the end
  EXPECT_EQ(quoteUserText("\xe9" "a\xaa"), "\\xe9a\\xaa");
}

TEST(QuoteUserText, LongTextIsShortened) {
  EXPECT_EQ(quoteUserText(std::string(100, 'x'), 10), std::string(10, 'x') + "...");
}

}  // namespace
