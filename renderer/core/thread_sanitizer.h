#pragma once
// ThreadSanitizer and TBB: Debian's TBB is not instrumented, so TSan sees neither a task being handed to a worker
// (the fork) nor the end of a parallel loop (the join), and reports every result a worker wrote and the caller
// reads as a race. AnnouncedLoop announces both with __tsan_release/__tsan_acquire; it exists only in builds with
// -fsanitize=thread (ISOTRACE_THREAD_SANITIZER), and parallel_for.h is its only user. publish/acquire announce the
// other hand-off isotrace code takes part in: Embree calling bounds callbacks in its own TBB tasks.
#if defined(__SANITIZE_THREAD__)
#define ISOTRACE_THREAD_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(thread_sanitizer)
#define ISOTRACE_THREAD_SANITIZER 1
#endif
#endif

#ifdef ISOTRACE_THREAD_SANITIZER
#include <sanitizer/tsan_interface.h>
#endif

#include <utility>

namespace isotrace {

namespace thread_sanitizer {

// publish(object) once it is complete, before a library hands it to its own threads; acquire(object) first thing
// on such a thread: everything before the publish happens before what follows the acquire. No-ops without
// -fsanitize=thread.
inline void publish([[maybe_unused]] const void* object) {
#ifdef ISOTRACE_THREAD_SANITIZER
    __tsan_release(const_cast<void*>(object));
#endif
}

inline void acquire([[maybe_unused]] const void* object) {
#ifdef ISOTRACE_THREAD_SANITIZER
    __tsan_acquire(const_cast<void*>(object));
#endif
}

}  // namespace thread_sanitizer

#ifdef ISOTRACE_THREAD_SANITIZER

// One parallel loop, on the caller's stack; TBB calls it (on any thread) for every chunk. The loop object itself
// is the fork's sync object and join_ the join's: chunks synchronise with the caller only, never with each other,
// so a race between two chunks is still reported.
template <class Body>
class AnnouncedLoop {
public:
    explicit AnnouncedLoop(const Body& body) : body_(body) {}
    // The join: every chunk happens before what the caller does after the loop (also when a chunk threw).
    ~AnnouncedLoop() { __tsan_acquire(&join_); }
    AnnouncedLoop(const AnnouncedLoop&) = delete;
    AnnouncedLoop& operator=(const AnnouncedLoop&) = delete;

    // The fork, just before handing the loop to TBB: everything the caller did until then happens before every
    // chunk. Passing this object's address out also makes the compiler finish every store to it first.
    void fork() const { __tsan_release(sync_object()); }

    template <class Chunk>
    void operator()(Chunk&& chunk) const {
        __tsan_acquire(sync_object());  // first, before reading any member
        const ChunkEnd end{join_};
        body_(std::forward<Chunk>(chunk));
    }

private:
    struct ChunkEnd {
        char& join;
        ~ChunkEnd() { __tsan_release(&join); }
    };

    void* sync_object() const { return const_cast<AnnouncedLoop*>(this); }

    const Body& body_;
    mutable char join_ = 0;
};

#endif

}  // namespace isotrace
