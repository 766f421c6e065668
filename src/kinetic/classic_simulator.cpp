#include "kinetic/classic_simulator.hpp"

#include <algorithm>
#include <numeric>

#include "exact/error.hpp"

namespace kmr::kinetic {

using exact::Dyadic;
using exact::Integer;
using poly::Polynomial;

namespace {
constexpr std::size_t kNone = static_cast<std::size_t>(-1);
const Integer& coefficient(const Polynomial& p, int i) {
  static const Integer zero(0);
  return i <= p.degree() ? p[i] : zero;
}
}  // namespace

ClassicKineticSort::ClassicKineticSort(std::vector<Polynomial> positions, int lattice_bits, Dyadic horizon)
    : x_(std::move(positions)), bits_(lattice_bits), horizon_(std::move(horizon)), order_(x_.size()) {
  for (std::size_t i = 0; i < x_.size(); ++i)
    if (x_[i].degree() > 1) throw InputError("the classic simulator sorts linear motions only (point " + std::to_string(i) + ")");
  std::iota(order_.begin(), order_.end(), std::size_t{0});
  std::stable_sort(order_.begin(), order_.end(), [&](std::size_t a, std::size_t b) {
    if (x_[a] == x_[b]) throw InputError("points " + std::to_string(a) + " and " + std::to_string(b) + " have identical trajectories");
    return sign_after_now(a, b) > 0;
  });
  slot_cert_.assign(order_.empty() ? 0 : order_.size() - 1, kNone);
  for (std::size_t j = 0; j < slot_cert_.size(); ++j) certify(j);
}

int ClassicKineticSort::sign_after_now(std::size_t a, std::size_t b) const {
  Polynomial p = x_[b] - x_[a];
  if (!started_) return poly::sign_before(p, Dyadic(0));  // the state just before t = 0
  // p(τ)·den = c0·den + c1·num; at a root, the sign just after τ is the slope's.
  int s = (coefficient(p, 0) * tau_den_ + coefficient(p, 1) * tau_num_).sign();
  return s != 0 ? s : coefficient(p, 1).sign();
}

void ClassicKineticSort::certify(std::size_t slot) {
  std::size_t a = order_[slot], b = order_[slot + 1];
  Polynomial p = x_[b] - x_[a];
  if (sign_after_now(a, b) < 0)  // out of order just after τ: its root is τ and it fails now
    KMR_CHECK(coefficient(p, 1).sign() < 0, "a pair out of order just after τ that is not crossing at τ");
  if (coefficient(p, 1).sign() >= 0) return;  // never turns negative
  Integer from = started_ ? Integer((tau_num_ << static_cast<unsigned>(bits_)) / tau_den_) : Integer(0);
  if (started_ && from * tau_den_ > (tau_num_ << static_cast<unsigned>(bits_))) from -= 1;  // floor
  poly::LatticeRootSolver solver(p, bits_);
  auto k = solver.next_failure_after(Dyadic(from, -bits_), horizon_);
  counters_.lattice_sturm_queries += solver.sturm_queries;
  if (!k) return;
  std::size_t index = certs_.size();
  certs_.emplace_back(Cert{std::move(solver), *k, bits_, exact::bit_length(coefficient(p, 1)), slot});
  slot_cert_[slot] = index;
  queue_.insert(index);
}

void ClassicKineticSort::uncertify(std::size_t slot) {
  std::size_t index = slot_cert_[slot];
  if (index == kNone) return;
  queue_.erase(index);
  certs_[index].reset();
  slot_cert_[slot] = kNone;
}

void ClassicKineticSort::refine(Cert& c) {
  // One bisection step: is the root below the midpoint (2m+1)·2^−(s+1)?
  Integer mid = 2 * c.m + 1;
  bool below = c.solver.roots_below(mid, c.s + 1) == 1;
  c.m = below ? Integer(2 * c.m) : mid;
  c.s += 1;
  ++counters_.bisection_steps;
}

bool ClassicKineticSort::earlier(std::size_t a, std::size_t b) {
  if (a == b) return false;
  ++counters_.comparisons;
  Cert &A = *certs_[a], &B = *certs_[b];
  for (;;) {
    if (A.s < B.s) {
      refine(A);
    } else if (B.s < A.s) {
      refine(B);
    } else if (A.m != B.m) {
      return A.m < B.m;  // disjoint intervals of one width
    } else if (A.s > A.slope_bits + B.slope_bits) {
      ++counters_.ties;  // narrower than any gap between distinct roots: equal failure times
      return a < b;
    } else {
      refine(A);
      refine(B);
    }
  }
}

bool ClassicKineticSort::next_event(const Dyadic& until) {
  if (queue_.empty()) return false;
  std::size_t index = *queue_.begin();
  Cert& c = *certs_[index];
  const Polynomial& p = c.solver.polynomial();
  // The failure time τ = −c0/c1 (c1 < 0): processed only if τ < until.
  Integer num = -coefficient(p, 0), den = coefficient(p, 1);
  if (den < 0) num = -num, den = -den;
  if (!(Dyadic(num) < until * Dyadic(den))) return false;
  queue_.erase(queue_.begin());
  std::size_t slot = c.slot;
  certs_[index].reset();
  slot_cert_[slot] = kNone;
  KMR_CHECK(!started_ || num * tau_den_ >= tau_num_ * den, "events out of time order");
  tau_num_ = std::move(num), tau_den_ = std::move(den);
  started_ = true;
  std::swap(order_[slot], order_[slot + 1]);
  ++counters_.events;
  KMR_CHECK(sign_after_now(order_[slot], order_[slot + 1]) > 0, "a swapped pair is not in order just after its crossing");
  if (slot > 0) uncertify(slot - 1), certify(slot - 1);
  certify(slot);
  if (slot + 1 < slot_cert_.size()) uncertify(slot + 1), certify(slot + 1);
  return true;
}

}  // namespace kmr::kinetic
