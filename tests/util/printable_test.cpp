// printable(): outside text in logs and messages. Each test names the forgery it stops.
#include "util/printable.h"

#include <gtest/gtest.h>

namespace vem::util {
namespace {

TEST(Printable, NewlineInANameCannotStartAForgedLogLine) {
  EXPECT_EQ(printable("evil\nvemd info: FAKE LINE.vem"), "evil\\nvemd info: FAKE LINE.vem");
  EXPECT_EQ(printable("a\r\nb\tc"), "a\\r\\nb\\tc");
}

TEST(Printable, BackslashIsDoubledSoAnEscapeCannotBeFaked) {
  EXPECT_EQ(printable("a\\nb"), "a\\\\nb");
  EXPECT_NE(printable("a\\nb"), printable("a\nb"));
}

TEST(Printable, ControlBytesAndTerminalEscapesBecomeHex) {
  EXPECT_EQ(printable(std::string_view("\x1b[2J\0x", 6)), "\\x1b[2J\\x00x");
  EXPECT_EQ(printable("\x7f"), "\\x7f");
}

TEST(Printable, WellFormedUtf8StaysReadable) {
  EXPECT_EQ(printable("Süd-Bühne 日本 🎥"), "Süd-Bühne 日本 🎥");
  EXPECT_TRUE(isPrintable("Süd-Bühne"));
}

TEST(Printable, MalformedUtf8ByteByByte) {
  EXPECT_EQ(printable("\xc3"), "\\xc3");                  // truncated
  EXPECT_EQ(printable("\xc0\xaf"), "\\xc0\\xaf");         // overlong '/'
  EXPECT_EQ(printable("\xed\xa0\x80"), "\\xed\\xa0\\x80");  // a surrogate
  EXPECT_EQ(printable("\xf5\x80\x80\x80"), "\\xf5\\x80\\x80\\x80");  // above U+10FFFF
  EXPECT_EQ(printable("\xe2\x82"), "\\xe2\\x82");         // cut short at the end
}

TEST(Printable, BidiOverridesAndLineSeparatorsAreShownNotObeyed) {
  EXPECT_EQ(printable("a\u202Eb"), "a\\u{202e}b");
  EXPECT_EQ(printable("a\u2028b"), "a\\u{2028}b");
  EXPECT_EQ(printable("a\u2067b"), "a\\u{2067}b");
  EXPECT_EQ(printable("a\u0085b"), "a\\u{0085}b");  // NEL, a C1 control
  EXPECT_FALSE(isPrintable("a\u202Eb"));
}

TEST(Printable, LongTextIsCutAndTheRestCounted) {
  const std::string text(1000, 'x');
  EXPECT_EQ(printable(text, 10), std::string(10, 'x') + "... (990 more bytes)");
  EXPECT_FALSE(isPrintable(text, 10));
  EXPECT_TRUE(isPrintable(text, 1000));
}

TEST(Printable, AUtf8SequenceCutByTheLimitIsEscapedNotSplit) {
  // "é" is two bytes; a limit of 1 keeps only its lead byte, shown as hex.
  EXPECT_EQ(printable("é", 1), "\\xc3... (1 more bytes)");
}

}  // namespace
}  // namespace vem::util
