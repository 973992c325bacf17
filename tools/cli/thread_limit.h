#pragma once
// --threads for the commands that run in parallel: 0 means all cores, N at most N oneTBB workers.
#include <tbb/global_control.h>
#include <tbb/info.h>

#include <CLI/CLI.hpp>
#include <cstddef>

namespace isotrace::cli {

inline CLI::Option* add_threads_option(CLI::App& command, int& threads) {
    return command.add_option("--threads", threads, "Worker threads (0 = all cores)")->check(CLI::Range(0, 4096));
}

// Caps oneTBB at the requested number of threads for as long as it lives.
class ThreadLimit {
public:
    explicit ThreadLimit(int requested)
        : threads_(requested > 0 ? requested : tbb::info::default_concurrency()),
          control_(tbb::global_control::max_allowed_parallelism, std::size_t(threads_)) {}
    int threads() const { return threads_; }

private:
    int threads_;
    tbb::global_control control_;
};

}  // namespace isotrace::cli
