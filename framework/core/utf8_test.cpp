// UTF-8 checks and the markup escape: ill-formed bytes are found where they
// are, replaced by U+FFFD, and never reach a page as they are.
#include "core/utf8.h"

#include <gtest/gtest.h>

#include "core/markup.h"

namespace ll {
namespace {

const std::string kReplacement = "\xEF\xBF\xBD";

TEST(Utf8, WellFormedTextHasNoInvalidByte) {
  EXPECT_EQ(firstInvalidUtf8("plain ASCII"), std::string::npos);
  EXPECT_EQ(firstInvalidUtf8("f\xC3\xBCr \xE2\x82\xAC \xF0\x9F\x92\xA1"), std::string::npos);  // ü, €, a 4-byte emoji
  EXPECT_EQ(firstInvalidUtf8(""), std::string::npos);
}

TEST(Utf8, IllFormedSequencesAreFoundAtTheirFirstByte) {
  EXPECT_EQ(firstInvalidUtf8("f\xFCr"), 1u);              // Latin-1 ü
  EXPECT_EQ(firstInvalidUtf8("ab\xC0\x80"), 2u);          // overlong NUL
  EXPECT_EQ(firstInvalidUtf8("\xED\xA0\x80"), 0u);        // a UTF-16 surrogate
  EXPECT_EQ(firstInvalidUtf8("\xF4\x90\x80\x80"), 0u);    // beyond U+10FFFF
  EXPECT_EQ(firstInvalidUtf8("ok \xE2\x82"), 3u);         // cut short at the end
  EXPECT_EQ(firstInvalidUtf8("\xC3\xBC\xFF", 2), 2u);     // from an offset
}

TEST(Utf8, ReplacementKeepsGoodTextAndReplacesEachBadByte) {
  EXPECT_EQ(replaceInvalidUtf8("f\xC3\xBCr"), "f\xC3\xBCr");
  EXPECT_EQ(replaceInvalidUtf8("f\xFCr"), "f" + kReplacement + "r");
  EXPECT_EQ(replaceInvalidUtf8("\xE2\x82"), kReplacement + kReplacement);
  EXPECT_EQ(firstInvalidUtf8(replaceInvalidUtf8(std::string("\x80\xFF\xC3", 3))), std::string::npos);
}

TEST(Markup, EscapesQuotesAndBracketsDropsControlsAndReplacesBadBytes) {
  EXPECT_EQ(escapeMarkup("<a href=\"x\">Tom's & Jerry</a>"),
            "&lt;a href=&quot;x&quot;&gt;Tom&#39;s &amp; Jerry&lt;/a&gt;");
  EXPECT_EQ(escapeMarkup("line\nbreak\x01"), "line&#10;break");
  EXPECT_EQ(escapeMarkup("line\nbreak\ttab", true), "line\nbreak\ttab");
  EXPECT_EQ(escapeMarkup("Gr\xFC\xDF" "e"), "Gr" + kReplacement + kReplacement + "e");
}

}  // namespace
}  // namespace ll
