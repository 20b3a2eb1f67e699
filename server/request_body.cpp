#include "request_body.h"

#include "http_server.h"
#include "problem.h"
#include "util/error.h"

namespace facetlight::server {

size_t bodyLimit(const ServiceLimits& limits, const std::string& path) {
    return path == "/api/meshes" ? limits.maxUploadBytes : limits.maxBodyBytes;
}

bool BodyCollector::operator()(const char* data, size_t n) {
    if (bytes_.size() + n > limit_) {
        tooLarge_ = true;
        return false;
    }
    bytes_.append(data, n);
    return true;
}

void BodyCollector::read(const httplib::ContentReader& reader) {
    complete_ = reader(std::ref(*this));
}

void BodyCollector::readMultipart(const httplib::ContentReader& reader,
                                  const httplib::MultipartContentHeader& header,
                                  const std::function<bool()>& wanted) {
    complete_ =
        reader(header, [&](const char* data, size_t n) { return wanted() ? (*this)(data, n) : true; });
}

bool BodyCollector::refuseIncomplete(httplib::Response& res, const std::string& what) const {
    if (tooLarge_) {
        problem(res, 413, what + " is larger than " + std::to_string(limit_) + " bytes");
    } else if (const HttpServer::ReadRefusal& refused = HttpServer::readRefusal(); refused.status != 0) {
        problem(res, refused.status, refused.detail + "; nothing was stored");
    } else if (!complete_) {
        // The client went away, or lied about the length.
        problem(res, 400, "the body ended before its Content-Length; nothing was stored");
    } else {
        return false;
    }
    return true;
}

int64_t queryInt(const httplib::Request& req, const std::string& name, int64_t fallback, int64_t lo,
                 int64_t hi) {
    if (!req.has_param(name)) return fallback;
    const std::string v = req.get_param_value(name);
    const std::string msg =
        name + " must be an integer between " + std::to_string(lo) + " and " + std::to_string(hi);
    if (v.empty() || v.size() > 12 || v.find_first_not_of("0123456789") != std::string::npos)
        throw Error(name, msg);
    const int64_t x = std::stoll(v);
    if (x < lo || x > hi) throw Error(name, msg);
    return x;
}

}  // namespace facetlight::server
