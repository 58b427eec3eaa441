// Designs from searches running side by side, gathered into batches (optim/lane_batcher.hpp).
#include "inerta/optim/lane_batcher.hpp"

#include <stdexcept>

namespace inerta::optim {

LaneBatcher::LaneBatcher(int searches, Evaluate evaluate) : active_(searches), evaluate_(std::move(evaluate)) {
  if (searches < 1) throw std::invalid_argument("LaneBatcher: at least one search");
}

void LaneBatcher::run_locked(std::unique_lock<std::mutex>& lock) {
  running_ = true;
  std::vector<Request*> batch;
  batch.swap(pending_);
  std::vector<network::Network> all;
  for (const Request* r : batch) all.insert(all.end(), r->designs->begin(), r->designs->end());
  lock.unlock();
  std::vector<BatchEvaluation> out;
  std::exception_ptr failed;
  try {
    out = evaluate_(all);
    if (out.size() != all.size()) throw std::logic_error("LaneBatcher: the evaluator gave a wrong number of results");
  } catch (...) {  // the whole batch failed: every design's exception
    failed = std::current_exception();
  }
  lock.lock();
  std::size_t k = 0;
  for (Request* r : batch) {
    r->out.resize(r->designs->size());
    for (auto& o : r->out) {
      if (failed) o.error = failed;
      else o = std::move(out[k]);
      ++k;
    }
    r->ready = true;
  }
  ++batches_, designs_ += static_cast<int>(all.size());
  running_ = false;
  cv_.notify_all();
}

std::vector<BatchEvaluation> LaneBatcher::ask(const std::vector<network::Network>& designs) {
  Request me{&designs, {}, false};
  std::unique_lock<std::mutex> lock(mutex_);
  pending_.push_back(&me);
  cv_.notify_all();
  // Every search still running is waiting: the batch runs (on the thread that sees it first).
  while (!me.ready) {
    if (!running_ && static_cast<int>(pending_.size()) >= active_) run_locked(lock);
    else cv_.wait(lock);
  }
  return std::move(me.out);
}

void LaneBatcher::done() {
  std::lock_guard<std::mutex> lock(mutex_);
  --active_;
  cv_.notify_all();  // the waiting ones may now be all that run
}

int LaneBatcher::batches() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return batches_;
}
int LaneBatcher::designs() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return designs_;
}

}  // namespace inerta::optim
