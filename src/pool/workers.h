// A fork-join pool kept for the life of a context: a draw hands each thread one share of its work
// and waits for all of them. Starting threads per draw cost more than small draws' work. One job
// may also run beside the caller (post).
#pragma once
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <type_traits>
#include <thread>
#include <vector>

namespace ffc::pool {

class Workers {
 public:
  static constexpr int kMax = 64;
  explicit Workers(int threads);  // min(threads, kMax) - 1 are started; the caller is share 0
  ~Workers();
  Workers(const Workers&) = delete;
  Workers& operator=(const Workers&) = delete;

  int size() const { return int(threads_.size()) + 1; }
  // Calls fn(share) once for each share in [0, shares) (default: one per thread) and returns when
  // all have returned. The threads take shares as they come: a thread the system runs late leaves
  // its share to the others rather than holding up the draw, and more shares than threads even
  // out unequal ones. Not reentrant.
  template <typename F>
  void run(F&& fn, int shares = 0) {
    run_impl(&fn, [](void* f, int share) { (*static_cast<std::remove_reference_t<F>*>(f))(share); }, shares > 0 ? shares : size());
  }
  // Starts fn(arg) on one of the started threads and returns at once (with no thread started, runs
  // it first): the caller goes on with other work, and neither run nor post may come before
  // wait_posted. Immediate mode's early draws (state/immediate.cpp). The caller keeps arg alive
  // until wait_posted returns.
  void post(void (*fn)(void*), void* arg);
  bool posted_done() const { return done_.load(std::memory_order_acquire) == shares_; }
  void wait_posted();  // what fn wrote is visible after it

 private:
  void run_impl(void* fn, void (*call)(void*, int), int shares);
  void start(void* fn, void (*call)(void*, int), int shares);  // run_impl's half before the caller takes shares
  struct Run {
    uint64_t generation = 0;
    int shares = 0;
    void* fn = nullptr;
    void (*call)(void*, int) = nullptr;
  };
  void loop();
  void take_shares(const Run& run);

  std::vector<std::thread> threads_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::atomic<uint64_t> generation_{0};
  // The run's generation (high 32 bits) and its next share (low 32): a thread woken for one run
  // cannot take a share of the next.
  std::atomic<uint64_t> ticket_{0};
  std::atomic<int> done_{0};
  int shares_ = 0;
  bool stop_ = false;
  void* fn_ = nullptr;
  void (*call_)(void*, int) = nullptr;
  void (*posted_fn_)(void*) = nullptr;
  void* posted_arg_ = nullptr;
};

}  // namespace ffc::pool
