#pragma once
// Designs from searches running side by side, gathered into batches (issue 50: a multi-fidelity
// study's refinements, their finite-element evaluations stepped together as lanes). Each search runs
// on a thread of its own and asks for its designs' costs; when every search still running is waiting,
// the last one to ask evaluates all the waiting designs in one call and hands each its result. A
// design's result does not depend on the designs it was batched with (lanes give lone runs' numbers
// bit for bit), so the searches' paths are those of running them one after another.
#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <vector>

#include "inerta/optim/study.hpp"

namespace inerta::optim {

class LaneBatcher {
 public:
  /// Evaluates several designs (in order), each result independent of the others (evaluate_batch).
  using Evaluate = std::function<std::vector<BatchEvaluation>(const std::vector<network::Network>&)>;

  /// `searches`: how many threads will ask (each calls done() when it stops asking).
  LaneBatcher(int searches, Evaluate evaluate);
  /// The designs' results, in order, once a batch with them has run (blocks; may run the batch). An
  /// exception of the whole batch is each design's.
  std::vector<BatchEvaluation> ask(const std::vector<network::Network>& designs);
  /// This thread's search asks no more (also when it fails).
  void done();
  /// Batches run so far, and the designs in them.
  int batches() const;
  int designs() const;

 private:
  struct Request {
    const std::vector<network::Network>* designs;
    std::vector<BatchEvaluation> out;
    bool ready = false;
  };
  void run_locked(std::unique_lock<std::mutex>& lock);  // runs every pending request (the lock released meanwhile)
  mutable std::mutex mutex_;
  std::condition_variable cv_;
  int active_;
  bool running_ = false;
  std::vector<Request*> pending_;
  Evaluate evaluate_;
  int batches_ = 0, designs_ = 0;
};

}  // namespace inerta::optim
