#include "renderer/embree/embree_device.h"

#include <pmmintrin.h>
#include <xmmintrin.h>

#include <cctype>
#include <mutex>
#include <stdexcept>

namespace isotrace {
namespace {

std::atomic<std::int64_t> g_bytes_in_use{0};
std::mutex g_error_mutex;
std::string g_last_error;

void record_error(void*, RTCError code, const char* message) {
    std::lock_guard lock(g_error_mutex);
    if (g_last_error.empty())
        g_last_error = std::string("Embree error ") + std::to_string(int(code)) + ": " + (message ? message : "");
}

bool track_memory(void*, ssize_t bytes, bool) {
    g_bytes_in_use += bytes;
    return true;
}

}  // namespace

RTCDevice embree_device() {
    // Created once and deliberately kept for the life of the process: Embree objects may outlive any owner.
    static const RTCDevice device = [] {
        std::string config = "verbose=0,max_isa=";
        for (const char c : kEmbreeIsaCap) config += char(std::tolower(static_cast<unsigned char>(c)));
        RTCDevice created = rtcNewDevice(config.c_str());
        if (!created) throw std::runtime_error("cannot create the Embree device");
        rtcSetDeviceErrorFunction(created, record_error, nullptr);
        rtcSetDeviceMemoryMonitorFunction(created, track_memory, nullptr);
        return created;
    }();
    return device;
}

void check_embree(const std::string& what) {
    std::lock_guard lock(g_error_mutex);
    if (g_last_error.empty()) return;
    const std::string message = what + ": " + g_last_error;
    g_last_error.clear();
    throw std::runtime_error(message);
}

std::int64_t embree_bytes_in_use() { return g_bytes_in_use.load(); }

void enable_flush_to_zero() {
    _MM_SET_FLUSH_ZERO_MODE(_MM_FLUSH_ZERO_ON);
    _MM_SET_DENORMALS_ZERO_MODE(_MM_DENORMALS_ZERO_ON);
}

}  // namespace isotrace
