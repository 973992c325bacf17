#pragma once
// Point-to-point messages of bytes between the ranks of MPI_COMM_WORLD, tagged by purpose. Only the thread that
// initialised MPI calls these (MPI_THREAD_FUNNELED).
#include <optional>
#include <string>

namespace isotrace::mpi {

enum class Tag : int {
    Identity = 1,  // worker -> 0: version, binary and scene fingerprints, or why the scene did not load
    Verdict,       // 0 -> worker: go on, or stop (rank 0 reports why)
    Ready,         // worker -> 0: first request for work
    Result,        // worker -> 0: a finished item (and a request for the next)
    Work,          // 0 -> worker: an item
    Done,          // 0 -> worker: no more work
    Counters,      // worker -> 0: its statistics at the end
    Bench,         // worker -> 0: its benchmark results
};

struct Message {
    int from = 0;
    Tag tag = Tag::Identity;
    std::string bytes;
};

void send(int to, Tag tag, const std::string& bytes);
// Blocks until a message from `from` (any rank when empty) arrives.
Message receive(std::optional<int> from = std::nullopt);
// The next message if one has arrived, without waiting.
std::optional<Message> try_receive();

// The world's size and this process's rank (MPI must be initialised).
int world_size();
int world_rank();

}  // namespace isotrace::mpi
