#include "renderer/distributed/mpi_channel.h"

#include <mpi.h>

#include <climits>
#include <stdexcept>

namespace isotrace::mpi {
namespace {

Message receive_probed(const MPI_Status& probed) {
    int count = 0;
    MPI_Get_count(&probed, MPI_BYTE, &count);
    Message message{probed.MPI_SOURCE, Tag(probed.MPI_TAG), std::string(std::size_t(count), '\0')};
    MPI_Recv(message.bytes.data(), count, MPI_BYTE, probed.MPI_SOURCE, probed.MPI_TAG, MPI_COMM_WORLD,
             MPI_STATUS_IGNORE);
    return message;
}

}  // namespace

void send(int to, Tag tag, const std::string& bytes) {
    if (bytes.size() > std::size_t(INT_MAX))
        throw std::runtime_error("distributed render: a message of " + std::to_string(bytes.size()) +
                                 " bytes exceeds MPI's limit of 2^31 - 1");
    MPI_Send(bytes.data(), int(bytes.size()), MPI_BYTE, to, int(tag), MPI_COMM_WORLD);
}

Message receive(std::optional<int> from) {
    MPI_Status status;
    MPI_Probe(from.value_or(MPI_ANY_SOURCE), MPI_ANY_TAG, MPI_COMM_WORLD, &status);
    return receive_probed(status);
}

std::optional<Message> try_receive() {
    int arrived = 0;
    MPI_Status status;
    MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &arrived, &status);
    if (!arrived) return std::nullopt;
    return receive_probed(status);
}

int world_size() {
    int size = 1;
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    return size;
}

int world_rank() {
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    return rank;
}

}  // namespace isotrace::mpi
