// Worker threads of a sweep: they pull case ids from a CaseFeed (in order) and push finished runs
// to a ResultQueue that one thread drains and commits. Which thread ran a case never matters.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

#include "solver/study/study_store.h"

namespace isopound {

// Case ids waiting to be computed. Open feeds can receive more (an MPI rank asks rank 0 for
// chunks); pop() blocks until an id arrives or the feed is closed and empty, or stopped.
class CaseFeed {
 public:
  void push(const std::vector<std::int64_t>& ids);
  void close();  // no more ids will come
  void stop();   // hand out nothing more (interrupt)
  bool pop(std::int64_t& id);
  std::vector<std::int64_t> take(std::size_t count);  // non-blocking, for another rank
  std::size_t size() const;

 private:
  mutable std::mutex mutex_;
  std::condition_variable ready_;
  std::deque<std::int64_t> ids_;
  bool closed_ = false;
  bool stopped_ = false;
};

class ResultQueue {
 public:
  void push(RunRecord run);
  // Moves everything queued into `out` (appending), waiting up to `wait` for the first one.
  void drain(std::vector<RunRecord>& out, std::chrono::milliseconds wait);
  bool empty() const;

 private:
  mutable std::mutex mutex_;
  std::condition_variable ready_;
  std::vector<RunRecord> runs_;
};

// `count` threads running `compute` on ids from `feed` until it runs dry; joined on destruction
// (after stopping the feed, so a destructor during an exception does not wait for all cases).
class WorkerPool {
 public:
  WorkerPool(int count, CaseFeed& feed, ResultQueue& results,
             std::function<RunRecord(std::int64_t)> compute);
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;
  bool finished() const { return running_.load() == 0; }

 private:
  CaseFeed& feed_;
  std::atomic<int> running_{0};
  std::vector<std::thread> threads_;
};

}  // namespace isopound
