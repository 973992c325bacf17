#include "tools/cli/progress_bar.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>

namespace isotrace::cli {

bool stderr_is_terminal() { return ::isatty(STDERR_FILENO) == 1; }

std::string format_duration(double seconds) {
    if (!(seconds >= 0) || !std::isfinite(seconds)) return "--:--";
    const long total = std::lround(seconds);
    char text[32];
    if (total >= 3600) std::snprintf(text, sizeof text, "%ld:%02ld:%02ld", total / 3600, total / 60 % 60, total % 60);
    else std::snprintf(text, sizeof text, "%02ld:%02ld", total / 60, total % 60);
    return text;
}

void ProgressBar::update(const RenderProgress& progress) {
    if (!enabled_) return;
    constexpr int kWidth = 30;
    const int filled = std::clamp(int(progress.fraction * kWidth), 0, kWidth);
    const std::string bar = std::string(std::size_t(filled), '#') + std::string(std::size_t(kWidth - filled), '.');
    const double mrays = progress.elapsed_seconds > 0 ? progress.rays / progress.elapsed_seconds * 1e-6 : 0;
    std::fprintf(stderr, "\r[%s] %5.1f%%  %s elapsed  ETA %s  %.2f Mrays/s  %d spp done\x1b[K", bar.c_str(),
                 progress.fraction * 100, format_duration(progress.elapsed_seconds).c_str(),
                 format_duration(progress.eta_seconds).c_str(), mrays, progress.completed_spp);
    std::fflush(stderr);
    drawn_ = true;
}

void ProgressBar::finish() {
    if (drawn_) std::fputc('\n', stderr);
    drawn_ = false;
}

}  // namespace isotrace::cli
