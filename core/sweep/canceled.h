#pragma once
// What a sweep or a study throws when its RunControl's cancel stops it. Here, in the lowest folder that
// throws it: the phases below return a `cancelled` flag instead.
#include <exception>

namespace facetlight {

class Canceled : public std::exception {
  public:
    const char* what() const noexcept override { return "canceled"; }
};

}  // namespace facetlight
