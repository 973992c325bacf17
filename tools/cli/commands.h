#pragma once
#include <CLI/CLI.hpp>

namespace isotrace::cli {

// Each sub-command adds itself to the application and returns the function that runs it (exit code).
using CommandRunner = std::function<int()>;

CommandRunner add_render_command(CLI::App& app);
CommandRunner add_info_command(CLI::App& app);
CommandRunner add_depth_command(CLI::App& app);
CommandRunner add_bench_command(CLI::App& app);
CommandRunner add_mesh_command(CLI::App& app);
CommandRunner add_deform_command(CLI::App& app);
CommandRunner add_diff_command(CLI::App& app);

// Exit codes shared by all commands.
constexpr int kExitOk = 0;
constexpr int kExitFailure = 1;     // internal or system error (I/O, Embree)
constexpr int kExitBadInput = 2;    // the user's scene, files or arguments are wrong
// Finished, but the result does not meet what was asked: a reference render that stopped before its target error,
// a diff whose threshold or z-test fails. The outputs are written.
constexpr int kExitNotMet = 3;
// Interrupted by a signal: 128 + the signal number (130 for SIGINT, 143 for SIGTERM), as shells report it.

}  // namespace isotrace::cli
