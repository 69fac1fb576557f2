// MPI transport of a sweep (see study_mpi.h). Only the main thread calls MPI (MPI_THREAD_FUNNELED);
// without ISOPOUND_HAVE_MPI every call is for a single rank and sending is an error.
#include "solver/study/study_mpi.h"

#include <cstdlib>
#include <cstring>
#include <stdexcept>

#ifdef ISOPOUND_HAVE_MPI
#define OMPI_SKIP_MPICXX 1  // the C API only: no deprecated C++ bindings to link
#define MPICH_SKIP_MPICXX 1
#include <mpi.h>
#endif

namespace isopound {
namespace {

// resize + memcpy: vector::insert of a byte range trips GCC 12's false -Wstringop-overflow.
void put_bytes(std::vector<char>& out, const void* bytes, std::size_t count) {
  if (count == 0) return;
  const std::size_t at = out.size();
  out.resize(at + count);
  std::memcpy(out.data() + at, bytes, count);
}

template <typename T>
void put(std::vector<char>& out, const T& value) {
  put_bytes(out, &value, sizeof(T));
}

template <typename T>
T get(const std::vector<char>& in, std::size_t& at) {
  if (at + sizeof(T) > in.size()) throw std::runtime_error("truncated message between MPI ranks");
  T value;
  std::memcpy(&value, in.data() + at, sizeof(T));
  at += sizeof(T);
  return value;
}

[[maybe_unused]] int env_int(const char* name, int fallback) {
  const char* text = std::getenv(name);
  return text && *text ? std::atoi(text) : fallback;
}

}  // namespace

bool RankSession::launched_by_mpi() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK", "PMI_RANK"})
    if (std::getenv(name)) return true;
  return false;
}

#ifdef ISOPOUND_HAVE_MPI

bool RankSession::available() {
  return true;
}

RankSession::RankSession() {
  if (!launched_by_mpi()) return;
  int provided = 0;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  active_ = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  local_size_ = env_int("OMPI_COMM_WORLD_LOCAL_SIZE", env_int("MPI_LOCALNRANKS", 1));
  if (local_size_ < 1) local_size_ = 1;
}

RankSession::~RankSession() {
  if (active_) MPI_Finalize();
}

void RankSession::send(int destination, RankMessage tag, const std::vector<char>& bytes) const {
  MPI_Send(bytes.data(), static_cast<int>(bytes.size()), MPI_BYTE, destination,
           static_cast<int>(tag), MPI_COMM_WORLD);
}

bool RankSession::try_receive(Incoming& message, int source) const {
  int waiting = 0;
  MPI_Status status;
  MPI_Iprobe(source < 0 ? MPI_ANY_SOURCE : source, MPI_ANY_TAG, MPI_COMM_WORLD, &waiting, &status);
  if (!waiting) return false;
  int count = 0;
  MPI_Get_count(&status, MPI_BYTE, &count);
  message.bytes.resize(static_cast<std::size_t>(count));
  message.source = status.MPI_SOURCE;
  message.tag = static_cast<RankMessage>(status.MPI_TAG);
  MPI_Recv(message.bytes.data(), count, MPI_BYTE, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD,
           MPI_STATUS_IGNORE);
  return true;
}

int RankSession::broadcast(int status) const {
  if (active_) MPI_Bcast(&status, 1, MPI_INT, 0, MPI_COMM_WORLD);
  return status;
}

void RankSession::abort(int code) const {
  if (active_) MPI_Abort(MPI_COMM_WORLD, code);
  std::exit(code);
}

#else

bool RankSession::available() {
  return false;
}
RankSession::RankSession() = default;
RankSession::~RankSession() = default;
void RankSession::send(int, RankMessage, const std::vector<char>&) const {
  throw std::logic_error("isopound was built without MPI");
}
bool RankSession::try_receive(Incoming&, int) const {
  return false;
}
int RankSession::broadcast(int status) const {
  return status;
}
void RankSession::abort(int code) const {
  std::exit(code);
}

#endif

std::vector<char> encode_cases(const std::vector<std::int64_t>& cases) {
  std::vector<char> out;
  put<std::uint64_t>(out, cases.size());
  for (const std::int64_t c : cases) put(out, c);
  return out;
}

std::vector<std::int64_t> decode_cases(const std::vector<char>& bytes) {
  std::size_t at = 0;
  const auto n = get<std::uint64_t>(bytes, at);
  std::vector<std::int64_t> cases;
  for (std::uint64_t i = 0; i < n; ++i) cases.push_back(get<std::int64_t>(bytes, at));
  return cases;
}

std::vector<char> encode_runs(const std::vector<RunRecord>& runs) {
  std::vector<char> out;
  put<std::uint64_t>(out, runs.size());
  for (const RunRecord& r : runs) {
    put(out, r.case_id);
    put<std::uint8_t>(out, r.ok ? 1 : 0);
    put<std::int32_t>(out, r.rank);
    put(out, r.steps);
    put(out, r.wall_seconds);
    put<std::uint64_t>(out, r.values.size());
    for (const double v : r.values) put(out, v);
    put<std::uint64_t>(out, r.error.size());
    put_bytes(out, r.error.data(), r.error.size());
  }
  return out;
}

std::vector<RunRecord> decode_runs(const std::vector<char>& bytes) {
  std::size_t at = 0;
  const auto n = get<std::uint64_t>(bytes, at);
  std::vector<RunRecord> runs;
  for (std::uint64_t i = 0; i < n; ++i) {
    RunRecord r;
    r.case_id = get<std::int64_t>(bytes, at);
    r.ok = get<std::uint8_t>(bytes, at) != 0;
    r.rank = get<std::int32_t>(bytes, at);
    r.steps = get<std::int64_t>(bytes, at);
    r.wall_seconds = get<double>(bytes, at);
    const auto values = get<std::uint64_t>(bytes, at);
    for (std::uint64_t k = 0; k < values; ++k) r.values.push_back(get<double>(bytes, at));
    const auto length = get<std::uint64_t>(bytes, at);
    if (at + length > bytes.size()) throw std::runtime_error("truncated message between MPI ranks");
    r.error.assign(bytes.data() + at, length);
    at += length;
    runs.push_back(std::move(r));
  }
  return runs;
}

}  // namespace isopound
