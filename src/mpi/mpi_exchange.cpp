// The tiles' exchange over MPI (see mpi_exchange.hpp).
#include "mpi/mpi_exchange.hpp"

#include <algorithm>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <thread>

#include <mpi.h>

namespace sansui::mpi {
namespace {

/// A message's header in the byte stream between two ranks.
struct Header {
  std::int32_t from, to;
  std::uint64_t size;
};

void check(int status, const char* what) {
  if (status != MPI_SUCCESS) throw std::runtime_error(std::string("MPI ") + what + " failed");
}

/// A communicator of its own for agreeing on failure: its collectives never meet the tiles'.
MPI_Comm failure_comm = MPI_COMM_NULL;

}  // namespace

Session::Session(int& argc, char**& argv) {
  check(MPI_Init(&argc, &argv), "init");
  check(MPI_Comm_dup(MPI_COMM_WORLD, &failure_comm), "comm_dup");
}
Session::~Session() {
  if (failure_comm != MPI_COMM_NULL) MPI_Comm_free(&failure_comm);
  MPI_Finalize();
}

bool every_rank_failed(std::chrono::milliseconds patience) {
  if (failure_comm == MPI_COMM_NULL) return false;
  MPI_Request request = MPI_REQUEST_NULL;
  if (MPI_Ibarrier(failure_comm, &request) != MPI_SUCCESS) return false;
  const auto deadline = std::chrono::steady_clock::now() + patience;
  for (;;) {
    int done = 0;
    MPI_Test(&request, &done, MPI_STATUS_IGNORE);
    if (done != 0) return true;
    if (std::chrono::steady_clock::now() >= deadline) return false;  // the others are at work (or waiting in the tiles' collectives)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
}

Exchange::Exchange() {
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks_);
}

std::vector<TileMessage> Exchange::exchange(std::vector<TileMessage> outgoing) {
  const auto n = static_cast<std::size_t>(ranks_);
  std::vector<std::vector<std::byte>> to_rank(n);
  for (const TileMessage& m : outgoing) {
    std::vector<std::byte>& buffer = to_rank[static_cast<std::size_t>(owner(m.to))];
    const Header header{m.from, m.to, m.bytes.size()};
    const auto* h = reinterpret_cast<const std::byte*>(&header);
    buffer.insert(buffer.end(), h, h + sizeof header);
    buffer.insert(buffer.end(), m.bytes.begin(), m.bytes.end());
  }
  outgoing.clear();
  std::vector<long long> send_sizes(n), receive_sizes(n);
  for (std::size_t r = 0; r < n; ++r) send_sizes[r] = static_cast<long long>(to_rank[r].size());
  check(MPI_Alltoall(send_sizes.data(), 1, MPI_LONG_LONG, receive_sizes.data(), 1, MPI_LONG_LONG, MPI_COMM_WORLD), "alltoall");
  // MPI counts are ints: each rank's share of one exchange stays under 2 GiB (a border graph of
  // tens of millions of cells).
  std::vector<int> send_counts(n), send_offsets(n), receive_counts(n), receive_offsets(n);
  long long send_total = 0, receive_total = 0;
  for (std::size_t r = 0; r < n; ++r) {
    send_offsets[r] = static_cast<int>(send_total), receive_offsets[r] = static_cast<int>(receive_total);
    send_counts[r] = static_cast<int>(send_sizes[r]), receive_counts[r] = static_cast<int>(receive_sizes[r]);
    send_total += send_sizes[r], receive_total += receive_sizes[r];
  }
  if (send_total > std::numeric_limits<int>::max() || receive_total > std::numeric_limits<int>::max())
    throw std::runtime_error("one exchange between tiles is over 2 GiB on a rank: use more ranks or smaller tiles");
  std::vector<std::byte> sending(static_cast<std::size_t>(send_total)), receiving(static_cast<std::size_t>(receive_total));
  for (std::size_t r = 0; r < n; ++r) std::copy(to_rank[r].begin(), to_rank[r].end(), sending.begin() + send_offsets[r]);
  for (std::size_t r = 0; r < n; ++r)
    if (static_cast<int>(r) != rank_) bytes_sent += send_sizes[r];  // what leaves the rank
  ++exchanges;
  check(MPI_Alltoallv(sending.data(), send_counts.data(), send_offsets.data(), MPI_BYTE, receiving.data(), receive_counts.data(),
                      receive_offsets.data(), MPI_BYTE, MPI_COMM_WORLD),
        "alltoallv");
  std::vector<TileMessage> incoming;
  for (std::size_t at = 0; at + sizeof(Header) <= receiving.size();) {
    Header header{};
    std::copy_n(receiving.begin() + static_cast<std::ptrdiff_t>(at), sizeof header, reinterpret_cast<std::byte*>(&header));
    at += sizeof header;
    const auto begin = receiving.begin() + static_cast<std::ptrdiff_t>(at);
    incoming.push_back({header.from, header.to, std::vector<std::byte>(begin, begin + static_cast<std::ptrdiff_t>(header.size))});
    at += header.size;
  }
  std::stable_sort(incoming.begin(), incoming.end(), [](const TileMessage& a, const TileMessage& b) { return a.from < b.from; });
  return incoming;
}

std::int64_t Exchange::sum(std::int64_t value) {
  long long in = value, out = 0;
  check(MPI_Allreduce(&in, &out, 1, MPI_LONG_LONG, MPI_SUM, MPI_COMM_WORLD), "allreduce");
  return out;
}

double Exchange::max(double value) {
  double out = 0.0;
  check(MPI_Allreduce(&value, &out, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD), "allreduce");
  return out;
}

}  // namespace sansui::mpi
