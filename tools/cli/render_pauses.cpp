#include "tools/cli/render_pauses.h"

#include <algorithm>

namespace isotrace::cli {

void RenderPauses::add(double interval_seconds, Task task) {
    tasks_.push_back({interval_seconds, std::move(task)});
    pause_interval_seconds_ =
        pause_interval_seconds_ > 0 ? std::min(pause_interval_seconds_, interval_seconds) : interval_seconds;
}

void RenderPauses::install(RenderOptions& options) {
    if (tasks_.empty()) return;
    options.checkpoint_interval_seconds = pause_interval_seconds_;
    options.on_checkpoint = [this](const Film& film) { pause(film); };
}

void RenderPauses::pause(const Film& film) {
    // The renderer pauses after every pause_interval_seconds_ of rendering (the time paused does not count). What
    // a run comes late by carries over, so a task keeps its interval on average; a relative slack keeps a task
    // whose interval is a multiple of the pause interval from slipping by one pause through rounding.
    for (Scheduled& scheduled : tasks_) {
        scheduled.seconds_since_run += pause_interval_seconds_;
        if (scheduled.seconds_since_run < scheduled.interval_seconds * (1 - 1e-9)) continue;
        scheduled.seconds_since_run = std::max(0.0, scheduled.seconds_since_run - scheduled.interval_seconds);
        scheduled.task(film);
    }
}

}  // namespace isotrace::cli
