#pragma once
// The one exception type of facetlight (after Nori): loaders, validators and the tracer throw it with a
// message meant for the user; the CLI and the server catch it once at the top.
#include <stdexcept>
#include <string>

namespace facetlight {

class Error : public std::runtime_error {
public:
    explicit Error(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace facetlight
