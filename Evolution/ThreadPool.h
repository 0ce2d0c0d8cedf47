#pragma once
/// @file ThreadPool.h
/// @brief A fixed set of threads that run the calls of a parallel loop.

#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace thyrix {

/// Threads started once and reused by every forEach(), so a generation of evaluations does
/// not pay for starting threads. The calling thread works too: a pool of `threads` starts
/// `threads - 1` threads of its own. One forEach() runs at a time (calls from several threads
/// wait their turn).
class ThreadPool {
 public:
  /// @param threads threads that run the calls, the caller's included (at least 1)
  /// @throws InvalidArgument naming "ThreadPool.threads" if it is 0
  explicit ThreadPool(std::size_t threads);
  /// Waits for the threads to finish and joins them.
  ~ThreadPool();
  ThreadPool(const ThreadPool&) = delete;
  ThreadPool& operator=(const ThreadPool&) = delete;

  /// Threads that run the calls, the caller's included.
  [[nodiscard]] std::size_t threadCount() const { return workers_.size() + 1; }

  /// Calls `job(i)` once for every i in [0, count), spread over the threads in no fixed order,
  /// and returns when every call has returned. If a call throws, the calls not yet started are
  /// skipped and, once the running ones have returned, the exception of the lowest index that
  /// threw is rethrown here; the pool stays usable.
  void forEach(std::size_t count, const std::function<void(std::size_t)>& job);

 private:
  void work();
  void runCalls();

  std::vector<std::thread> workers_;
  std::mutex runMutex_;  // one forEach() at a time
  std::mutex mutex_;
  std::condition_variable wake_;
  std::condition_variable done_;
  const std::function<void(std::size_t)>* job_ = nullptr;
  std::size_t count_ = 0;
  std::size_t next_ = 0;      // the next index to hand out
  std::size_t running_ = 0;   // workers inside the current loop
  std::size_t round_ = 0;     // counts the loops, so a worker joins each once
  bool stopping_ = false;     // the destructor's signal
  std::exception_ptr error_;  // the exception of the lowest index that threw
  std::size_t errorIndex_ = 0;
};

}  // namespace thyrix
