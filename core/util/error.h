#pragma once
// The one exception type of facetlight (after Nori): loaders, validators and the tracer throw it with a
// message meant for the user; the CLI and the server catch it once at the top.
#include <stdexcept>
#include <string>

namespace facetlight {

class Error : public std::runtime_error {
  public:
    explicit Error(const std::string& message) : std::runtime_error(message) {}
    // About one field of a job: `field` is its dotted path ("light.direction", "render.width"), which the
    // message names; the server reports it as the problem's `field`.
    Error(const std::string& field, const std::string& message)
        : std::runtime_error(message), field_(field) {}

    const std::string& field() const { return field_; }
    // The same error about a field inside `parent` ("cut" makes "pavilion" "cut.pavilion"); the message,
    // which begins with the field's name, gains the parent in front.
    Error within(const std::string& parent) const {
        if (field_.empty()) return Error(parent, parent + ": " + what());
        return Error(parent + "." + field_, parent + "." + what());
    }

  private:
    std::string field_;
};

}  // namespace facetlight
