#pragma once
// The classic baseline of §2.1: kinetic sorting of linear motions on an event-at-a-time simulator
// that separates failure times exactly, as CGAL's Kinetic simulator did ("in exact separation, one
// finds smaller and smaller intervals (e.g., using binary search) until all events fall into
// separate intervals"). It exists to measure what lattice batching (MotionSimulator) avoids.
//
// Guarantees:
//  * Each certificate's failure time (the root of x_right − x_left where it turns negative) is
//    isolated first to its lattice interval by LatticeRootSolver (the work the lattice simulator
//    also does), then by bisection with Sturm queries, only as far as the event queue's ordering
//    requires: two failure times are compared by refining both isolating intervals until they are
//    disjoint. Two equal failure times (simultaneous events) can never be separated: equality is
//    established when the intervals reach the root separation bound of two linear polynomials,
//    width 2^−s < 1/|c1·d1| (distinct roots −c0/c1 ≠ −d0/d1 differ by at least 1/|c1·d1|), and ties
//    are then broken by certificate id.
//  * Events are processed one at a time at their exact (rational) time τ: one swap per event; the
//    new certificates of the neighbours fail at τ itself when their pair is out of order just
//    after τ (several points meeting at one place and time are swapped one event at a time).
//  * At every τ it reaches, order() is the sort just after τ; run_until(T) processes exactly the
//    crossings with time < T, so at a lattice time T its order equals KineticSort's.
//  * Positions must have degree ≤ 1 and be pairwise distinct (InputError otherwise).
#include <cstddef>
#include <optional>
#include <set>
#include <vector>

#include "poly/sturm.hpp"

namespace kmr::kinetic {

struct ClassicCounters {
  long long events = 0;                 // certificate failures processed (one crossing each)
  long long lattice_sturm_queries = 0;  // isolating each failure to its lattice interval
  long long bisection_steps = 0;        // Sturm queries refining intervals below the lattice
  long long comparisons = 0;            // failure-time comparisons made by the event queue
  long long ties = 0;                   // comparisons that had to establish equal failure times
  long long root_work() const { return lattice_sturm_queries + bisection_steps; }
};

class ClassicKineticSort {
 public:
  ClassicKineticSort(std::vector<poly::Polynomial> positions, int lattice_bits, exact::Dyadic horizon);

  const std::vector<std::size_t>& order() const { return order_; }
  // Processes the earliest failure if its time is < until; false when there is none.
  bool next_event(const exact::Dyadic& until);
  void run_until(const exact::Dyadic& until) {
    while (next_event(until)) {
    }
  }
  long long swaps() const { return counters_.events; }
  const ClassicCounters& counters() const { return counters_; }

 private:
  struct Cert {
    poly::LatticeRootSolver solver;
    exact::Integer m;  // the failure time lies in [m·2^−s, (m+1)·2^−s)
    long long s;
    std::int64_t slope_bits;  // bit length of |c1|, for the separation bound
    std::size_t slot;
  };
  struct Earlier {  // exact order of failure times, ties by id; refines intervals as needed
    ClassicKineticSort* self;
    bool operator()(std::size_t a, std::size_t b) const { return self->earlier(a, b); }
  };
  bool earlier(std::size_t a, std::size_t b);
  void refine(Cert& c);
  void certify(std::size_t slot);
  void uncertify(std::size_t slot);
  int sign_after_now(std::size_t a, std::size_t b) const;  // sign of x_b − x_a just after τ

  std::vector<poly::Polynomial> x_;
  int bits_;
  exact::Dyadic horizon_;
  exact::Integer tau_num_{0}, tau_den_{1};  // τ; before the first event, the state is just before 0
  bool started_ = false;
  std::vector<std::size_t> order_;
  std::vector<std::size_t> slot_cert_;            // slot → certificate index, or npos
  std::vector<std::optional<Cert>> certs_;        // by certificate index (sequential)
  std::set<std::size_t, Earlier> queue_{Earlier{this}};
  ClassicCounters counters_;
};

}  // namespace kmr::kinetic
