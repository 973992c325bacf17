#pragma once
// The QueryScratch of a scene's queries: lent to a query for its duration and kept afterwards, one for every query
// that ran at the same moment as others, so that buffers grow once per concurrent query rather than once per query.
// Lending takes no lock: the scratches sit in slots, each with a flag that one atomic exchange takes, and a thread
// looks first at a slot of its own (by a hash of its id), so that on many cores the queries of different threads
// touch different cache lines rather than one shared lock.
#include <atomic>
#include <cstddef>
#include <memory>

#include "renderer/embree/query_scratch.h"

namespace isotrace {

class QueryScratchPool {
public:
    // Where a lent scratch came from, so that giving it back is one store.
    struct Loan {
        QueryScratch* scratch = nullptr;
        std::size_t slot = 0;  // kNoSlot: made for this loan alone, every slot being lent
    };
    static constexpr std::size_t kNoSlot = static_cast<std::size_t>(-1);

    // `slots` scratches at most are kept; by default twice the hardware threads (at least 16), so that a query
    // finds one without a search and every thread of the machine has one.
    explicit QueryScratchPool(std::size_t slots = default_slots());
    QueryScratchPool(const QueryScratchPool&) = delete;
    QueryScratchPool& operator=(const QueryScratchPool&) = delete;

    // An idle scratch (the thread's own slot's when idle), made on first use; a scratch of its own when every slot
    // is lent (more concurrent queries than slots), dropped when given back.
    Loan borrow();
    // The loan's scratch is idle again.
    void give_back(const Loan& loan);

    static std::size_t default_slots();

private:
    // A cache line each: the flags of different threads' slots do not share one.
    struct alignas(64) Slot {
        std::atomic<bool> lent{false};
        std::unique_ptr<QueryScratch> scratch;  // touched only by the slot's borrower
    };
    std::unique_ptr<Slot[]> slots_;
    std::size_t slot_count_;
};

}  // namespace isotrace
