// The tiles' collective exchange (core/tile_exchange.hpp) over MPI ranks. Optional: built when
// CMake finds MPI (Open MPI from Debian: libopenmpi-dev, openmpi-bin).
#pragma once

#include <chrono>

#include "core/tile_exchange.hpp"

namespace sansui::mpi {

/// MPI_Init on construction and MPI_Finalize on destruction: one per process, in main().
class Session {
 public:
  Session(int& argc, char**& argv);
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;
};

/// Called by a rank whose run failed: whether every rank failed (each calls this), waiting at
/// most `patience` for the others. A failure every rank meets (bad input: each reads the same
/// recipe) can then end the run with one line and no MPI_Abort; a rank that fails alone, while
/// the others work or wait for it in the tiles' collectives, gets false after `patience`.
bool every_rank_failed(std::chrono::milliseconds patience);

/// The exchange over MPI_COMM_WORLD: Alltoall of sizes, then Alltoallv of the messages.
class Exchange final : public TileExchange {
 public:
  Exchange();
  int rank() const override { return rank_; }
  int ranks() const override { return ranks_; }
  std::vector<TileMessage> exchange(std::vector<TileMessage> outgoing) override;
  std::int64_t sum(std::int64_t value) override;
  double max(double value) override;

 private:
  int rank_ = 0, ranks_ = 1;
};

}  // namespace sansui::mpi
