#pragma once
// --max-memory for every command that loads input: the limit of the MemoryBudget its input is charged to.
#include <CLI/CLI.hpp>
#include <cstdint>
#include <optional>
#include <string>

#include "tools/cli/command_helpers.h"

namespace isotrace::cli {

inline CLI::Option* add_max_memory_option(CLI::App& command, std::string& limit) {
    return command.add_option("--max-memory", limit,
                              "Refuse input whose memory exceeds this, before taking it: bytes with K/M/G/T, or a "
                              "percentage of physical memory (default: 80%)")
        ->type_name("SIZE");
}

// The limit given, if any (parse_memory_size's rules).
inline std::optional<std::uint64_t> max_memory_bytes(const std::string& limit) {
    if (limit.empty()) return std::nullopt;
    return parse_memory_size(limit, "--max-memory");
}

}  // namespace isotrace::cli
