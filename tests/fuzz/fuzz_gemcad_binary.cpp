// libFuzzer entry point for the GemCad binary .gem loader (see fuzz_target.h); replay_main.cpp runs it
// without libFuzzer.
#include "fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    return facetlight::fuzz::parseAndBuild(data, size, facetlight::MeshFormat::GemCadBinary);
}
