// The worker pool (src/pool/workers.h): run's shares, and post's one job beside the caller, which
// immediate mode's early draws rely on (state/immediate.cpp).
#include <gtest/gtest.h>

#include <atomic>
#include <thread>
#include <vector>

#include "pool/workers.h"

namespace ffc {
namespace {

TEST(Workers, RunCallsEveryShareOnce) {
  pool::Workers w(2);
  std::vector<std::atomic<int>> calls(7);
  w.run([&](int s) { calls[size_t(s)]++; }, 7);
  for (const auto& c : calls) EXPECT_EQ(c.load(), 1);
}

struct Job {
  std::atomic<bool> release{false};
  std::thread::id ran_on;
  int result = 0;
};

// The job runs on the pool's thread while the caller goes on (here: the caller lets it finish);
// what it wrote is visible after wait_posted, and run works again after it.
TEST(Workers, PostRunsBesideTheCaller) {
  pool::Workers w(2);
  Job job;
  w.post([](void* p) {
    auto* j = static_cast<Job*>(p);
    while (!j->release.load()) std::this_thread::yield();  // returns only once the caller has gone on
    j->ran_on = std::this_thread::get_id();
    j->result = 42;
  }, &job);
  EXPECT_FALSE(w.posted_done());
  job.release = true;
  w.wait_posted();
  EXPECT_TRUE(w.posted_done());
  EXPECT_EQ(job.result, 42);
  EXPECT_NE(job.ran_on, std::this_thread::get_id());
  std::atomic<int> shares{0};
  w.run([&](int) { shares++; });
  EXPECT_EQ(shares.load(), 2);
  EXPECT_TRUE(w.posted_done()) << "a run after the post leaves nothing posted";
}

// With no thread started the job runs within post.
TEST(Workers, PostWithoutThreadsRunsAtOnce) {
  pool::Workers w(1);
  Job job;
  job.release = true;
  w.post([](void* p) {
    auto* j = static_cast<Job*>(p);
    j->ran_on = std::this_thread::get_id();
    j->result = 7;
  }, &job);
  EXPECT_TRUE(w.posted_done());
  EXPECT_EQ(job.result, 7);
  EXPECT_EQ(job.ran_on, std::this_thread::get_id());
  w.wait_posted();
}

}  // namespace
}  // namespace ffc
