// SCALECERT_TIMING=1 prints the time of each stage on stderr (never in the output).
#pragma once
#include <chrono>
#include <cstdio>
#include <cstdlib>

namespace scalecert::internal {

struct StageClock {
    bool on = std::getenv("SCALECERT_TIMING") != nullptr;
    std::chrono::steady_clock::time_point t = std::chrono::steady_clock::now();
    void restart() { t = std::chrono::steady_clock::now(); }
    void lap(const char* what) {
        if (!on) return;
        auto now = std::chrono::steady_clock::now();
        std::fprintf(stderr, "scalecert: timing: %-22s %9.3f ms\n", what,
                     std::chrono::duration<double, std::milli>(now - t).count());
        t = now;
    }
};

}  // namespace scalecert::internal
