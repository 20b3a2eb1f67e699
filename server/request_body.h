#pragma once
// Reading a request: its body as it arrives, within its route's limit; a query parameter.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>

#include <httplib.h>

#include "job_spec.h"

namespace facetlight::server {

// The most bytes a request body may have: uploads have their own limit. The one place both the check before
// routing (Content-Length) and the handlers' readers (BodyCollector, bytes as they arrive) take it from.
size_t bodyLimit(const ServiceLimits& limits, const std::string& path);

// Collects a request body as it arrives, stopping the read once it passes its route's limit. `read` says
// whether every byte of the Content-Length arrived: a body cut short (the client went away, or lied) stores
// nothing.
class BodyCollector {
  public:
    BodyCollector(const ServiceLimits& limits, const httplib::Request& req)
        : limit_(bodyLimit(limits, req.path)) {}
    bool operator()(const char* data, size_t n);
    void read(const httplib::ContentReader& reader);
    void readMultipart(const httplib::ContentReader& reader, const httplib::MultipartContentHeader& header,
                       const std::function<bool()>& wanted);
    // Answers a body that was not read whole, `what` naming it ("the job"): 413 past its limit, 408 when it
    // came too slowly (HttpServer::readRefusal), else 400 (it stopped short of its Content-Length). False
    // when the body is whole and nothing was answered.
    bool refuseIncomplete(httplib::Response& res, const std::string& what) const;
    std::string& bytes() { return bytes_; }

  private:
    size_t limit_;
    std::string bytes_;
    bool tooLarge_ = false;
    bool complete_ = false;
};

// A query parameter as an integer in [lo, hi]; `fallback` when absent. Throws Error naming it.
int64_t queryInt(const httplib::Request& req, const std::string& name, int64_t fallback, int64_t lo,
                 int64_t hi);

}  // namespace facetlight::server
