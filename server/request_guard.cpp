#include "request_guard.h"

#include <algorithm>
#include <cctype>

#include "bearer_token.h"

namespace facetlight::server {

namespace {

bool isHexId(std::string_view s) {
    return s.size() == 32 && std::all_of(s.begin(), s.end(), [](char c) {
               return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f');
           });
}

// Whether `path` matches the route template segment by segment, without regular expressions (libstdc++'s
// can overflow the stack on long paths).
bool matchesTemplate(std::string_view pattern, std::string_view path) {
    for (;;) {
        const size_t p = pattern.find('/'), q = path.find('/');
        const std::string_view a = pattern.substr(0, p), b = path.substr(0, q);
        if (!(a == "{id}" ? isHexId(b) : a == b)) return false;
        if (p == std::string_view::npos || q == std::string_view::npos) return p == q;
        pattern.remove_prefix(p + 1);
        path.remove_prefix(q + 1);
    }
}

bool hasControlCharacter(std::string_view s) {
    return std::any_of(s.begin(), s.end(), [](char c) { return uint8_t(c) < 0x20 || c == 0x7f; });
}

Refusal refuse(int status, std::string detail) {
    return {status, std::move(detail), {{"Connection", "close"}}};
}

std::string lowerCase(std::string_view s) {
    std::string out(s);
    for (char& c : out) c = char(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

// Whether `authority` (a Host header, or an Origin after its scheme) is one of `hosts`, with or without a
// port. "[::1]" holds colons of its own: a port comes after the last one, outside the brackets.
bool isAllowedHost(std::string_view authority, const std::set<std::string>& hosts) {
    std::string name = lowerCase(authority);
    if (const size_t colon = name.rfind(':');
        colon != std::string::npos && name.find(']', colon) == std::string::npos) {
        const std::string_view port = std::string_view(name).substr(colon + 1);
        if (port.empty() || port.size() > 5 || port.find_first_not_of("0123456789") != std::string::npos)
            return false;
        name.resize(colon);
    }
    return hosts.count(name) > 0;
}

// An Origin of ours: http or https (behind a proxy) and an allowed host; "null" (a sandboxed or file page) is
// not.
bool isOurOrigin(std::string_view origin, const std::set<std::string>& hosts) {
    const std::string lower = lowerCase(origin);
    for (std::string_view scheme : {"http://", "https://"})
        if (lower.starts_with(scheme))
            return isAllowedHost(std::string_view(lower).substr(scheme.size()), hosts);
    return false;
}

bool isApiPath(std::string_view path) {
    return path == "/api" || path.starts_with("/api/");
}

bool changesState(const std::string& method) {
    return method == "POST" || method == "PUT" || method == "PATCH" || method == "DELETE";
}

}  // namespace

std::vector<std::string> methodsAllowed(const std::vector<Route>& routes, std::string_view path) {
    std::vector<std::string> methods;
    for (const Route& r : routes)
        if (matchesTemplate(r.path, path)) {
            methods.push_back(r.method);
            if (r.method == "GET") methods.push_back("HEAD");
        }
    std::sort(methods.begin(), methods.end());
    methods.erase(std::unique(methods.begin(), methods.end()), methods.end());
    return methods;
}

std::optional<Refusal> checkRequest(const httplib::Request& req, const RequestRules& rules) {
    if (req.target.size() > rules.maxUrlBytes)
        return refuse(414, "the URL is longer than " + std::to_string(rules.maxUrlBytes) + " bytes");
    if (hasControlCharacter(req.path)) return refuse(400, "the path contains control characters");
    // HTTP/1.0 clients may send no Host; HTTP/1.1 requires one (httplib drops an empty one).
    if (!req.has_header("Host")) {
        if (req.version == "HTTP/1.1") return refuse(400, "an HTTP/1.1 request needs a Host header");
    } else if (!isAllowedHost(req.get_header_value("Host"), rules.allowedHosts))
        return refuse(421, "this server is not reached by that Host name; start it with --allowed-host NAME");
    if (changesState(req.method) && req.has_header("Origin") &&
        !isOurOrigin(req.get_header_value("Origin"), rules.allowedHosts))
        return refuse(403, "changes are taken only from this server's own pages: the Origin is not ours");
    if (!rules.token.empty() && isApiPath(req.path) &&
        !bearerMatches(req.get_header_value("Authorization"), rules.token)) {
        const bool sent = req.has_header("Authorization");
        Refusal r =
            refuse(401, sent ? "the bearer token is not this server's"
                             : "send the server's token (its --token-file) as Authorization: Bearer TOKEN");
        r.headers.emplace_back(
            "WWW-Authenticate",
            sent ? "Bearer realm=\"facetlight\", error=\"invalid_token\"" : "Bearer realm=\"facetlight\"");
        return r;
    }
    if (req.has_header("Transfer-Encoding"))
        return refuse(411, "chunked request bodies are not accepted: send Content-Length");

    std::optional<std::string> length;
    for (auto [it, end] = req.headers.equal_range("Content-Length"); it != end; ++it) {
        const std::string& v = it->second;
        if (v.empty() || v.size() > 15 || v.find_first_not_of("0123456789") != std::string::npos)
            return refuse(400, "Content-Length must be a whole number of bytes");
        if (length && *length != v)
            return refuse(400, "the request has two different Content-Length headers");
        length = v;
    }

    const std::vector<std::string> allowed = methodsAllowed(rules.routes, req.path);
    if (!allowed.empty() && std::find(allowed.begin(), allowed.end(), req.method) == allowed.end()) {
        std::string list;
        for (const auto& m : allowed) list += (list.empty() ? "" : ", ") + m;
        Refusal r{405, req.method + " is not allowed here; this resource takes " + list, {{"Allow", list}}};
        if (length && *length != "0") r.headers.emplace_back("Connection", "close");  // the body stays unread
        return r;
    }

    const size_t limit = rules.bodyLimit(req.path);
    if (length && std::stoull(*length) > limit)
        return refuse(413, "the request body is larger than " + std::to_string(limit) + " bytes");
    for (const auto& [route, types] : rules.bodyRoutes) {
        const size_t space = route.find(' ');
        if (route.substr(0, space) != req.method || !matchesTemplate(route.substr(space + 1), req.path))
            continue;
        if (!length) return refuse(411, "send the body with a Content-Length header");
        // A browser sends form and text bodies to any site without asking first: only our own types pass.
        if (const std::string type = mediaType(req); !types.count(type)) {
            std::string list;
            for (const auto& t : types) list += (list.empty() ? "" : " or ") + t;
            return refuse(415, "send the body as " + list + " (got " +
                                   (type.empty() ? std::string("no Content-Type") : escapeForLog(type, 80)) +
                                   ")");
        }
    }
    return std::nullopt;
}

std::string mediaType(const httplib::Request& req) {
    std::string type = req.get_header_value("Content-Type");
    type = type.substr(0, type.find(';'));
    while (!type.empty() && type.back() == ' ') type.pop_back();
    return lowerCase(type);
}

std::string escapeForLog(std::string_view text, size_t maxBytes) {
    std::string out;
    for (char c : text.substr(0, maxBytes)) {
        const auto u = uint8_t(c);
        if (u < 0x20 || u > 0x7e || c == '"' || c == '\\') {
            static const char kHex[] = "0123456789abcdef";
            out += "\\x";
            out += kHex[u >> 4];
            out += kHex[u & 15];
        } else {
            out += c;
        }
    }
    if (text.size() > maxBytes) out += "...";
    return out;
}

}  // namespace facetlight::server
