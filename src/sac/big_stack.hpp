#pragma once
// kmr::sac::BigStack — a large stack, mapped once, on which the owner runs closures.
//
// Runs and propagations recurse natively (a continuation nests per list element or per hull
// insertion), deeper than the default 8 MiB stack allows. The owner of a Runtime keeps one BigStack
// for as long as it runs and propagates, so every run reuses one mapping whose pages stay touched:
// no thread, no stack mapping and no first-touch page faults per propagation. (Before: a new
// pthread with a 1 GiB stack per call — clone3, mmap/mprotect/munmap and the stack's page faults
// every time. A kept worker thread was measured too and lost: each hand-off waits for the
// scheduler to wake the worker. spec/sac.md, "Big stacks".)
//
// Guarantees (tests/sac/big_stack_test.cpp):
//  * run(f) executes f on the calling thread with the stack pointer inside this object's mapping
//    (at least `bytes` usable, a guard page below), and returns when f has returned.
//  * An exception thrown by f is rethrown by run() in the caller, as the same object; the stack
//    stays usable. Nothing is left on the big stack between runs (each run starts afresh).
//  * Every run() of one BigStack uses the same mapping (its pages stay mapped until destruction).
//  * run() called from inside f (already on this stack) calls f directly.
//  * of_thread(bytes) returns the same object on every call from one thread while it is large
//    enough; other threads get their own. Asking for more than the kept stack has while it runs
//    throws ContractError. The kept stack is unmapped at thread exit, so std::exit must not be
//    called from inside a run on it.
//  * The constructor throws ContractError for a size below PTHREAD_STACK_MIN or one that cannot be
//    mapped; destruction unmaps (while no run is in progress).
// A BigStack belongs to one thread at a time (no locking), and f must return or throw: leaving it
// by longjmp or thread cancellation is not supported.
// Deterministic: f runs on the caller's thread exactly as it would on the caller's stack.
// Under AddressSanitizer the switches are announced (__sanitizer_start/finish_switch_fiber).
#include <cstddef>
#include <exception>
#include <functional>

namespace kmr::sac {

class BigStack {
 public:
  explicit BigStack(std::size_t bytes);
  ~BigStack();
  BigStack(const BigStack&) = delete;
  BigStack& operator=(const BigStack&) = delete;

  // Runs f with its stack on this object's mapping and waits for it; rethrows f's exception here.
  void run(const std::function<void()>& f);
  // Whether p points into the usable part of the mapping (for tests: where f's locals live).
  bool contains(const void* p) const;
  // Returns the pages below the top `keep` bytes to the system (madvise MADV_DONTNEED; they read
  // as zero and fault in again if touched); does nothing during a run.
  void trim(std::size_t keep);

  // The calling thread's kept stack of at least `bytes`, mapped at the first call (or mapped anew,
  // larger, when idle and too small) and kept until the thread exits: owners that come and go on
  // one thread (the kinetic hulls of an audit loop) share one warm mapping instead of faulting in
  // a fresh stack each (issue 9, spec/sac.md "Big stacks").
  static BigStack& of_thread(std::size_t bytes);
  static BigStack* kept_of_thread();  // the thread's kept stack, if of_thread mapped one
  std::size_t usable() const { return usable_; }

 private:
  static void enter(unsigned hi, unsigned lo);
  void body();

  char* base_ = nullptr;  // the mapping: a guard page, then `usable_` bytes
  std::size_t mapped_ = 0, usable_ = 0;
  const std::function<void()>* job_ = nullptr;
  std::exception_ptr error_;
  bool running_ = false;
  void* contexts_ = nullptr;  // the caller's and the stack's ucontext_t (kept out of this header)
};

// One-shot: BigStack(bytes).run(f), for callers that run once (the sac bench, the audit's list checks).
void with_stack(std::size_t bytes, const std::function<void()>& f);

}  // namespace kmr::sac
