// Worker threads, case feed and result queue of a sweep (see study_pool.h): one mutex each, no
// work stealing; ids are handed out in increasing order.
#include "solver/study/study_pool.h"

namespace isopound {

void CaseFeed::push(const std::vector<std::int64_t>& ids) {
  {
    const std::lock_guard lock(mutex_);
    ids_.insert(ids_.end(), ids.begin(), ids.end());
  }
  ready_.notify_all();
}

void CaseFeed::close() {
  {
    const std::lock_guard lock(mutex_);
    closed_ = true;
  }
  ready_.notify_all();
}

void CaseFeed::stop() {
  {
    const std::lock_guard lock(mutex_);
    stopped_ = true;
  }
  ready_.notify_all();
}

bool CaseFeed::pop(std::int64_t& id) {
  std::unique_lock lock(mutex_);
  ready_.wait(lock, [&] { return stopped_ || !ids_.empty() || closed_; });
  if (stopped_ || ids_.empty()) return false;
  id = ids_.front();
  ids_.pop_front();
  return true;
}

std::vector<std::int64_t> CaseFeed::take(std::size_t count) {
  const std::lock_guard lock(mutex_);
  std::vector<std::int64_t> out;
  if (stopped_) return out;
  while (out.size() < count && !ids_.empty()) {
    out.push_back(ids_.front());
    ids_.pop_front();
  }
  return out;
}

std::size_t CaseFeed::size() const {
  const std::lock_guard lock(mutex_);
  return ids_.size();
}

void ResultQueue::push(RunRecord run) {
  {
    const std::lock_guard lock(mutex_);
    runs_.push_back(std::move(run));
  }
  ready_.notify_one();
}

void ResultQueue::drain(std::vector<RunRecord>& out, std::chrono::milliseconds wait) {
  std::unique_lock lock(mutex_);
  if (runs_.empty() && wait.count() > 0)
    ready_.wait_for(lock, wait, [&] { return !runs_.empty(); });
  for (RunRecord& run : runs_) out.push_back(std::move(run));
  runs_.clear();
}

bool ResultQueue::empty() const {
  const std::lock_guard lock(mutex_);
  return runs_.empty();
}

WorkerPool::WorkerPool(int count, CaseFeed& feed, ResultQueue& results,
                       std::function<RunRecord(std::int64_t)> compute)
    : feed_(feed) {
  running_ = count;
  for (int i = 0; i < count; ++i) {
    threads_.emplace_back([this, &feed, &results, compute] {
      std::int64_t id = 0;
      while (feed.pop(id)) results.push(compute(id));
      running_.fetch_sub(1);
    });
  }
}

WorkerPool::~WorkerPool() {
  feed_.stop();
  for (std::thread& t : threads_) t.join();
}

}  // namespace isopound
