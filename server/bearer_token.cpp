#include "bearer_token.h"

#include <arpa/inet.h>

#include <cctype>
#include <cerrno>
#include <cstring>
#include <fstream>

#include "util/error.h"

namespace facetlight::server {

std::string readTokenFile(const std::filesystem::path& file) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec))
        throw Error(file.string() + " is not a file (" + (ec ? ec.message() : "no such file") + ")");
    std::ifstream in(file, std::ios::binary);
    if (!in) throw Error("cannot read " + file.string() + ": " + std::strerror(errno));
    std::string token;
    std::getline(in, token);
    if (in.bad()) throw Error("cannot read " + file.string());
    while (!token.empty() && std::isspace(static_cast<unsigned char>(token.back()))) token.pop_back();
    if (token.empty()) throw Error(file.string() + ": its first line, the token, is empty");
    for (char c : token)
        if (c < 0x21 || c > 0x7e)
            throw Error(file.string() + ": the token may hold only visible ASCII characters, no spaces");
    if (token.size() < kMinTokenChars || token.size() > kMaxTokenChars)
        throw Error(file.string() + ": the token has " + std::to_string(token.size()) +
                    " characters; give it " + std::to_string(kMinTokenChars) + " to " +
                    std::to_string(kMaxTokenChars) + " (e.g. head -c 24 /dev/urandom | base64)");
    return token;
}

bool bearerMatches(std::string_view authorization, std::string_view token) {
    constexpr std::string_view kScheme = "bearer ";
    if (authorization.size() < kScheme.size()) return false;
    for (size_t i = 0; i < kScheme.size(); ++i)
        if (std::tolower(static_cast<unsigned char>(authorization[i])) != kScheme[i]) return false;
    std::string_view given = authorization.substr(kScheme.size());
    while (!given.empty() && given.front() == ' ') given.remove_prefix(1);
    while (!given.empty() && given.back() == ' ') given.remove_suffix(1);
    // Every byte of the token is compared whatever was given, with no early exit: the time taken says nothing
    // about how long a prefix matched.
    unsigned diff = given.size() != token.size();
    for (size_t i = 0; i < token.size(); ++i)
        diff |= uint8_t(token[i]) ^ uint8_t(i < given.size() ? given[i] : 0);
    return diff == 0;
}

bool isLoopbackAddress(const std::string& host) {
    if (host == "localhost") return true;
    in_addr v4{};
    if (::inet_pton(AF_INET, host.c_str(), &v4) == 1) return (ntohl(v4.s_addr) >> 24) == 127;
    std::string bare = host;
    if (bare.size() > 2 && bare.front() == '[' && bare.back() == ']') bare = bare.substr(1, bare.size() - 2);
    in6_addr v6{};
    if (::inet_pton(AF_INET6, bare.c_str(), &v6) != 1) return false;
    if (IN6_IS_ADDR_LOOPBACK(&v6)) return true;
    return IN6_IS_ADDR_V4MAPPED(&v6) && v6.s6_addr[12] == 127;
}

}  // namespace facetlight::server
