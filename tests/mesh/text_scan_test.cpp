// What a message may quote of a file or its name (mesh/text_scan.hpp).
#include <gtest/gtest.h>

#include "lbmshape/mesh/text_scan.hpp"

namespace lbmshape {
namespace {

// A file's content is quoted in ASCII: each byte beyond it shows as '?',
// even where it is well-formed UTF-8 (a no-break space in a keyword looks
// like a space, and the line like a good one).
TEST(TextScan, ContentIsQuotedInAscii)
{
  EXPECT_EQ(text::quoted("v\xc2\xa0"
                         "0 0 0"),
            "'v?"
            "?0 0 0'");
  EXPECT_EQ(text::quoted("caf\xc3\xa9"),
            "'caf?"
            "?'");
  EXPECT_EQ(text::printable("a\tb\r\n"), "a?b");
}

// A name is quoted in its own letters where they are printable UTF-8, and
// bytes that are not, or characters that hide or reorder text, become '?'.
TEST(TextScan, NamesKeepTheirPrintableLetters)
{
  EXPECT_EQ(text::quotedName("donn\xc3\xa9"
                             "es \xc3\xbc.bin"),
            "'donn\xc3\xa9"
            "es \xc3\xbc.bin'");
  EXPECT_EQ(text::quotedName("\xe6\x97\xa5\xe6\x9c\xac.bin"), "'\xe6\x97\xa5\xe6\x9c\xac.bin'");  // CJK
  EXPECT_EQ(text::quotedName("\xf0\x9f\x99\x82.bin"), "'\xf0\x9f\x99\x82.bin'");                  // U+1F642
  EXPECT_EQ(text::quotedName("latin1 \xe9.bin"), "'latin1 ?.bin'");                               // not UTF-8
  EXPECT_EQ(text::quotedName("\xc0\xaf"),
            "'?"
            "?'");  // overlong '/'
  EXPECT_EQ(text::quotedName("\xed\xa0\x80"),
            "'?"
            "?"
            "?'");  // a surrogate
  EXPECT_EQ(text::quotedName("a\xe2\x80\xae"
                             "b"),
            "'a?"
            "?"
            "?b'");  // right-to-left override
  EXPECT_EQ(text::quotedName("a\xc2\xa0"
                             "b"),
            "'a?"
            "?b'");  // no-break space
  EXPECT_EQ(text::quotedName("a\xc2\x85"
                             "b"),
            "'a?"
            "?b'");                            // C1 control (NEL)
  EXPECT_EQ(text::quotedName("\xc3"), "'?'");  // cut short
}

// The limit counts characters, not bytes.
TEST(TextScan, TheLimitCountsCharacters)
{
  const std::string name(70, 'a');
  EXPECT_EQ(text::quotedName(name), "'" + std::string(60, 'a') + "...'");
  std::string accented;
  for (int i = 0; i < 60; ++i) accented += "\xc3\xa9";
  EXPECT_EQ(text::quotedName(accented), "'" + accented + "'");
}

}  // namespace
}  // namespace lbmshape
