#include "util/bounded_read.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "util/error.h"

namespace facetlight {

std::string readFileUpTo(const std::string& path, size_t maxBytes, const std::string& what) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) throw Error(path + ": is a directory, not a " + what);
    auto tooLarge = [&] {
        return Error(path + ": the " + what + " is larger than " + std::to_string(maxBytes) + " bytes");
    };
    if (std::filesystem::is_regular_file(path, ec) && std::filesystem::file_size(path, ec) > maxBytes && !ec)
        throw tooLarge();
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(path + ": cannot open: " + std::strerror(errno));
    std::string bytes;
    char chunk[1 << 16];
    // Read in chunks up to one byte past the cap: devices and pipes have no size to ask for first.
    while (bytes.size() <= maxBytes && in.read(chunk, sizeof chunk).gcount() > 0)
        bytes.append(chunk, size_t(in.gcount()));
    if (in.bad()) throw Error(path + ": cannot read: " + std::strerror(errno));
    if (bytes.size() > maxBytes) throw tooLarge();
    return bytes;
}

}  // namespace facetlight
