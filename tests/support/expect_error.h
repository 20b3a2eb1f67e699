#pragma once
// Checking refusals: that a call throws facetlight::Error whose message holds a fragment; and a file's bytes.
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "util/error.h"

namespace facetlight::test {

template <class F>
void expectError(F&& f, const std::string& fragment) {
    try {
        f();
        ADD_FAILURE() << "expected an error containing '" << fragment << "'";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
}

inline std::string readFileBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

}  // namespace facetlight::test
