#pragma once
// A child process and its process group: started with stdout and stderr on one pipe, its output read line by
// line, and ended (SIGTERM to the whole group, then SIGKILL after a grace period) when asked to cancel.
#include <chrono>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "util/run_control.h"

namespace facetlight::server {

// Runs argv in its own process group with stdout and stderr on one pipe, calls
// onLine for each output line, ends the group when control.cancelled() becomes true.
struct ChildExit {
    int exitCode = -1;  // valid when signal == 0
    int signal = 0;     // the signal that ended the child, if any
    bool cancelled = false;
    std::string tail;  // the last few KB of output that were not progress lines
};
ChildExit runChild(const std::vector<std::string>& argv,
                   const std::function<bool(std::string_view line)>& onLine, const RunControl& control,
                   std::chrono::milliseconds cancelGrace);

}  // namespace facetlight::server
