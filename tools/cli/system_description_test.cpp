#include "tools/cli/system_description.h"

#include <gtest/gtest.h>

#include <fstream>

namespace isotrace::cli {
namespace {

TEST(SystemDescription, HasTheTopologyAndVersions) {
    const nlohmann::json system = system_description();
    for (const char* key : {"cpu", "commit", "sockets", "physical_cores", "hardware_threads", "smt", "caches",
                            "memory_bytes", "memory_speed", "clock_mhz", "os", "kernel", "tbb_version", "oiio_version",
                            "ocio_version"})
        EXPECT_TRUE(system.contains(key)) << key;
    // hwloc reads the topology of any Linux machine.
    EXPECT_GE(system["sockets"].get<int>(), 1);
    EXPECT_GE(system["physical_cores"].get<int>(), 1);
    EXPECT_GE(system["hardware_threads"].get<int>(), system["physical_cores"].get<int>());
    // The kernel's total, as /proc/meminfo says it (hwloc's NUMA nodes can hold less in a virtual machine).
    std::ifstream meminfo("/proc/meminfo");
    std::string key;
    std::uint64_t kib = 0;
    meminfo >> key >> kib;
    ASSERT_EQ(key, "MemTotal:");
    EXPECT_EQ(system["memory_bytes"].get<std::uint64_t>(), kib * 1024);
    ASSERT_FALSE(system["caches"].empty());
    EXPECT_GE(system["caches"][0]["bytes"].get<std::uint64_t>(), 1024u);
    EXPECT_NE(system["kernel"].get<std::string>().find("Linux"), std::string::npos);
}

TEST(SystemDescription, OsReleaseValue) {
    const std::string text = "NAME=\"Debian GNU/Linux\"\nPRETTY_NAME=\"Debian GNU/Linux 12 (bookworm)\"\nID=debian\n";
    EXPECT_EQ(os_release_value(text, "PRETTY_NAME"), "Debian GNU/Linux 12 (bookworm)");
    EXPECT_EQ(os_release_value(text, "ID"), "debian");
    EXPECT_EQ(os_release_value(text, "NAME"), "Debian GNU/Linux");
    EXPECT_EQ(os_release_value(text, "VERSION"), "");
}

}  // namespace
}  // namespace isotrace::cli
