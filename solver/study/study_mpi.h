// MPI ranks of a sweep (optional, ISOPOUND_HAVE_MPI): rank 0 owns the database and hands out cases
// on request, the others compute and send results back; not under mpirun/srun: one rank, no
// messages.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "solver/study/study_store.h"

namespace isopound {

// Message tags between ranks.
enum class RankMessage : int { kRequest = 1, kWork = 2, kResults = 3 };

struct Incoming {
  int source = 0;
  RankMessage tag = RankMessage::kRequest;
  std::vector<char> bytes;
};

// MPI_Init_thread (funneled: only the main thread talks) on construction when launched by an MPI
// starter, MPI_Finalize on destruction.
class RankSession {
 public:
  RankSession();
  ~RankSession();
  RankSession(const RankSession&) = delete;
  RankSession& operator=(const RankSession&) = delete;

  bool active() const { return active_; }  // more than a plain process: MPI is initialised
  int rank() const { return rank_; }
  int size() const { return size_; }
  int local_size() const { return local_size_; }  // ranks on this node (for the default -j)

  void send(int destination, RankMessage tag, const std::vector<char>& bytes) const;
  // Non-blocking: true and fills `message` when one is waiting (from `source`, -1 = any).
  bool try_receive(Incoming& message, int source = -1) const;
  // Rank 0's value of `status` on every rank (collective).
  int broadcast(int status) const;
  [[noreturn]] void abort(int code) const;

  // True when the environment shows an MPI starter (OMPI_COMM_WORLD_SIZE, PMI_SIZE, PMIX_RANK).
  static bool launched_by_mpi();
  static bool available();  // built with MPI

 private:
  bool active_ = false;
  int rank_ = 0;
  int size_ = 1;
  int local_size_ = 1;
};

// Wire format of the messages (native byte order: all ranks run the same binary).
std::vector<char> encode_cases(const std::vector<std::int64_t>& cases);
std::vector<std::int64_t> decode_cases(const std::vector<char>& bytes);
std::vector<char> encode_runs(const std::vector<RunRecord>& runs);
std::vector<RunRecord> decode_runs(const std::vector<char>& bytes);

}  // namespace isopound
