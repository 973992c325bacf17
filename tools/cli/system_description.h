#pragma once
// The system facts of an isotrace benchmark result: machine_description() (CPU, ISA, compiler, commit), the
// topology from hwloc (sockets, cores, hardware threads, SMT, caches), the memory size, clocks where /sys or /proc
// tell them, the operating system and kernel, and the versions of the libraries the work runs on.
#include <nlohmann/json.hpp>

#include <string>

namespace isotrace::cli {

// machine_description()'s fields and {"sockets", "physical_cores", "hardware_threads", "smt", "caches":
// [{"level", "type", "bytes", "count"}], "memory_bytes", "memory_speed", "clock_mhz": {"base", "min", "max",
// "current"}, "os", "kernel", "tbb_version", "oiio_version", "ocio_version"}. A fact that cannot be read without
// privileges (memory speed) or is not offered (clocks in many virtual machines) is null.
nlohmann::json system_description();

// The value of KEY="value" or KEY=value in an os-release file's text; empty when absent.
std::string os_release_value(const std::string& text, const std::string& key);

}  // namespace isotrace::cli
