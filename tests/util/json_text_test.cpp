#include <gtest/gtest.h>

#include <string>

#include "util/error.h"
#include "util/json_text.h"

using namespace facetlight;

namespace {

std::string nestedArrays(int depth) { return std::string(size_t(depth), '[') + std::string(size_t(depth), ']'); }

std::string nestedObjects(int depth) {
    std::string text;
    for (int i = 0; i < depth; ++i) text += "{\"a\":";
    text += "1";
    return text + std::string(size_t(depth), '}');
}

std::string errorOf(const std::string& text) {
    try {
        parseUntrustedJson(text, "the body");
    } catch (const Error& e) {
        return e.what();
    }
    return "no error";
}

}  // namespace

TEST(JsonText, NestingUpToTheLimitParses) {
    EXPECT_TRUE(parseUntrustedJson(nestedArrays(kMaxJsonDepth), "the body").is_array());
    EXPECT_EQ(parseUntrustedJson(nestedObjects(kMaxJsonDepth), "the body").size(), 1u);
    EXPECT_EQ(parseUntrustedJson(R"({"photons": 1000, "light": {"direction": [0, 0, -1]}})", "the job")["photons"],
              1000);
}

TEST(JsonText, DeeperNestingIsRefusedNamingTheLimit) {
    const std::string expected = "the body nests arrays and objects deeper than 64 levels";
    EXPECT_EQ(errorOf(nestedArrays(kMaxJsonDepth + 1)), expected);
    EXPECT_EQ(errorOf(nestedObjects(kMaxJsonDepth + 1)), expected);
    // Issue 18: 150 000 levels (300 KB, under the body limit) overflowed the stack.
    EXPECT_EQ(errorOf(nestedArrays(150'000)), expected);
    EXPECT_EQ(errorOf(std::string(150'000, '[')), expected);  // refused before the missing ends are seen
}

TEST(JsonText, SyntaxErrorsNameTheByte) {
    EXPECT_EQ(errorOf("{\"a\": }"), "the body is not valid JSON: byte 7");
    EXPECT_EQ(errorOf(""), "the body is not valid JSON: byte 1");
    EXPECT_EQ(errorOf("{} x"), "the body is not valid JSON: byte 4");
}

TEST(JsonText, NumbersBeyondADoubleAreRefused) {
    // fuzz_job found that nlohmann-json throws out_of_range, not parse_error, for such a literal.
    const std::string expected = "the body holds a number beyond the range of a double (about 1.8e308)";
    EXPECT_EQ(errorOf(R"({"light": {"direction": [2e308, 1e308, 1e308]}})"), expected);
    EXPECT_EQ(errorOf("-1e400"), expected);
}
