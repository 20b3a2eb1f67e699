#pragma once
// Checking refusals: that a call throws facetlight::Error whose message holds a fragment, or the field it names;
// and a file's bytes.
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

// The field f's refusal names (Error::field(), its message checked to name it too), or "no error".
template <class F>
std::string refusedField(F&& f) {
    try {
        f();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(e.field()), std::string::npos) << e.what();
        return e.field();
    }
    return "no error";
}

inline std::string readFileBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

}  // namespace facetlight::test
