#pragma once
#include <cstdio>
#include <string>

#include "renderer/render/tile_renderer.h"

namespace isotrace::cli {

// One-line progress bar with ETA and Mrays/s, redrawn in place on a terminal. Silent when disabled.
class ProgressBar {
public:
    explicit ProgressBar(bool enabled) : enabled_(enabled) {}
    void update(const RenderProgress& progress);
    void finish();  // ends the line

private:
    bool enabled_;
    bool drawn_ = false;
};

// True when stderr is an interactive terminal.
bool stderr_is_terminal();

std::string format_duration(double seconds);

}  // namespace isotrace::cli
