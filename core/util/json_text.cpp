#include "util/json_text.h"

#include <string>

#include "util/error.h"

namespace facetlight {

namespace {

// Thrown from the parser's callback to stop it at the first level too deep, before it reads further.
struct TooDeep {};

}  // namespace

nlohmann::json parseUntrustedJson(std::string_view text, const std::string& what) {
    using nlohmann::json;
    const json::parser_callback_t limitDepth = [](int depth, json::parse_event_t event, json&) {
        if ((event == json::parse_event_t::object_start || event == json::parse_event_t::array_start) &&
            depth >= kMaxJsonDepth)
            throw TooDeep{};
        return true;
    };
    try {
        return json::parse(text, limitDepth);
    } catch (const TooDeep&) {
        throw Error(what + " nests arrays and objects deeper than " + std::to_string(kMaxJsonDepth) + " levels");
    } catch (const json::parse_error& e) {
        throw Error(what + " is not valid JSON: byte " + std::to_string(e.byte));
    } catch (const json::out_of_range&) {
        // A literal beyond a double's range, such as 2e308 (found by fuzz_job).
        throw Error(what + " holds a number beyond the range of a double (about 1.8e308)");
    }
}

}  // namespace facetlight
