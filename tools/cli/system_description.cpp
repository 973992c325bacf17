#include "tools/cli/system_description.h"

#include <hwloc.h>
#include <oneapi/tbb/version.h>
#include <sys/utsname.h>
#include <unistd.h>
// Version macros only: the benchmark reads no images through OpenImageIO in this process's own code, and the image
// module it loads is built against the same Debian package.
#include <OpenColorIO/OpenColorABI.h>
#include <OpenImageIO/oiioversion.h>

#include <fstream>
#include <map>
#include <sstream>

#include "tools/cli/machine_description.h"

namespace isotrace::cli {
namespace {

// A /sys file's number, in kHz for cpufreq; null when unreadable.
nlohmann::json sys_megahertz(const std::string& file) {
    std::ifstream in(file);
    double khz = 0;
    if (!(in >> khz) || khz <= 0) return nullptr;
    return khz / 1000;
}

nlohmann::json current_megahertz() {
    std::ifstream cpuinfo("/proc/cpuinfo");
    for (std::string line; std::getline(cpuinfo, line);)
        if (line.rfind("cpu MHz", 0) == 0 && line.find(':') != std::string::npos) {
            try {
                return std::stod(line.substr(line.find(':') + 1));
            } catch (const std::exception&) {
                return nullptr;
            }
        }
    return nullptr;
}

std::string file_text(const std::string& path) {
    std::ifstream in(path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

class Topology {
public:
    Topology() {
        if (hwloc_topology_init(&topology_) != 0) return;
        loaded_ = hwloc_topology_load(topology_) == 0;
    }
    ~Topology() {
        if (topology_) hwloc_topology_destroy(topology_);
    }
    Topology(const Topology&) = delete;
    Topology& operator=(const Topology&) = delete;

    nlohmann::json count(hwloc_obj_type_t type) const {
        if (!loaded_) return nullptr;
        const int n = hwloc_get_nbobjs_by_type(topology_, type);
        return n > 0 ? nlohmann::json(n) : nlohmann::json();
    }

    nlohmann::json caches() const {
        nlohmann::json list = nlohmann::json::array();
        if (!loaded_) return list;
        // Sizes per level and type: {"level", "type", "bytes" of one cache, "count" of them}.
        std::map<std::pair<unsigned, std::string>, std::pair<std::uint64_t, int>> found;
        const int depth = hwloc_topology_get_depth(topology_);
        for (int d = 0; d < depth; ++d) {
            const hwloc_obj_type_t type = hwloc_get_depth_type(topology_, d);
            if (!hwloc_obj_type_is_cache(type)) continue;
            for (unsigned i = 0; i < hwloc_get_nbobjs_by_depth(topology_, d); ++i) {
                const hwloc_obj_t obj = hwloc_get_obj_by_depth(topology_, d, i);
                const char* kind = obj->attr->cache.type == HWLOC_OBJ_CACHE_DATA          ? "data"
                                   : obj->attr->cache.type == HWLOC_OBJ_CACHE_INSTRUCTION ? "instruction"
                                                                                          : "unified";
                auto& entry = found[{obj->attr->cache.depth, kind}];
                entry.first = obj->attr->cache.size;
                ++entry.second;
            }
        }
        for (const auto& [key, value] : found)
            list.push_back({{"level", key.first}, {"type", key.second}, {"bytes", value.first}, {"count", value.second}});
        return list;
    }

private:
    hwloc_topology_t topology_ = nullptr;
    bool loaded_ = false;
};

}  // namespace

std::string os_release_value(const std::string& text, const std::string& key) {
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);)
        if (line.rfind(key + "=", 0) == 0) {
            std::string value = line.substr(key.size() + 1);
            if (value.size() >= 2 && (value.front() == '"' || value.front() == '\'') && value.back() == value.front())
                value = value.substr(1, value.size() - 2);
            return value;
        }
    return "";
}

nlohmann::json system_description() {
    nlohmann::json system = machine_description();
    const Topology topology;
    system["sockets"] = topology.count(HWLOC_OBJ_PACKAGE);
    system["physical_cores"] = topology.count(HWLOC_OBJ_CORE);
    system["hardware_threads"] = topology.count(HWLOC_OBJ_PU);
    system["smt"] = system["physical_cores"].is_number() && system["hardware_threads"].is_number()
                        ? nlohmann::json(system["hardware_threads"].get<int>() > system["physical_cores"].get<int>())
                        : nlohmann::json();
    system["caches"] = topology.caches();
    // The kernel's figure (as /proc/meminfo's MemTotal): hwloc sums its NUMA nodes, which some virtual machines
    // describe with less memory than they have.
    const long pages = sysconf(_SC_PHYS_PAGES), page_bytes = sysconf(_SC_PAGE_SIZE);
    system["memory_bytes"] = pages > 0 && page_bytes > 0 ? nlohmann::json(std::uint64_t(pages) * std::uint64_t(page_bytes))
                                                         : nlohmann::json();
    system["memory_speed"] = nullptr;  // only the SMBIOS tables say it, and they need root (dmidecode)
    const std::string cpufreq = "/sys/devices/system/cpu/cpu0/cpufreq/";
    system["clock_mhz"] = {{"base", sys_megahertz(cpufreq + "base_frequency")},
                           {"min", sys_megahertz(cpufreq + "cpuinfo_min_freq")},
                           {"max", sys_megahertz(cpufreq + "cpuinfo_max_freq")},
                           {"current", current_megahertz()}};
    const std::string os = os_release_value(file_text("/etc/os-release"), "PRETTY_NAME");
    system["os"] = os.empty() ? "unknown" : os;
    utsname name{};
    system["kernel"] = uname(&name) == 0 ? std::string(name.sysname) + " " + name.release + " " + name.machine
                                         : std::string("unknown");
    system["tbb_version"] = TBB_runtime_version();
    system["oiio_version"] = OIIO_VERSION_STRING;
    system["ocio_version"] = OCIO_VERSION;
    return system;
}

}  // namespace isotrace::cli
