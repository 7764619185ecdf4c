// crspline command line: output written as it is computed. See output_stream.hpp.
#include "output_stream.hpp"

#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "json_input.hpp"

namespace crspline::cli {

double round_to_precision(double x, int precision) {
    if (precision <= 0 || precision >= 17 || !std::isfinite(x)) return x;
    std::array<char, 40> buf;
    std::snprintf(buf.data(), buf.size(), "%.*e", precision - 1, x);
    return std::strtod(buf.data(), nullptr);
}

void append_number(std::string& s, double x, const number_format& f) {
    std::array<char, 32> buf;
    const auto r = std::to_chars(buf.data(), buf.data() + buf.size(), round_to_precision(x, f.precision));
    s.append(buf.data(), r.ptr);
}

void append_json_number(std::string& s, double x, const number_format& f) {
    // nlohmann::json's layout of the shortest digits d1..dk with the decimal
    // point after position n: dddd.0 for k <= n <= 15, dd.dd for 0 < n <= 15,
    // 0.000ddd for -4 < n <= 0, else d.ddde+XX (at least two exponent digits).
    x = round_to_precision(x, f.precision);
    if (x == 0) {
        s += std::signbit(x) ? "-0.0" : "0.0";
        return;
    }
    std::array<char, 40> buf;
    const auto r = std::to_chars(buf.data(), buf.data() + buf.size(), x, std::chars_format::scientific);
    std::string_view sci(buf.data(), std::size_t(r.ptr - buf.data()));
    if (sci.front() == '-') {
        s += '-';
        sci.remove_prefix(1);
    }
    const std::size_t e = sci.find('e');
    std::string digits;
    for (char c : sci.substr(0, e))
        if (c != '.') digits += c;
    const int k = int(digits.size());
    const int n = std::atoi(std::string(sci.substr(e + 1)).c_str()) + 1;
    if (k <= n && n <= 15) {
        s += digits;
        s.append(std::size_t(n - k), '0');
        s += ".0";
    } else if (0 < n && n <= 15) {
        s.append(digits, 0, std::size_t(n));
        s += '.';
        s.append(digits, std::size_t(n));
    } else if (-4 < n && n <= 0) {
        s += "0.";
        s.append(std::size_t(-n), '0');
        s += digits;
    } else {
        s += digits[0];
        if (k > 1) {
            s += '.';
            s.append(digits, 1);
        }
        const int ex = n - 1;
        s += ex < 0 ? "e-" : "e+";
        const int a = std::abs(ex);
        if (a < 10) s += '0';
        s += std::to_string(a);
    }
}

output_stream::output_stream(std::string path) : path_(std::move(path)), to_stdout_(path_.empty() || path_ == "-") {}

output_stream::~output_stream() {
    if (fd_ >= 0) ::close(fd_);
    if (!committed_ && !tmp_.empty()) ::unlink(tmp_.c_str());
}

void output_stream::fail(int err) {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
    if (!tmp_.empty()) ::unlink(tmp_.c_str());
    tmp_.clear();
    throw input_error((to_stdout_ ? std::string("<stdout>") : path_) + ": cannot write: " + std::strerror(err));
}

void output_stream::flush() {
    started_ = true;
    int fd = STDOUT_FILENO;
    if (!to_stdout_) {
        if (fd_ < 0 && !direct_) {
            // A device or a pipe (/dev/null, /dev/stdout, a FIFO) is written
            // directly: there is no file to replace.
            struct stat st;
            if (::stat(path_.c_str(), &st) == 0 && !S_ISREG(st.st_mode) && !S_ISDIR(st.st_mode)) {
                direct_ = true;
                fd_ = ::open(path_.c_str(), O_WRONLY | O_CLOEXEC);
                if (fd_ < 0) fail(errno);
            }
        }
        if (fd_ < 0) {
            // A temporary file next to the target, renamed over it when complete.
            const std::filesystem::path target(path_);
            const std::filesystem::path dir = target.has_parent_path() ? target.parent_path() : std::filesystem::path(".");
            tmp_ = (dir / ("." + target.filename().string() + ".tmp-XXXXXX")).string();
            fd_ = ::mkstemp(tmp_.data());
            if (fd_ < 0) {
                const int err = errno;
                tmp_.clear();
                fail(err);
            }
        }
        fd = fd_;
    }
    std::size_t done = 0;
    while (done < buf_.size()) {
        const ssize_t w = ::write(fd, buf_.data() + done, buf_.size() - done);
        if (w < 0) {
            if (errno == EINTR) continue;
            fail(errno);
        }
        done += std::size_t(w);
    }
    buf_.clear();
}

void output_stream::not_finite(const std::string& where) {
    throw input_error(where + ": the result is not finite (the input's coordinates or knot intervals are too "
                              "extreme for double arithmetic)");
}

void output_stream::commit() {
    if (in_memory_) return;
    flush();
    committed_ = true;
    if (to_stdout_) return;
    if (direct_) {
        const int fd = fd_;
        fd_ = -1;
        if (::close(fd) != 0) fail(errno);
        return;
    }
    ::fchmod(fd_, 0644);
    const int fd = fd_;
    fd_ = -1;
    if (::close(fd) != 0) {
        committed_ = false;
        fail(errno);
    }
    if (std::rename(tmp_.c_str(), path_.c_str()) != 0) {
        committed_ = false;
        fail(errno);
    }
}

}  // namespace crspline::cli
