#include "renderer/embree/query_scratch_pool.h"

namespace isotrace {

QueryScratch& QueryScratchPool::borrow() {
    const std::lock_guard lock(mutex_);
    if (idle_.empty()) {
        all_.push_back(std::make_unique<QueryScratch>());
        idle_.reserve(all_.size());
        return *all_.back();
    }
    QueryScratch& scratch = *idle_.back();
    idle_.pop_back();
    return scratch;
}

void QueryScratchPool::give_back(QueryScratch& scratch) {
    const std::lock_guard lock(mutex_);
    idle_.push_back(&scratch);
}

}  // namespace isotrace
