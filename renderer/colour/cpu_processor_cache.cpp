#include "renderer/colour/cpu_processor_cache.h"

#include <mutex>

namespace isotrace {

OCIO_NAMESPACE::ConstCPUProcessorRcPtr CpuProcessorCache::get(const Key& key, const Builder& build) const {
    {
        std::shared_lock reading(mutex_);
        if (auto found = processors_.find(key); found != processors_.end()) return found->second;
    }
    std::unique_lock writing(mutex_);
    // Another thread may have built it while we waited for the exclusive lock.
    if (auto found = processors_.find(key); found != processors_.end()) return found->second;
    return processors_.emplace(key, build()).first->second;
}

}  // namespace isotrace
