// crspline command line: progress of long runs on stderr, only when stderr
// is a terminal, and only once a run has taken more than a second: a line
// "crspline eval: 42%" rewritten in place, erased at the end. Never when
// stderr is a file or a pipe (scripts and tests see exactly one error line
// or nothing).
#pragma once

#include <chrono>
#include <cstdio>
#include <string>

#include <unistd.h>

namespace crspline::cli {

/// When the process started (static initialization, before main): the
/// second counts from here, input reading included, as the person at the
/// terminal waits it. (Counted from the progress object, a run that spent
/// 0.6 s reading its input and 0.9 s evaluating showed nothing.)
inline const std::chrono::steady_clock::time_point process_start = std::chrono::steady_clock::now();

class progress {
public:
    explicit progress(std::string label) : label_(std::move(label)), on_(::isatty(STDERR_FILENO) == 1) {}
    progress(const progress&) = delete;
    progress& operator=(const progress&) = delete;
    ~progress() {
        if (shown_) std::fprintf(stderr, "\r\033[K");
    }

    /// fraction of the work done, in [0, 1].
    void update(double fraction) {
        if (!on_) return;
        const auto now = clock::now();
        if (now - start_ < std::chrono::seconds(1) || now - last_ < std::chrono::milliseconds(200)) return;
        last_ = now;
        shown_ = true;
        std::fprintf(stderr, "\r%s: %3d%%", label_.c_str(), int(fraction * 100));
        std::fflush(stderr);
    }

    /// A phase without a measurable fraction ("searching for self-intersections").
    void phase(const std::string& what) {
        if (!on_) return;
        shown_ = true;
        std::fprintf(stderr, "\r\033[K%s: %s", label_.c_str(), what.c_str());
        std::fflush(stderr);
    }

private:
    using clock = std::chrono::steady_clock;
    std::string label_;
    bool on_, shown_ = false;
    clock::time_point start_ = process_start, last_{};
};

}  // namespace crspline::cli
