// libFuzzer entry point for a job body as the service reads it: JSON text with bounded nesting, then the job
// with this service's limits. A facetlight::Error is the expected answer to bad input. A job that is accepted
// must read back from its stored form as the same job, or a restart would run something else: any other
// outcome aborts (a finding).
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "job_spec.h"
#include "util/error.h"
#include "util/json_text.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace facetlight;
    const server::ServiceLimits limits;
    nlohmann::json stored;
    try {
        const nlohmann::json body =
            parseUntrustedJson({reinterpret_cast<const char*>(data), size}, "the body");
        stored = toJson(server::parseJobSpec(body, 4, &limits));
    } catch (const Error&) {
        return 0;
    }
    if (toJson(server::parseJobSpec(stored, 4)) != stored) std::abort();
    return 0;
}
