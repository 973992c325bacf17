#include "renderer/embree/query_scratch_pool.h"

#include <algorithm>
#include <functional>
#include <thread>

namespace isotrace {

std::size_t QueryScratchPool::default_slots() {
    return std::max<std::size_t>(16, 2 * std::size_t(std::thread::hardware_concurrency()));
}

QueryScratchPool::QueryScratchPool(std::size_t slots)
    : slots_(std::make_unique<Slot[]>(std::max<std::size_t>(1, slots))), slot_count_(std::max<std::size_t>(1, slots)) {}

QueryScratchPool::Loan QueryScratchPool::borrow() {
    const std::size_t home = std::hash<std::thread::id>{}(std::this_thread::get_id()) % slot_count_;
    for (std::size_t i = 0; i < slot_count_; ++i) {
        const std::size_t index = (home + i) % slot_count_;
        Slot& slot = slots_[index];
        // Reading first: a slot another thread holds is passed over without writing to its cache line.
        if (slot.lent.load(std::memory_order_relaxed) || slot.lent.exchange(true, std::memory_order_acquire)) continue;
        if (!slot.scratch) slot.scratch = std::make_unique<QueryScratch>();
        return {slot.scratch.get(), index};
    }
    return {new QueryScratch(), kNoSlot};
}

void QueryScratchPool::give_back(const Loan& loan) {
    if (loan.slot == kNoSlot) {
        delete loan.scratch;
        return;
    }
    slots_[loan.slot].lent.store(false, std::memory_order_release);
}

}  // namespace isotrace
