// Text from outside stored as valid UTF-8 (files/utf8_text.h): bad bytes
// become U+FFFD, good characters stay, a cut text starts on a character.
#include <gtest/gtest.h>

#include <string>

#include "files/utf8_text.h"

using xval::utf8CharacterStart;
using xval::validUtf8;

TEST(Utf8Text, GoodTextIsKept) {
  const std::string s = "plain, caf\xC3\xA9, \xE2\x82\xAC, \xF0\x9F\x98\x80, tab\t";
  EXPECT_EQ(validUtf8(s), s);
}

TEST(Utf8Text, EachBadByteBecomesTheReplacementCharacter) {
  EXPECT_EQ(validUtf8("a\xFF\xFE" "b"), "a\xEF\xBF\xBD\xEF\xBF\xBD" "b");
  EXPECT_EQ(validUtf8("\x80"), "\xEF\xBF\xBD");                  // a lone continuation byte
  EXPECT_EQ(validUtf8("\xE2\x82"), "\xEF\xBF\xBD\xEF\xBF\xBD");  // a sequence cut at the end
  EXPECT_EQ(validUtf8("\xC0\xAF"), "\xEF\xBF\xBD\xEF\xBF\xBD");  // an overlong '/'
  EXPECT_EQ(validUtf8("\xED\xA0\x80"), "\xEF\xBF\xBD\xEF\xBF\xBD\xEF\xBF\xBD");  // a surrogate
  EXPECT_EQ(validUtf8("\xF4\x90\x80\x80"), "\xEF\xBF\xBD\xEF\xBF\xBD\xEF\xBF\xBD\xEF\xBF\xBD");  // > U+10FFFF
  EXPECT_EQ(validUtf8("\xE2\x82x"), "\xEF\xBF\xBD\xEF\xBF\xBDx");  // a sequence broken by ASCII
}

TEST(Utf8Text, ACutStartsOnTheNextCharacter) {
  const std::string euros = "\xE2\x82\xAC\xE2\x82\xAC";
  EXPECT_EQ(utf8CharacterStart(euros, 0), 0u);
  EXPECT_EQ(utf8CharacterStart(euros.substr(1), 0), 2u);
  EXPECT_EQ(utf8CharacterStart(euros.substr(2), 0), 1u);
  // At most 3 continuation bytes are skipped: more is no character.
  EXPECT_EQ(utf8CharacterStart("\x80\x80\x80\x80\x80", 0), 3u);
}
