#pragma once
// Thread-safe memo of OCIO CPU processors: building one (optimising and finalising the transform
// chain) costs far more than applying it, and the same few conversions are requested many times.
#include <OpenColorIO/OpenColorIO.h>

#include <functional>
#include <map>
#include <shared_mutex>
#include <string>
#include <utility>

namespace isotrace {

class CpuProcessorCache {
public:
    // (from, to) names a conversion; `build` runs only the first time that pair is requested.
    using Key = std::pair<std::string, std::string>;
    using Builder = std::function<OCIO_NAMESPACE::ConstCPUProcessorRcPtr()>;

    OCIO_NAMESPACE::ConstCPUProcessorRcPtr get(const Key& key, const Builder& build) const;

private:
    mutable std::shared_mutex mutex_;
    mutable std::map<Key, OCIO_NAMESPACE::ConstCPUProcessorRcPtr> processors_;
};

}  // namespace isotrace
