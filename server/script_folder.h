#pragma once
// A read-only folder of JavaScript modules served under a URL prefix: the page's three.js, from Debian's
// libjs-three (/usr/share/javascript/three), at /vendor/three/. Only .js files under the listed subfolders,
// so that a module's relative import (OrbitControls' '../../../build/three.module.js') resolves; no directory
// listing, no dot files, no path that leaves the folder.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <httplib.h>

namespace facetlight::server {

// What the page and the served modules are sent with: checked again on every load, so that a page and its
// modules stay in step after an upgrade.
inline constexpr const char* kStaticCacheControl = "no-cache";

struct ScriptFolder {
    std::string prefix;                   // URL prefix ending in '/', e.g. "/vendor/three/"
    std::filesystem::path folder;         // e.g. /usr/share/javascript/three
    std::vector<std::string> subfolders;  // served subfolders, e.g. {"build", "examples/jsm"}
};

// The file that `subPath` (the request path after the prefix) names, or nothing when it names no .js file
// under one of the subfolders: empty, ".", ".." or dot-file components, characters other than letters,
// digits, '.', '_' and '-', another extension. Lexical, so unit-testable; the caller checks that it exists.
std::optional<std::filesystem::path> scriptPath(const ScriptFolder& scripts, std::string_view subPath);

// Serves GET and HEAD of the folder's scripts as text/javascript with kStaticCacheControl; other paths under
// the prefix get 404. False (and nothing served) when the folder is missing.
bool serveScripts(httplib::Server& server, const ScriptFolder& scripts);

}  // namespace facetlight::server
