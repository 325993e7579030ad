#include "pool/workers.h"

#include <algorithm>

#include "raster/isa.h"
#if FFCOMPAT_X86
#include <emmintrin.h>
#endif

namespace ffc::pool {

namespace {
// A hint to the CPU inside a spin loop (x86 pause, Arm yield): the other hyperthread runs, and
// leaving the loop costs no mispredicted memory order. Elsewhere nothing: the loop is the same.
inline void spin_pause() {
#if FFCOMPAT_X86
  _mm_pause();
#elif defined(__aarch64__) || defined(__arm__)
  __asm__ __volatile__("yield");
#endif
}
}  // namespace

Workers::Workers(int threads) {
  for (int i = 1; i < std::min(threads, kMax); ++i) threads_.emplace_back([this] { loop(); });
}

Workers::~Workers() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
    generation_.fetch_add(1);
  }
  wake_.notify_all();
  for (std::thread& t : threads_) t.join();
}

void Workers::run_impl(void* fn, void (*call)(void*, int), int shares) {
  if (threads_.empty()) {
    for (int share = 0; share < shares; ++share) call(fn, share);
    return;
  }
  start(fn, call, shares);
  take_shares({generation_.load(), shares, fn, call});
  // The shares are about equal: the others finish soon after this one, so spin rather than sleep.
  while (done_.load(std::memory_order_acquire) != shares) spin_pause();
}

void Workers::post(void (*fn)(void*), void* arg) {
  if (threads_.empty()) return fn(arg);  // no thread to run it beside the caller: now
  posted_fn_ = fn, posted_arg_ = arg;
  start(this, [](void* w, int) {
    auto* self = static_cast<Workers*>(w);
    self->posted_fn_(self->posted_arg_);
  }, 1);
}

void Workers::wait_posted() {
  while (!posted_done()) spin_pause();
}

void Workers::start(void* fn, void (*call)(void*, int), int shares) {
  uint64_t generation;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    fn_ = fn, call_ = call, shares_ = shares;
    done_.store(0);
    generation = (generation_.load() + 1) & 0xFFFFFFFF;
    ticket_.store(generation << 32);
    generation_.store(generation);
  }
  wake_.notify_all();
}

// The run's own values, not the members: a thread that finished the last share of one run may still
// be here when the caller starts the next, and the next's share count read with this run's ticket
// would let it take (and run with the next run's function) a share of this run that never existed.
void Workers::take_shares(const Run& run) {
  uint64_t t = ticket_.load(std::memory_order_acquire);
  for (;;) {
    const int share = int(t & 0xFFFFFFFF);
    if (t >> 32 != run.generation || share >= run.shares) return;
    if (!ticket_.compare_exchange_weak(t, t + 1, std::memory_order_acq_rel)) continue;
    run.call(run.fn, share);
    done_.fetch_add(1, std::memory_order_acq_rel);
    t = ticket_.load(std::memory_order_acquire);
  }
}

void Workers::loop() {
  uint64_t seen = 0;
  for (;;) {
    // A draw's phases follow each other within microseconds: spin a little before sleeping.
    for (int spin = 0; spin < 20000 && generation_.load(std::memory_order_acquire) == seen; ++spin) spin_pause();
    Run run;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [&] { return generation_.load() != seen; });
      seen = generation_.load();
      if (stop_) return;
      run = {seen, shares_, fn_, call_};  // as start() left them, under its lock
    }
    take_shares(run);
  }
}

}  // namespace ffc::pool
