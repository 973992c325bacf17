#pragma once
// QueryContext: the context a ray query hands Embree. Embree passes it on to every user-geometry callback of the
// query (args->context), instanced ones included, so what the query carries travels behind Embree's own fields:
// the pool its scratch comes from, and the scratch once a callback has needed one (lent for the rest of the query).
#include <embree3/rtcore.h>

#include <type_traits>

#include "renderer/embree/query_scratch_pool.h"

namespace isotrace {

struct QueryContext {
    RTCIntersectContext embree;  // first: the callbacks' args->context points here
    QueryScratchPool* pool;
    QueryScratchPool::Loan loan;  // from `pool`, by the first callback that asks for a scratch

    explicit QueryContext(QueryScratchPool& scratch_pool) : pool(&scratch_pool) { rtcInitIntersectContext(&embree); }
    ~QueryContext() {
        if (loan.scratch) pool->give_back(loan);
    }
    QueryContext(const QueryContext&) = delete;
    QueryContext& operator=(const QueryContext&) = delete;
};
static_assert(std::is_standard_layout_v<QueryContext>, "a pointer to QueryContext::embree is one to the QueryContext");

// The scratch of the query whose callback received `context`, which must be a QueryContext's (every query of a
// RenderScene that can reach a user geometry passes one).
inline QueryScratch& query_scratch(RTCIntersectContext* context) {
    QueryContext& query = *reinterpret_cast<QueryContext*>(context);
    if (!query.loan.scratch) query.loan = query.pool->borrow();
    return *query.loan.scratch;
}

}  // namespace isotrace
