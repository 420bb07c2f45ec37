#include "cli/ProgressLine.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <iostream>

namespace dropscope {

namespace {

constexpr double kQuietSeconds = 1.0;  // runs shorter than this show no progress at all

std::string formatDuration(double seconds) {
    const auto whole = static_cast<long long>(std::ceil(seconds));
    char text[48];
    if (whole < 60) {
        std::snprintf(text, sizeof text, "%lld s", whole);
    } else if (whole < 3600) {
        std::snprintf(text, sizeof text, "%lld min %02lld s", whole / 60, whole % 60);
    } else {
        std::snprintf(text, sizeof text, "%lld h %02lld min", whole / 3600, whole / 60 % 60);
    }
    return text;
}

}  // namespace

std::string formatProgress(const TraceProgress& progress) {
    const double done = static_cast<double>(progress.done);
    const double total = static_cast<double>(progress.total);
    const double rate = progress.seconds > 0.0 ? done / progress.seconds : 0.0;
    const std::string left = rate > 0.0 ? formatDuration((total - done) / rate) + " left" : "time left unknown";
    char text[160];
    std::snprintf(text, sizeof text, "trace: %llu / %llu photons (%.1f%%), %.0f photons/s, %s",
                  static_cast<unsigned long long>(progress.done), static_cast<unsigned long long>(progress.total),
                  total > 0.0 ? 100.0 * done / total : 0.0, rate, left.c_str());
    return text;
}

void ProgressLine::update(const TraceProgress& progress) {
    if (progress.seconds < kQuietSeconds) return;
    if (style_ == Style::Lines && shown_ && progress.seconds - lastShown_ < kLineSeconds) return;
    show(progress);
}

void ProgressLine::finish(const TraceProgress& progress) {
    if (!shown_) return;
    show(progress);
    if (style_ == Style::InPlace) terminal_ << '\n' << std::flush;
}

void ProgressLine::show(const TraceProgress& progress) {
    const std::string line = formatProgress(progress);
    if (style_ == Style::Lines) {
        terminal_ << line << '\n' << std::flush;
        lastShown_ = progress.seconds;
        shown_ = true;
        return;
    }
    terminal_ << '\r' << line;
    if (line.size() < width_) terminal_ << std::string(width_ - line.size(), ' ');
    terminal_ << std::flush;
    width_ = line.size();
    shown_ = true;
}

bool isTerminal(const std::ostream& err) { return err.rdbuf() == std::cerr.rdbuf() && ::isatty(STDERR_FILENO) == 1; }

}  // namespace dropscope
