#include "tools/cli/machine_description.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <array>
#include <fstream>
#include <set>
#include <sstream>
#include <thread>

#include "geometry/implicit/blob_cell_queries.h"
#include "renderer/core/version.h"
#include "renderer/embree/embree_device.h"
#include "tools/cli/build_description.h"

namespace isotrace::cli {
namespace {

// The value of the first /proc/cpuinfo line starting with `key`; empty if none.
std::string cpuinfo_value(const std::string& key) {
    std::ifstream cpuinfo("/proc/cpuinfo");
    std::string line;
    while (std::getline(cpuinfo, line))
        if (line.rfind(key, 0) == 0) {
            const std::size_t colon = line.find(':');
            if (colon == std::string::npos) return "";
            const std::size_t start = line.find_first_not_of(' ', colon + 1);
            return start == std::string::npos ? "" : line.substr(start);
        }
    return "";
}

std::string native_packets() {
    const RTCDevice device = embree_device();
    std::string widths;
    for (const auto& [property, width] : {std::pair{RTC_DEVICE_PROPERTY_NATIVE_RAY4_SUPPORTED, "4"},
                                          std::pair{RTC_DEVICE_PROPERTY_NATIVE_RAY8_SUPPORTED, "8"},
                                          std::pair{RTC_DEVICE_PROPERTY_NATIVE_RAY16_SUPPORTED, "16"}})
        if (rtcGetDeviceProperty(device, property)) {
            if (!widths.empty()) widths += ',';
            widths += width;
        }
    return widths.empty() ? "none" : widths;
}

}  // namespace

std::string cpu_model() {
    const std::string model = cpuinfo_value("model name");
    return model.empty() ? "unknown" : model;
}

namespace {

// Embree's instruction sets, narrowest first.
constexpr std::array<std::string_view, 5> kEmbreeIsas = {"SSE2", "SSE4.2", "AVX", "AVX2", "AVX512SKX"};

const std::string_view* rank_of(std::string_view isa) { return std::find(kEmbreeIsas.begin(), kEmbreeIsas.end(), isa); }

}  // namespace

std::string isa_from_cpu_flags(const std::string& flags) {
    std::set<std::string> present;
    std::istringstream words(flags);
    for (std::string word; words >> word;) present.insert(word);
    const auto all = [&present](std::initializer_list<const char*> names) {
        for (const char* name : names)
            if (!present.count(name)) return false;
        return true;
    };
    if (all({"avx512f", "avx512dq", "avx512cd", "avx512bw", "avx512vl"})) return "AVX512SKX";
    if (all({"avx2", "fma", "bmi1", "bmi2", "lzcnt"}) || all({"avx2", "fma", "bmi1", "bmi2", "abm"})) return "AVX2";
    if (all({"avx"})) return "AVX";
    if (all({"sse4_2"})) return "SSE4.2";
    if (all({"sse2"})) return "SSE2";
    return "unknown";
}

std::string embree_isa() {
    const std::string best = isa_from_cpu_flags(cpuinfo_value("flags"));
    return rank_of(best) != kEmbreeIsas.end() && rank_of(best) > rank_of(kEmbreeIsaCap) ? std::string(kEmbreeIsaCap)
                                                                                          : best;
}

bool embree_isa_before_avx2(std::string_view isa) {
    return rank_of(isa) != kEmbreeIsas.end() && rank_of(isa) < rank_of("AVX2");
}

nlohmann::json machine_description() {
    const BuildDescription build = build_description();
    const RTCDevice device = embree_device();
    return {{"cpu", cpu_model()},
            {"cores", std::thread::hardware_concurrency()},
            {"embree_isa", embree_isa()},
            {"embree_native_packets", native_packets()},
            {"blob_march_isa", blob_cell_queries().isa},
            {"embree_version", std::to_string(rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_VERSION_MAJOR)) + "." +
                                   std::to_string(rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_VERSION_MINOR)) +
                                   "." +
                                   std::to_string(rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_VERSION_PATCH))},
            {"compiler", build.compiler},
            {"flags", build.flags},
            {"build_type", build.build_type},
            {"isotrace_version", kIsotraceVersion},
            {"commit", build.commit}};
}

}  // namespace isotrace::cli
