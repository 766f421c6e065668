// sac::BigStack (sac/big_stack.hpp): closures run on one kept large stack. Each test judges by an
// independent fact: hand-derived results, the frame address against the object's mapping, the
// process's minor page faults (a warm stack takes none), mincore after destruction, and the
// system's own refusals (below PTHREAD_STACK_MIN; a size no mmap can satisfy).
#include <gtest/gtest.h>

#include <pthread.h>
#include <sys/mman.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "error_of.hpp"
#include "sac/big_stack.hpp"

using namespace kmr::sac;

namespace {

using kmr::sac::test::error_of;

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// Recursion that keeps `kib` KiB of stack per level live; returns 1 + 2 + ... + depth and the
// lowest frame address reached.
struct Deep {
  std::uintptr_t lowest = UINTPTR_MAX;
  __attribute__((noinline)) std::uint64_t sum(std::uint64_t depth) {
    volatile char pad[4096];
    pad[0] = static_cast<char>(depth);
    pad[4095] = pad[0];
    auto here = reinterpret_cast<std::uintptr_t>(__builtin_frame_address(0));
    if (here < lowest) lowest = here;
    std::uint64_t below = depth > 1 ? sum(depth - 1) : 0;
    return below + depth + static_cast<std::uint64_t>(pad[4095] - pad[0]);
  }
};

std::uintptr_t frame() { return reinterpret_cast<std::uintptr_t>(__builtin_frame_address(0)); }

long minor_faults() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_minflt;
}

struct Odd {
  int value;
};

TEST(SacBigStack, ResultsAndEffectsCrossTheBoundary) {
  BigStack stack(std::size_t{64} << 20);
  std::uint64_t got = 0;
  std::vector<int> seen;
  stack.run([&] {
    got = Deep().sum(1000);
    seen.push_back(7);
  });
  EXPECT_EQ(got, 1000u * 1001u / 2);  // hand-derived
  EXPECT_EQ(seen, std::vector<int>{7});
  stack.run([&] { seen.push_back(8); });  // a second run sees and extends the first run's effects
  EXPECT_EQ(seen, (std::vector<int>{7, 8}));
}

TEST(SacBigStack, ExceptionsCrossAsTheSameObjectAndTheStackStaysUsable) {
  BigStack stack(std::size_t{64} << 20);
  try {
    stack.run([] { throw std::out_of_range("from the big stack"); });
    ADD_FAILURE() << "no exception";
  } catch (const std::out_of_range& e) {
    EXPECT_STREQ(e.what(), "from the big stack");
  }
  try {
    stack.run([] {
      Deep().sum(100);
      throw Odd{42};
    });
    ADD_FAILURE() << "no exception";
  } catch (const Odd& e) {
    EXPECT_EQ(e.value, 42);
  }
  int after = 0;
  EXPECT_NO_THROW(stack.run([&] { after = 5; }));  // no stale exception from the runs before
  EXPECT_EQ(after, 5);
  std::string e = error_of([&] { stack.run([] { KMR_CHECK(false, "inside"); }); });
  EXPECT_TRUE(has(e, "inside")) << e;
}

TEST(SacBigStack, DeepRecursionBeyondTheDefaultStackRunsOnTheMapping) {
  rlimit lim{};
  ASSERT_EQ(getrlimit(RLIMIT_STACK, &lim), 0);
  const std::uint64_t depth = 5120;  // ≥ 4 KiB per level: ≥ 20 MiB, 2.5× the default 8 MiB stack
  BigStack stack(std::size_t{256} << 20);
  Deep deep;
  std::uint64_t got = 0;
  std::uintptr_t top = 0;
  stack.run([&] {
    top = frame();
    got = deep.sum(depth);
  });
  EXPECT_EQ(got, depth * (depth + 1) / 2);
  EXPECT_TRUE(stack.contains(reinterpret_cast<const void*>(top)));
  EXPECT_TRUE(stack.contains(reinterpret_cast<const void*>(deep.lowest)));
  EXPECT_GE(top - deep.lowest, std::uintptr_t{20} << 20);
  if (lim.rlim_cur != RLIM_INFINITY) {
    EXPECT_GT(top - deep.lowest, lim.rlim_cur);
  }
  EXPECT_FALSE(stack.contains(reinterpret_cast<const void*>(frame())));  // the caller stays on its own stack
}

TEST(SacBigStack, RepeatedRunsReuseOneWarmStackOnTheCallersThread) {
  BigStack stack(std::size_t{256} << 20);
  std::vector<std::uintptr_t> tops;
  std::vector<std::thread::id> threads;
  std::vector<long> faults;
  for (int i = 0; i < 3; ++i) {
    const long before = minor_faults();
    stack.run([&] {
      tops.push_back(frame());
      threads.push_back(std::this_thread::get_id());
      Deep().sum(2048);  // ≥ 8 MiB of stack: ≥ 2048 pages first-touched by the first run
    });
    faults.push_back(minor_faults() - before);
  }
  for (std::uintptr_t t : tops) EXPECT_TRUE(stack.contains(reinterpret_cast<const void*>(t)));
  EXPECT_EQ(tops[1], tops[0]);  // every run starts at the same place on the same mapping
  EXPECT_EQ(tops[2], tops[0]);
  for (std::thread::id t : threads) EXPECT_EQ(t, std::this_thread::get_id());  // no thread is created
  // 4 KiB pages (THP "madvise" or "never", as here; with THP "always" the first run may fault far
  // less). Later runs fault only for what is not the stack (ASan's fake stacks under
  // detect_stack_use_after_return=1: ≈ 300), well under a quarter of the first run's.
  EXPECT_GE(faults[0], 2048);
  EXPECT_LT(faults[1], faults[0] / 4) << "the second run's stack pages should already be mapped";
  EXPECT_LT(faults[2], faults[0] / 4);
}

