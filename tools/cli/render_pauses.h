#pragma once
// The tasks a render pauses for (RenderOptions::on_checkpoint: the film is consistent, no sample in flight):
// checkpoints (--checkpoint-every) and interim outputs (--write-every), each at its own interval of rendering
// time. The render pauses at the shortest interval; each pause runs the tasks whose interval has passed since
// they last ran.
#include <functional>
#include <vector>

#include "renderer/film/film.h"
#include "renderer/render/tile_renderer.h"

namespace isotrace::cli {

class RenderPauses {
public:
    using Task = std::function<void(const Film&)>;

    // `interval_seconds` > 0 of rendering between runs of `task`.
    void add(double interval_seconds, Task task);

    // Makes `options` pause for the tasks (nothing when there are none). This object must outlive the render.
    void install(RenderOptions& options);

    // One pause: the tasks that are due run, in the order they were added.
    void pause(const Film& film);

private:
    struct Scheduled {
        double interval_seconds;
        Task task;
        double seconds_since_run = 0;
    };
    std::vector<Scheduled> tasks_;
    double pause_interval_seconds_ = 0;
};

}  // namespace isotrace::cli
