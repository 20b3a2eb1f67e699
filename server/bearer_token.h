#pragma once
// The service's one secret (issue 31, item 1): a bearer token read from a file at start-up, which every /api
// request must then carry as "Authorization: Bearer <token>". Without one, only loopback addresses may be
// bound unless --no-auth says otherwise.
#include <filesystem>
#include <string>
#include <string_view>

namespace facetlight::server {

// The most and fewest characters a token may have: short ones can be guessed over the network.
constexpr size_t kMinTokenChars = 16;
constexpr size_t kMaxTokenChars = 4096;

// The first line of `file`, without trailing white space. Throws Error when the file cannot be read, or the
// line is empty, too short, too long or holds characters other than visible ASCII.
std::string readTokenFile(const std::filesystem::path& file);

// Whether an Authorization header's value is "Bearer <token>" (the scheme in any case) with this token.
// Compares in time that depends on the token's length only, not on how much of it was guessed right.
bool bearerMatches(std::string_view authorization, std::string_view token);

// Whether binding `host` keeps the service on this machine: localhost, 127.0.0.0/8, ::1 (also v4-mapped).
bool isLoopbackAddress(const std::string& host);

}  // namespace facetlight::server
