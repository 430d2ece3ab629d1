// SPDX-License-Identifier: MIT
// PrintableText and the error types built on it: messages quoting a damaged file never carry raw
// bytes (a flipped byte in an HDF5 attribute value used to reach the terminal as 0xff).
#include "core/printable_text.h"

#include <gtest/gtest.h>

#include "core/errors.h"
#include "core/utf8.h"

namespace rpt {
namespace {

TEST(PrintableText, ValidUtf8NewlinesAndTabsAreKept) {
  const std::string text = "Z\xc3\xbcrich \xe2\x9c\x93 \xf0\x9f\x98\x80 line\nnext\tcolumn";
  EXPECT_EQ(PrintableText(text), text);
  EXPECT_EQ(PrintableText(""), "");
}

TEST(PrintableText, InvalidBytesAndControlCharactersAreEscaped) {
  EXPECT_EQ(PrintableText("\xffpt-sequences"), "\\xffpt-sequences");
  EXPECT_EQ(PrintableText(std::string("a\0b", 3)), "a\\x00b");
  EXPECT_EQ(PrintableText("bell\x07 del\x7f cr\r esc\x1b"), "bell\\x07 del\\x7f cr\\x0d esc\\x1b");
  EXPECT_EQ(PrintableText("\xc0\xaf"), "\\xc0\\xaf") << "overlong '/'";
  EXPECT_EQ(PrintableText("\xed\xa0\x80"), "\\xed\\xa0\\x80") << "UTF-16 surrogate";
  EXPECT_EQ(PrintableText("\xf4\x90\x80\x80"), "\\xf4\\x90\\x80\\x80") << "beyond U+10FFFF";
  EXPECT_EQ(PrintableText("cut \xe2\x82"), "cut \\xe2\\x82") << "sequence cut short";
  EXPECT_EQ(PrintableText("\x80\xe2\x82\xac"), "\\x80\xe2\x82\xac") << "stray continuation, then a valid euro sign";
}

TEST(QuoteName, QuotesAndKeepsANameOnOneLine) {
  EXPECT_EQ(QuoteName("cam 1"), "'cam 1'");
  EXPECT_EQ(QuoteName("Z\xc3\xbcrich"), "'Z\xc3\xbcrich'");
  EXPECT_EQ(QuoteName("a\nb\tc\rd"), "'a\\x0ab\\x09c\\x0dd'");
  EXPECT_EQ(QuoteName("\x1b[31mred"), "'\\x1b[31mred'");
  EXPECT_EQ(QuoteName(""), "''");
}

// The same check decides which strings the JSON and XML writers replace; it must agree with the
// escaping above.
TEST(PrintableText, IsValidUtf8AgreesWithTheEscaping) {
  for (const std::string text : {"", "plain", "Z\xc3\xbcrich \xe2\x9c\x93 \xf0\x9f\x98\x80", "tab\tnewline\n"}) {
    EXPECT_TRUE(IsValidUtf8(text)) << text;
  }
  for (const std::string text : {"\xffpt", "\xc0\xaf", "\xed\xa0\x80", "\xf4\x90\x80\x80", "cut \xe2\x82", "\x80"}) {
    EXPECT_FALSE(IsValidUtf8(text)) << PrintableText(text);
  }
  // Control characters are valid UTF-8 (the writers escape them their own way).
  EXPECT_TRUE(IsValidUtf8("bell\x07"));
}

TEST(PrintableText, ErrorMessagesArePrintable) {
  EXPECT_STREQ(InputError("f.h5: attribute format is '\xffpt'").what(), "f.h5: attribute format is '\\xffpt'");
  EXPECT_STREQ(InputError(std::string("name '\x01'")).what(), "name '\\x01'");
  EXPECT_STREQ(ConfigError("option '\xfe'").what(), "option '\\xfe'");
  EXPECT_STREQ(InputError("plain message").what(), "plain message");
}

}  // namespace
}  // namespace rpt
