#include "raster/workers.h"

#include <emmintrin.h>

#include <algorithm>

namespace ffc::raster {

Workers::Workers(int threads) {
  for (int i = 1; i < std::min(threads, kMax); ++i) threads_.emplace_back([this, i] { loop(i); });
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

void Workers::run_impl(void* fn, void (*call)(void*, int)) {
  if (threads_.empty()) return call(fn, 0);
  {
    std::lock_guard<std::mutex> lock(mutex_);
    fn_ = fn, call_ = call;
    pending_.store(int(threads_.size()));
    generation_.fetch_add(1);
  }
  wake_.notify_all();
  call(fn, 0);
  // The shares are about equal: the others finish soon after this one, so spin rather than sleep.
  while (pending_.load(std::memory_order_acquire) != 0) _mm_pause();
}

void Workers::loop(int share) {
  uint64_t seen = 0;
  for (;;) {
    // A draw's phases follow each other within microseconds: spin a little before sleeping.
    for (int spin = 0; spin < 20000 && generation_.load(std::memory_order_acquire) == seen; ++spin) _mm_pause();
    void* fn;
    void (*call)(void*, int);
    {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [&] { return generation_.load() != seen; });
      seen = generation_.load();
      if (stop_) return;
      fn = fn_, call = call_;
    }
    call(fn, share);
    pending_.fetch_sub(1, std::memory_order_acq_rel);
  }
}

}  // namespace ffc::raster
