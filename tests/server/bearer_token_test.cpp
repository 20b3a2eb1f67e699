#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "bearer_token.h"
#include "util/error.h"

using namespace facetlight::server;
namespace fs = std::filesystem;

namespace {

class TokenFile : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("facetlight_token_test_" + std::to_string(::getpid()));
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    fs::path write(const std::string& text) {
        const fs::path p = dir_ / "token";
        std::ofstream(p, std::ios::binary) << text;
        return p;
    }
    std::string refusal(const fs::path& p) {
        try {
            readTokenFile(p);
        } catch (const facetlight::Error& e) {
            return e.what();
        }
        return {};
    }
    fs::path dir_;
};

}  // namespace

TEST_F(TokenFile, TheFirstLineIsTheToken) {
    EXPECT_EQ(readTokenFile(write("abcdefghijklmnop0123\n")), "abcdefghijklmnop0123");
    EXPECT_EQ(readTokenFile(write("abcdefghijklmnop0123 \r\nsecond line\n")), "abcdefghijklmnop0123");
    EXPECT_EQ(readTokenFile(write("abcdefghijklmnop0123")), "abcdefghijklmnop0123");
}

TEST_F(TokenFile, EmptyShortOddOrMissingFilesAreRefused) {
    EXPECT_NE(refusal(write("")).find("empty"), std::string::npos);
    EXPECT_NE(refusal(write("\nabcdefghijklmnop0123\n")).find("empty"), std::string::npos);
    EXPECT_NE(refusal(write("short\n")).find("16"), std::string::npos);
    EXPECT_NE(refusal(write("abcdefgh ijklmnop0123\n")).find("visible ASCII"), std::string::npos);
    EXPECT_NE(refusal(dir_ / "missing").find("not a file"), std::string::npos);
    EXPECT_NE(refusal(dir_).find("not a file"), std::string::npos);
}

TEST(BearerToken, LoopbackAddresses) {
    for (const char* host : {"127.0.0.1", "127.1.2.3", "localhost", "::1", "[::1]", "::ffff:127.0.0.1"})
        EXPECT_TRUE(isLoopbackAddress(host)) << host;
    for (const char* host :
         {"0.0.0.0", "::", "192.168.1.4", "10.0.0.1", "::ffff:10.0.0.1", "example.com", "128.0.0.1", ""})
        EXPECT_FALSE(isLoopbackAddress(host)) << host;
}

TEST(BearerToken, OnlyTheWholeTokenMatches) {
    const std::string token = "abcdefghijklmnop0123";
    EXPECT_TRUE(bearerMatches("Bearer " + token, token));
    EXPECT_TRUE(bearerMatches("BEARER " + token, token));
    EXPECT_FALSE(bearerMatches("Bearer " + token + "4", token));
    EXPECT_FALSE(bearerMatches("Bearer " + token.substr(1), token));
    EXPECT_FALSE(bearerMatches("Bearer " + std::string(token.size(), 'a'), token));
    EXPECT_FALSE(bearerMatches(token, token));
    EXPECT_FALSE(bearerMatches("", token));
}
