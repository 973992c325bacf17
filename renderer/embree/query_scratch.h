#pragma once
// QueryScratch: the buffers one ray query reuses (the crossings and span lists of the solids it asks), kept
// between queries so that a query allocates nothing once they have grown. A solid that asks other solids, as CSG
// does, must keep its own buffers while they fill theirs: every call that needs buffers takes a Level, the next
// one down a stack the query owns, and gives it back when it returns. Not shared: one query at a time.
#include <cstddef>
#include <memory>
#include <vector>

namespace isotrace {

class QueryScratch {
public:
    // The buffers of one call: taken on construction, given back on destruction.
    class Level {
    public:
        explicit Level(QueryScratch& scratch);
        ~Level() { --scratch_.depth_; }
        Level(const Level&) = delete;
        Level& operator=(const Level&) = delete;

        // This level's buffers of type Buffers: default-constructed on first use, afterwards as the last call at
        // this depth left them (cleared by the caller, their capacity kept).
        template <class Buffers>
        Buffers& get() const {
            std::vector<Slot>& slots = scratch_.levels_[depth_];
            for (const Slot& slot : slots)
                if (slot.type == &type_key<Buffers>) return *static_cast<Buffers*>(slot.buffers.get());
            slots.push_back({&type_key<Buffers>, Erased(new Buffers(), [](void* p) { delete static_cast<Buffers*>(p); })});
            return *static_cast<Buffers*>(slots.back().buffers.get());
        }

    private:
        QueryScratch& scratch_;
        std::size_t depth_;  // an index, not a reference: deeper levels may reallocate the stack
    };

    // Levels taken now (0 between queries).
    std::size_t depth() const { return depth_; }

private:
    // Distinct for every type: the buffers' identity without RTTI.
    template <class Buffers>
    static constexpr char type_key = 0;

    using Erased = std::unique_ptr<void, void (*)(void*)>;
    struct Slot {
        const void* type;
        Erased buffers;  // a Buffers, on the heap so that references to it survive the slot list growing
    };

    std::vector<std::vector<Slot>> levels_;
    std::size_t depth_ = 0;
};

}  // namespace isotrace