TEST(SacBigStack, NestedRunCallsDirectlyOnTheSameStack) {
  BigStack stack(std::size_t{64} << 20);
  std::uintptr_t outer = 0, inner = 0;
  int depth_seen = 0;
  stack.run([&] {
    outer = frame();
    stack.run([&] {
      inner = frame();
      depth_seen = 2;
    });
  });
  EXPECT_EQ(depth_seen, 2);
  EXPECT_TRUE(stack.contains(reinterpret_cast<const void*>(inner)));
  EXPECT_LT(inner, outer);  // deeper on the same stack, not a restart at its top
}

TEST(SacBigStack, DestructionWhileIdleUnmapsTheStack) {
  { BigStack never_run(std::size_t{64} << 20); }
  std::uintptr_t top = 0;
  {
    BigStack stack(std::size_t{64} << 20);
    stack.run([&] { top = frame(); });
    try {
      stack.run([] { throw 1; });
    } catch (int) {
    }
  }
  const auto page = static_cast<std::uintptr_t>(sysconf(_SC_PAGESIZE));
  unsigned char v = 0;
  errno = 0;
  EXPECT_EQ(mincore(reinterpret_cast<void*>(top / page * page), page, &v), -1);
  EXPECT_EQ(errno, ENOMEM);  // not mapped any more
}

// of_thread (issue 9, spec/sac.md "Warm memory"): one kept stack per thread, reused by every caller
// on that thread while large enough; trim(keep) gives back the pages below the top `keep` bytes
// (mincore: not resident) and keeps the top's (resident), and the stack stays usable.
TEST(SacBigStack, OfThreadIsOneKeptStackPerThreadAndTrimGivesBackItsDeepPages) {
  BigStack& a = BigStack::of_thread(std::size_t{64} << 20);
  EXPECT_EQ(&BigStack::of_thread(std::size_t{32} << 20), &a);  // large enough: the same object
  EXPECT_EQ(BigStack::kept_of_thread(), &a);
  EXPECT_GE(a.usable(), std::size_t{64} << 20);
  BigStack* other = nullptr;
  std::thread([&] { other = &BigStack::of_thread(std::size_t{16} << 20); }).join();
  EXPECT_NE(other, &a);  // another thread's own (unmapped when that thread ended)
  Deep deep;
  std::uintptr_t top = 0;
  a.run([&] {
    top = frame();
    deep.sum(4096);  // ≥ 16 MiB of stack touched
  });
  const auto page = static_cast<std::uintptr_t>(sysconf(_SC_PAGESIZE));
  auto resident = [&](std::uintptr_t p) {
    unsigned char v = 0;
    EXPECT_EQ(mincore(reinterpret_cast<void*>(p / page * page), page, &v), 0);
    return (v & 1) != 0;
  };
  const std::uintptr_t deep_page = deep.lowest + 2 * page;  // touched by the deepest frames
  EXPECT_TRUE(resident(deep_page));
  EXPECT_TRUE(resident(top));
  a.trim(std::size_t{4} << 20);
  EXPECT_FALSE(resident(deep_page)) << "pages below the kept top should be given back";
  EXPECT_TRUE(resident(top)) << "the top 4 MiB stay";
  EXPECT_EQ(&BigStack::of_thread(std::size_t{1} << 20), &a);
  std::uint64_t again = 0;
  a.run([&] { again = deep.sum(2048); });  // usable after a trim (the pages fault in again)
  EXPECT_EQ(again, 2048u * 2049u / 2);
  // Asking for more while it runs is refused (it cannot be replaced under its own frames).
  std::string refused;
  a.run([&] { refused = error_of([&] { BigStack::of_thread(a.usable() + (std::size_t{1} << 20)); }); });
  EXPECT_NE(refused.find("running and smaller"), std::string::npos) << refused;
  EXPECT_EQ(BigStack::kept_of_thread(), &a);
}

TEST(SacBigStack, RefusedSizesAndTheOneShotWithStack) {
  bool ran = false;
  std::string small = error_of([&] { with_stack(PTHREAD_STACK_MIN - 1, [&] { ran = true; }); });
  EXPECT_TRUE(has(small, "sac::BigStack: bad stack size")) << small;
  std::string huge = error_of([&] { with_stack(std::size_t{1} << 62, [&] { ran = true; }); });
  EXPECT_TRUE(has(huge, "sac::BigStack: cannot map a stack of 4611686018427387904 bytes")) << huge;
  EXPECT_FALSE(ran);
  Deep deep;
  std::uint64_t got = 0;
  std::uintptr_t top = 0;
  with_stack(std::size_t{128} << 20, [&] {
    top = frame();
    got = deep.sum(3072);  // ≥ 12 MiB
  });
  EXPECT_EQ(got, 3072u * 3073u / 2);
  EXPECT_GE(top - deep.lowest, std::uintptr_t{12} << 20);
  EXPECT_THROW(with_stack(std::size_t{1} << 20, [] { throw std::out_of_range("one shot"); }), std::out_of_range);
}

}  // namespace
