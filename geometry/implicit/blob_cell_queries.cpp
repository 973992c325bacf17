// Which build of the blob cell queries runs (blob_cell_queries.h): chosen once per process.
#include "geometry/implicit/blob_cell_queries.h"

#include "renderer/core/avx2_module.h"

#ifndef ISOTRACE_BLOB_AVX2_MODULE
#error "the build must define ISOTRACE_BLOB_AVX2_MODULE (the AVX2 blob module's file name)"
#endif

namespace isotrace {

const BlobCellQueries& blob_cell_queries() {
    static const BlobCellQueries& chosen = []() -> const BlobCellQueries& {
        const BlobCellQueries* queries =
            avx2_module_build<const BlobCellQueries*>(ISOTRACE_BLOB_AVX2_MODULE, kBlobCellQueriesEntry);
        return queries ? *queries : baseline_blob_cell_queries();
    }();
    return chosen;
}

}  // namespace isotrace
