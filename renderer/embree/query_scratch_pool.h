#pragma once
// The QueryScratch of a scene's queries: lent to a query for its duration and kept afterwards, one for every query
// that ran at the same moment as others, so that buffers grow once per concurrent query rather than once per query.
#include <memory>
#include <mutex>
#include <vector>

#include "renderer/embree/query_scratch.h"

namespace isotrace {

class QueryScratchPool {
public:
    // An idle scratch, or a new one when every scratch is lent out.
    QueryScratch& borrow();
    // `scratch`, borrowed from this pool, is idle again.
    void give_back(QueryScratch& scratch);

private:
    std::mutex mutex_;
    std::vector<std::unique_ptr<QueryScratch>> all_;
    std::vector<QueryScratch*> idle_;  // capacity for all_: giving back never allocates
};

}  // namespace isotrace
