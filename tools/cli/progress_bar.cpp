#include "tools/cli/progress_bar.h"

#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>

namespace isotrace::cli {

bool stderr_is_terminal() { return ::isatty(STDERR_FILENO) == 1; }

int terminal_columns() {
    winsize size{};
    if (::ioctl(STDERR_FILENO, TIOCGWINSZ, &size) == 0 && size.ws_col > 0) return size.ws_col;
    return 80;
}

std::string format_duration(double seconds) {
    if (!(seconds >= 0) || !std::isfinite(seconds)) return "--:--";
    const long total = std::lround(seconds);
    char text[32];
    if (total >= 3600) std::snprintf(text, sizeof text, "%ld:%02ld:%02ld", total / 3600, total / 60 % 60, total % 60);
    else std::snprintf(text, sizeof text, "%02ld:%02ld", total / 60, total % 60);
    return text;
}

std::string format_progress_line(const RenderProgress& progress, int columns) {
    const double mrays = progress.elapsed_seconds > 0 ? progress.rays / progress.elapsed_seconds * 1e-6 : 0;
    char speed[32];
    std::snprintf(speed, sizeof speed, "%.2f Mrays/s", mrays);
    // With a time budget the budget is the plan: show the clock against it, not an unbounded sample count.
    const std::string time = progress.time_budget_seconds
                                 ? format_duration(progress.elapsed_seconds) + " of " +
                                       format_duration(*progress.time_budget_seconds) + " budget"
                                 : format_duration(progress.elapsed_seconds) + " elapsed  ETA " +
                                       format_duration(progress.eta_seconds);
    return format_progress(progress.fraction, {time, std::to_string(progress.completed_spp) + " spp done", speed},
                           columns);
}

std::string format_progress(double fraction, const std::vector<std::string>& details, int columns) {
    fraction = std::clamp(fraction, 0.0, 1.0);
    char percent[16];
    std::snprintf(percent, sizeof percent, "%5.1f%%", fraction * 100);
    std::vector<std::string> parts = {percent};
    parts.insert(parts.end(), details.begin(), details.end());
    constexpr int kMaxBar = 30, kMinBar = 10;
    const int usable = std::max(1, columns - 1);  // the last column would wrap on some terminals
    std::size_t shown = parts.size();
    const auto text_width = [&](std::size_t n) {
        int width = 0;
        for (std::size_t i = 0; i < n; ++i) width += 2 + int(parts[i].size());
        return width;
    };
    while (shown > 1 && text_width(shown) + kMinBar + 2 > usable) --shown;
    std::string line;
    const int bar = std::min(kMaxBar, usable - text_width(shown) - 2);
    if (bar >= kMinBar) {
        const int filled = std::clamp(int(fraction * bar), 0, bar);
        line += '[';
        line.append(std::size_t(filled), '#');
        line.append(std::size_t(bar - filled), '.');
        line += ']';
    }
    for (std::size_t i = 0; i < shown; ++i) line += (line.empty() ? "" : "  ") + parts[i];
    if (int(line.size()) > usable) line.resize(std::size_t(usable));
    return line;
}

void ProgressBar::draw(const std::string& line) {
    if (!enabled_) return;
    std::fprintf(stderr, "\r%s\x1b[K", line.c_str());
    std::fflush(stderr);
    drawn_ = true;
}

void ProgressBar::update(const RenderProgress& progress) {
    if (enabled_) draw(format_progress_line(progress, terminal_columns()));
}

void ProgressBar::finish() {
    if (drawn_) std::fputc('\n', stderr);
    drawn_ = false;
}

}  // namespace isotrace::cli
