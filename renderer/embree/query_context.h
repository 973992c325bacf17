#pragma once
// QueryContext: the context a ray query hands Embree. Embree passes it on to every user-geometry callback of the
// query (args->context), instanced ones included, so what the query carries travels behind Embree's own fields:
// the pool its scratch comes from, and the scratch once a callback has needed one (lent for the rest of the query).
#include <embree3/rtcore.h>

#include <type_traits>

#include "renderer/embree/put_off_queries.h"
#include "renderer/embree/query_scratch_pool.h"

namespace isotrace {

// Which of a primitive's occlusion queries a pass answers (RenderScene::occluded). A primitive may put off a query
// whose ray starts within it (a shadow ray leaving its surface), when proving that such a ray gets out costs far
// more than a query from outside: the first pass asks every other query, and only a ray none of them blocks is
// asked again for the ones put off (PutOffQueries, or a second traversal where they were not all kept). The answer
// is the same; a ray that something else blocks skips the costly one.
enum class OcclusionPass {
    All,             // a single pass
    AwayFromStarts,  // every query but those put off, which are noted (QueryContext::put_off)
    AtStarts,        // only the queries put off (a second traversal)
};

struct QueryContext {
    RTCIntersectContext embree;  // first: the callbacks' args->context points here
    QueryScratchPool* pool;
    QueryScratchPool::Loan loan;  // from `pool`, by the first callback that asks for a scratch
    OcclusionPass occlusion_pass = OcclusionPass::All;
    PutOffQueries put_off;  // by the first pass
    // The query's own rays (an RTCRay or RTCRay8) and their number: a callback given these keeps what it puts off.
    const void* rays = nullptr;
    unsigned ray_count = 0;

    explicit QueryContext(QueryScratchPool& scratch_pool) : pool(&scratch_pool) { rtcInitIntersectContext(&embree); }
    ~QueryContext() {
        if (loan.scratch) pool->give_back(loan);
    }
    QueryContext(const QueryContext&) = delete;
    QueryContext& operator=(const QueryContext&) = delete;
};
static_assert(std::is_standard_layout_v<QueryContext>, "a pointer to QueryContext::embree is one to the QueryContext");

// The QueryContext of the query whose callback received `context`, which must be a QueryContext's (every query of
// a RenderScene that can reach a user geometry passes one).
inline QueryContext& query_context(RTCIntersectContext* context) { return *reinterpret_cast<QueryContext*>(context); }

// That query's scratch.
inline QueryScratch& query_scratch(RTCIntersectContext* context) {
    QueryContext& query = query_context(context);
    if (!query.loan.scratch) query.loan = query.pool->borrow();
    return *query.loan.scratch;
}

}  // namespace isotrace
