#pragma once
// isotrace::parallel_sort: tbb::parallel_sort, except under -fsanitize=thread, where it is std::sort. TBB's sort
// moves elements between its threads inside its own tasks (the range splits partition the data), so there is no
// chunk for parallel_for.h's fork/join announcement to wrap, and TSan would report TBB's hand-offs as races in
// std::sort. The result is the same either way because only integers are accepted (equal keys are
// indistinguishable, so no sort can order them differently).
#include <algorithm>
#include <concepts>
#include <iterator>

#include <tbb/parallel_sort.h>

#include "renderer/core/thread_sanitizer.h"

namespace isotrace {

template <std::random_access_iterator RandomAccessIterator>
    requires std::integral<std::iter_value_t<RandomAccessIterator>>
void parallel_sort(RandomAccessIterator begin, RandomAccessIterator end) {
#ifdef ISOTRACE_THREAD_SANITIZER
    std::sort(begin, end);
#else
    tbb::parallel_sort(begin, end);
#endif
}

}  // namespace isotrace
