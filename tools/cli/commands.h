#pragma once
#include <CLI/CLI.hpp>

namespace isotrace::cli {

// Each command adds its options to its sub-command (named and described by the command table in main.cpp) and
// returns the function that runs it (exit code).
using CommandRunner = std::function<int()>;

CommandRunner add_render_options(CLI::App* command);
CommandRunner add_info_options(CLI::App* command);
CommandRunner add_depth_options(CLI::App* command);
CommandRunner add_bench_options(CLI::App* command);
CommandRunner add_benchmark_options(CLI::App* command);
CommandRunner add_mesh_options(CLI::App* command);
CommandRunner add_deform_options(CLI::App* command);
CommandRunner add_diff_options(CLI::App* command);

// Exit codes shared by all commands.
constexpr int kExitOk = 0;
constexpr int kExitFailure = 1;     // internal or system error (I/O, Embree)
constexpr int kExitBadInput = 2;    // the user's scene, files or arguments are wrong
// Finished, but the result does not meet what was asked: a reference render that stopped before its target error,
// a diff whose threshold or z-test fails. The outputs are written.
constexpr int kExitNotMet = 3;
// Interrupted by a signal: 128 + the signal number (130 for SIGINT, 143 for SIGTERM), as shells report it.

}  // namespace isotrace::cli
