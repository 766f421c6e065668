#include "sac/big_stack.hpp"

#include <pthread.h>
#include <sys/mman.h>
#include <ucontext.h>
#include <unistd.h>

#include <cstdint>
#include <memory>
#include <string>

#include "exact/error.hpp"
#include "sac/asan.hpp"

#ifdef KMR_ASAN
#include <sanitizer/common_interface_defs.h>
#endif

namespace kmr::sac {

namespace {
struct Contexts {
  ucontext_t caller, stack;
  const void* caller_bottom = nullptr;  // the caller's stack, for AddressSanitizer's switch back
  std::size_t caller_size = 0;
  void* fake_stack = nullptr;  // the caller's fake stack (AddressSanitizer's use-after-return)
};
std::size_t page_size() { return static_cast<std::size_t>(sysconf(_SC_PAGESIZE)); }
}  // namespace

BigStack::BigStack(std::size_t bytes) {
  KMR_CHECK(bytes >= static_cast<std::size_t>(PTHREAD_STACK_MIN), "sac::BigStack: bad stack size " + std::to_string(bytes));
  const std::size_t page = page_size();
  const std::size_t usable = (bytes + page - 1) / page * page;
  void* p = usable < bytes || usable + page < usable
                ? MAP_FAILED
                : mmap(nullptr, usable + page, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE | MAP_STACK, -1, 0);
  KMR_CHECK(p != MAP_FAILED, "sac::BigStack: cannot map a stack of " + std::to_string(bytes) + " bytes");
  base_ = static_cast<char*>(p);
  mapped_ = usable + page;
  usable_ = usable;
  if (mprotect(base_, page, PROT_NONE) != 0) {  // guard page: an overflow faults instead of writing below
    munmap(p, mapped_);
    KMR_CHECK(false, "sac::BigStack: cannot protect the guard page");
  }
  contexts_ = new Contexts;
}

BigStack::~BigStack() {
  delete static_cast<Contexts*>(contexts_);
  munmap(base_, mapped_);
}

void BigStack::trim(std::size_t keep) {
  if (running_) return;  // (its pages are in use)
  const std::size_t page = page_size();
  keep = (keep + page - 1) / page * page;
  if (keep >= usable_) return;
  madvise(base_ + page, usable_ - keep, MADV_DONTNEED);  // (advice: a failure changes nothing)
}

namespace {
// The thread's kept stack: a plain pointer (readable at any time) owned by a thread-local holder
// that unmaps it when the thread exits.
thread_local BigStack* kept = nullptr;
struct KeptHolder {
  bool armed = false;
  ~KeptHolder() {
    delete kept;
    kept = nullptr;
  }
};
thread_local KeptHolder kept_holder;
}  // namespace

BigStack& BigStack::of_thread(std::size_t bytes) {
  KMR_CHECK(!kept || kept->usable_ >= bytes || !kept->running_,
            "BigStack::of_thread: the thread's kept stack is running and smaller than " + std::to_string(bytes) + " bytes");
  if (!kept || kept->usable_ < bytes) {
    auto fresh = std::make_unique<BigStack>(bytes);
    delete kept;
    kept = fresh.release();
    kept_holder.armed = true;  // (odr-uses the holder, so its destructor runs at thread exit)
  }
  return *kept;
}

BigStack* BigStack::kept_of_thread() { return kept; }

bool BigStack::contains(const void* p) const {
  auto a = reinterpret_cast<std::uintptr_t>(p), lo = reinterpret_cast<std::uintptr_t>(base_ + (mapped_ - usable_));
  return a >= lo && a < lo + usable_;
}

// makecontext passes int arguments only: `this` travels as two 32-bit halves.
void BigStack::enter(unsigned hi, unsigned lo) {
  reinterpret_cast<BigStack*>((static_cast<std::uintptr_t>(hi) << 32) | lo)->body();
}

void BigStack::body() {
  auto& c = *static_cast<Contexts*>(contexts_);
#ifdef KMR_ASAN
  __sanitizer_finish_switch_fiber(nullptr, &c.caller_bottom, &c.caller_size);
#endif
  try {
    (*job_)();
  } catch (...) {
    error_ = std::current_exception();
  }
  // Back to the caller directly, never through this frame's epilogue: once AddressSanitizer has
  // been told that this stack's frames end (nullptr), no frame of it may be touched again.
#ifdef KMR_ASAN
  __sanitizer_start_switch_fiber(nullptr, c.caller_bottom, c.caller_size);
#endif
  setcontext(&c.caller);
}

void BigStack::run(const std::function<void()>& f) {
  if (running_) {  // nested: already on this stack
    f();
    return;
  }
  auto& c = *static_cast<Contexts*>(contexts_);
  KMR_CHECK(getcontext(&c.stack) == 0, "sac::BigStack: getcontext failed");
  c.stack.uc_stack.ss_sp = base_ + (mapped_ - usable_);
  c.stack.uc_stack.ss_size = usable_;
  c.stack.uc_link = &c.caller;
  const auto self = reinterpret_cast<std::uintptr_t>(this);
  makecontext(&c.stack, reinterpret_cast<void (*)()>(&BigStack::enter), 2, static_cast<unsigned>(self >> 32),
              static_cast<unsigned>(self & 0xffffffffu));
  job_ = &f;
  error_ = nullptr;
  running_ = true;
  // getcontext + setcontext rather than swapcontext, whose AddressSanitizer interceptor prints a
  // warning on stderr; body() resumes here with setcontext(&c.caller), with `entered` set.
  volatile bool entered = false;
  getcontext(&c.caller);
  if (!entered) {
    entered = true;
#ifdef KMR_ASAN
    __sanitizer_start_switch_fiber(&c.fake_stack, base_ + (mapped_ - usable_), usable_);
#endif
    setcontext(&c.stack);
    KMR_CHECK(false, "sac::BigStack: setcontext failed");
  }
#ifdef KMR_ASAN
  __sanitizer_finish_switch_fiber(c.fake_stack, nullptr, nullptr);
#endif
  running_ = false;
  job_ = nullptr;
  if (error_) {
    std::exception_ptr e = std::move(error_);
    error_ = nullptr;
    std::rethrow_exception(e);
  }
}

void with_stack(std::size_t bytes, const std::function<void()>& f) { BigStack(bytes).run(f); }

}  // namespace kmr::sac
