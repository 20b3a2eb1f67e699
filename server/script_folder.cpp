#include "script_folder.h"

#include <fstream>
#include <iterator>
#include <system_error>

namespace facetlight::server {

namespace {

bool safeComponent(std::string_view c) {
    if (c.empty() || c.front() == '.') return false;  // "", ".", "..", dot files
    for (const char ch : c) {
        const bool ok = (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9') ||
                        ch == '.' || ch == '_' || ch == '-';
        if (!ok) return false;
    }
    return true;
}

}  // namespace

std::optional<std::filesystem::path> scriptPath(const ScriptFolder& scripts, std::string_view subPath) {
    if (!subPath.ends_with(".js")) return std::nullopt;
    bool under = false;
    for (const std::string& sub : scripts.subfolders)
        under = under ||
                (subPath.size() > sub.size() + 1 && subPath.starts_with(sub) && subPath[sub.size()] == '/');
    if (!under) return std::nullopt;
    std::filesystem::path path = scripts.folder;
    for (size_t start = 0; start <= subPath.size();) {
        const size_t slash = std::min(subPath.find('/', start), subPath.size());
        const std::string_view component = subPath.substr(start, slash - start);
        if (!safeComponent(component)) return std::nullopt;
        path /= std::string(component);
        start = slash + 1;
    }
    return path;
}

bool serveScripts(httplib::Server& server, const ScriptFolder& scripts) {
    std::error_code ec;
    if (!std::filesystem::is_directory(scripts.folder, ec)) return false;
    // Bounded, not (.*): libstdc++'s regex recurses once per character matched.
    const std::string pattern = scripts.prefix + "([A-Za-z0-9_./-]{1,256})";
    server.Get(pattern, [scripts](const httplib::Request& req, httplib::Response& res) {
        const std::optional<std::filesystem::path> path = scriptPath(scripts, req.matches[1].str());
        std::error_code error;
        std::ifstream in;
        if (path && std::filesystem::is_regular_file(*path, error)) in.open(*path, std::ios::binary);
        if (!in.is_open()) {
            res.status = 404;  // the error handler writes the problem body
            return;
        }
        res.set_header("Cache-Control", kStaticCacheControl);
        res.set_content(std::string(std::istreambuf_iterator<char>(in), {}), "text/javascript");
    });
    return true;
}

}  // namespace facetlight::server
