#include "util/excerpt.h"

#include <gtest/gtest.h>

using namespace facetlight;

TEST(Excerpt, ShortTextWholeLongTextCut) {
    EXPECT_EQ(inQuotes("total_depth<=62"), "'total_depth<=62'");
    EXPECT_EQ(inQuotes(std::string(100000, 'x')), "'" + std::string(kExcerptBytes, 'x') + "...'");
    EXPECT_EQ(excerpt("abcdef", 3), "abc...");
    EXPECT_EQ(excerpt("abc", 3), "abc");
}

TEST(Excerpt, NeverCutsInsideAUtf8Character) {
    // "é" is two bytes: a cut after 2 bytes of "aé" would keep only half of it.
    EXPECT_EQ(excerpt("a\xc3\xa9z", 2), "a...");
    EXPECT_EQ(excerpt("a\xc3\xa9z", 3), "a\xc3\xa9...");
}
