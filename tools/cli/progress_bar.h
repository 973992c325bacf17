#pragma once
#include <cstdio>
#include <string>
#include <vector>

#include "renderer/render/tile_renderer.h"

namespace isotrace::cli {

// One-line progress bar with ETA (or the time budget) and Mrays/s, redrawn in place on a terminal and fitted to
// its width. Silent when disabled. The renderer's last report is 100 % for a render that finished.
class ProgressBar {
public:
    explicit ProgressBar(bool enabled) : enabled_(enabled) {}
    void update(const RenderProgress& progress);
    void draw(const std::string& line);  // any line, e.g. from format_progress
    void finish();  // ends the line

private:
    bool enabled_;
    bool drawn_ = false;
};

// True when stderr is an interactive terminal.
bool stderr_is_terminal();

std::string format_duration(double seconds);

// The line the bar draws, at most columns - 1 characters: the bar shrinks, then the least important parts go.
std::string format_progress_line(const RenderProgress& progress, int columns);

// A bar, the percentage and then `details` in order of importance, at most columns - 1 characters: the bar
// shrinks, then the last details go.
std::string format_progress(double fraction, const std::vector<std::string>& details, int columns);

// Width of the terminal on stderr (80 when unknown).
int terminal_columns();

}  // namespace isotrace::cli
