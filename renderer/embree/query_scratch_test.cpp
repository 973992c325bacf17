// QueryScratch: a level's buffers are its own while deeper levels are taken, and are the same buffers (capacity
// kept) the next time a call takes that level; QueryScratchPool lends a scratch to one borrower at a time.
#include "renderer/embree/query_scratch.h"

#include <gtest/gtest.h>

#include <vector>

#include "renderer/embree/query_scratch_pool.h"

namespace isotrace {
namespace {

struct TwoLists {
    std::vector<int> a, b;
};

TEST(QueryScratch, NestedLevelsHaveBuffersOfTheirOwn) {
    QueryScratch scratch;
    const QueryScratch::Level outer(scratch);
    std::vector<int>& outer_list = outer.get<std::vector<int>>();
    outer_list = {1, 2, 3};
    {
        const QueryScratch::Level inner(scratch);
        EXPECT_EQ(scratch.depth(), 2u);
        std::vector<int>& inner_list = inner.get<std::vector<int>>();
        EXPECT_NE(&inner_list, &outer_list);
        EXPECT_TRUE(inner_list.empty());
        inner_list.assign(100, 7);
        const QueryScratch::Level innermost(scratch);  // taking a third level keeps the others' buffers in place
        EXPECT_EQ(&inner.get<std::vector<int>>(), &inner_list);
    }
    EXPECT_EQ(scratch.depth(), 1u);
    EXPECT_EQ(outer_list, (std::vector<int>{1, 2, 3}));
    // Buffers of different types at one level are different buffers.
    EXPECT_NE(static_cast<void*>(&outer.get<TwoLists>()), static_cast<void*>(&outer_list));
}

TEST(QueryScratch, ALevelTakenAgainHasTheBuffersTheLastCallLeft) {
    QueryScratch scratch;
    const int* first_data = nullptr;
    for (int call = 0; call < 3; ++call) {
        const QueryScratch::Level top(scratch);
        const QueryScratch::Level level(scratch);
        TwoLists& lists = level.get<TwoLists>();
        if (call == 0) {
            lists.a.assign(1000, 1);
            first_data = lists.a.data();
        } else {
            EXPECT_EQ(lists.a.size(), 1000u);  // as the last call left it: clearing is the caller's
            EXPECT_EQ(lists.a.data(), first_data) << "no new allocation once grown";
            lists.a.clear();
            lists.a.assign(1000, 2);
        }
    }
    EXPECT_EQ(scratch.depth(), 0u);
}

TEST(QueryScratchPool, LendsEachScratchToOneBorrowerAtATime) {
    QueryScratchPool pool;
    QueryScratch& first = pool.borrow();
    QueryScratch& second = pool.borrow();
    EXPECT_NE(&first, &second);
    pool.give_back(first);
    EXPECT_EQ(&pool.borrow(), &first);  // kept, with its buffers, for the next query
    pool.give_back(first);
    pool.give_back(second);
}

}  // namespace
}  // namespace isotrace
