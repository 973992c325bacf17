// QueryScratch: a level's buffers are its own while deeper levels are taken, and are the same buffers (capacity
// kept) the next time a call takes that level; QueryScratchPool lends a scratch to one borrower at a time.
#include "renderer/embree/query_scratch.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <set>
#include <thread>
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
    const QueryScratchPool::Loan first = pool.borrow(), second = pool.borrow();
    EXPECT_NE(first.scratch, second.scratch);
    pool.give_back(first);
    const QueryScratchPool::Loan again = pool.borrow();
    EXPECT_EQ(again.scratch, first.scratch);  // the thread's own slot: kept, with its buffers, for the next query
    pool.give_back(again);
    pool.give_back(second);
}

TEST(QueryScratchPool, LendsScratchesOfTheirOwnWhenEverySlotIsLent) {
    QueryScratchPool pool(3);
    std::vector<QueryScratchPool::Loan> loans;
    for (int i = 0; i < 5; ++i) loans.push_back(pool.borrow());
    std::set<QueryScratch*> distinct;
    for (const QueryScratchPool::Loan& loan : loans) distinct.insert(loan.scratch);
    EXPECT_EQ(distinct.size(), loans.size());
    EXPECT_EQ(std::count_if(loans.begin(), loans.end(),
                            [](const QueryScratchPool::Loan& loan) { return loan.slot == QueryScratchPool::kNoSlot; }),
              2);
    for (const QueryScratchPool::Loan& loan : loans) pool.give_back(loan);  // the extra two are freed (sanitizers)
}

// Threads borrowing at once, more of them than slots: each writes its mark into its scratch's buffers and finds it
// still there before giving the scratch back, which a scratch lent to two threads at once would not keep.
TEST(QueryScratchPool, ThreadsBorrowingAtOnceNeverShareAScratch) {
    struct Marks {
        std::vector<int> values;
    };
    QueryScratchPool pool(4);
    std::atomic<int> clashes{0};
    std::vector<std::thread> threads;
    for (int id = 0; id < 8; ++id)
        threads.emplace_back([&, id] {
            for (int round = 0; round < 2000; ++round) {
                const QueryScratchPool::Loan loan = pool.borrow();
                {
                    const QueryScratch::Level level(*loan.scratch);
                    std::vector<int>& marks = level.get<Marks>().values;
                    marks.assign(16, id);
                    std::this_thread::yield();
                    if (std::count(marks.begin(), marks.end(), id) != 16) ++clashes;
                }
                pool.give_back(loan);
            }
        });
    for (std::thread& thread : threads) thread.join();
    EXPECT_EQ(clashes.load(), 0);
}

}  // namespace
}  // namespace isotrace
