#include "renderer/embree/query_scratch.h"

namespace isotrace {

QueryScratch::Level::Level(QueryScratch& scratch) : scratch_(scratch), depth_(scratch.depth_++) {
    if (scratch_.levels_.size() == depth_) scratch_.levels_.emplace_back();
}

}  // namespace isotrace
