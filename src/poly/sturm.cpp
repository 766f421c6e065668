#include "poly/sturm.hpp"

#include "exact/error.hpp"

namespace kmr::poly {

namespace {
int variations(const std::vector<int>& signs) {
  int v = 0, last = 0;
  for (int s : signs) {
    if (s == 0) continue;
    if (last != 0 && s != last) ++v;
    last = s;
  }
  return v;
}
}  // namespace

SturmSequence::SturmSequence(const Polynomial& p) {
  if (p.is_zero()) throw InputError("identically zero polynomial: it has no isolated roots");
  // Most certificates are square-free: build the sequence from p's primitive part directly. If it
  // ends in a nonconstant member, that member is gcd(p, p') (up to a constant), p has a multiple
  // root, and the sequence is rebuilt from the square-free part.
  Polynomial first = p.primitive_part();
  if (first.sign() < 0) first = -first;
  build(first);
  if (seq_.back().degree() > 0) build(square_free_part(p));
  KMR_CHECK(seq_.back().degree() <= 0, "Sturm sequence of a square-free polynomial ends in a constant");
  for (const auto& q : seq_) approx_.push_back(double_coefficients(q));
  std::vector<int> plus, minus;
  for (const auto& q : seq_) {
    plus.push_back(q.sign());
    minus.push_back(q.degree() % 2 == 0 ? q.sign() : -q.sign());
  }
  v_plus_inf_ = variations(plus);
  v_minus_inf_ = variations(minus);
}

void SturmSequence::build(const Polynomial& first) {
  seq_.clear();
  seq_.push_back(first);
  if (seq_[0].degree() > 0) seq_.push_back(seq_[0].derivative());
  while (seq_.size() >= 2 && seq_.back().degree() > 0) {
    const Polynomial& a = seq_[seq_.size() - 2];
    const Polynomial& b = seq_.back();
    Polynomial r = pseudo_remainder(a, b);
    if (r.is_zero()) break;  // b = gcd(first, first') up to a constant: first is not square-free
    // prem = lc(b)^(d+1)·rem: undo a negative factor so that r is a positive multiple of rem.
    int d1 = a.degree() - b.degree() + 1;
    if (b.leading().sign() < 0 && d1 % 2 == 1) r = -r;
    Integer g = r.content();  // positive: dividing keeps signs
    Polynomial next = -r;
    if (g != 1) next = exact_quotient(next, Polynomial(g));
    seq_.push_back(std::move(next));
  }
}

int SturmSequence::variations_at(const Integer& m, long long s) const {
  std::vector<int> signs;
  signs.reserve(seq_.size());
  for (std::size_t i = 0; i < seq_.size(); ++i) signs.push_back(filtered_sign_at(seq_[i], approx_[i], m, s));
  return variations(signs);
}

int SturmSequence::variations_at(const Dyadic& t) const {
  if (t.exponent() >= 0) return variations_at(t.floor(), 0);
  return variations_at(t.mantissa(), -t.exponent());
}

int SturmSequence::roots_below(const Integer& m, long long s) const {
  // V(−∞) − V(t) counts the distinct roots in (−∞, t]; subtract t itself if it is a root.
  int last = 0, v = 0;
  bool root_at_t = false;
  for (std::size_t i = 0; i < seq_.size(); ++i) {
    int sg = filtered_sign_at(seq_[i], approx_[i], m, s);
    if (i == 0) root_at_t = sg == 0;
    if (sg == 0) continue;
    if (last != 0 && sg != last) ++v;
    last = sg;
  }
  int le = v_minus_inf_ - v;
  return root_at_t ? le - 1 : le;
}

int SturmSequence::roots_below(const Dyadic& t) const {
  if (t.exponent() >= 0) return roots_below(t.floor(), 0);
  return roots_below(t.mantissa(), -t.exponent());
}

Integer lattice_ceil(const Dyadic& t, int bits) { return t.shifted(bits).ceil(); }

LatticeRootSolver::LatticeRootSolver(const Polynomial& p, int lattice_bits)
    : p_(p), p_approx_(double_coefficients(p)), bits_(lattice_bits) {
  if (p.is_zero()) throw InputError("identically zero polynomial: it has no isolated roots");
  if (lattice_bits < 0) throw InputError("lattice bits must be >= 0");
}

const SturmSequence& LatticeRootSolver::sturm() const {
  if (sturm_) return *sturm_;
  sturm_.emplace(p_);
  // Cauchy bound: |r| < 1 + max|ci/cn| ≤ 2^(bitlen(max|ci|) − bitlen(|cn|) + 2).
  const Polynomial& q = sturm_->square_free();
  std::int64_t top = 0;
  for (const auto& c : q.coefficients()) top = std::max(top, exact::bit_length(c));
  std::int64_t e = std::max<std::int64_t>(0, top - exact::bit_length(q.leading()) + 2);
  root_bound_k_ = Integer(1) << static_cast<unsigned>(e + bits_);
  return *sturm_;
}

int LatticeRootSolver::roots_below_lattice(const Integer& k) const {
  ++sturm_queries;
  return sturm().roots_below(k, bits_);
}

int LatticeRootSolver::sign_before_lattice(const Integer& k) const {
  // p(kδ) ≠ 0 decides at once (filtered); otherwise the first non-vanishing derivative does.
  int s = filtered_sign_at(p_, p_approx_, k, bits_);
  return s != 0 ? s : sign_before(p_, lattice_point(k));
}

bool LatticeRootSolver::sign_changes_across(const Integer& k) const {
  return sign_before_lattice(k) != sign_before_lattice(k + 1);
}

std::pair<Integer, Integer> LatticeRootSolver::clamp_range(const Integer& lo, const Integer& hi) const {
  sturm();  // sets root_bound_k_
  Integer a = lo < -root_bound_k_ ? Integer(-root_bound_k_) : lo;
  Integer b = hi > root_bound_k_ ? root_bound_k_ : hi;
  return {a, b};
}

template <class Visit>
bool LatticeRootSolver::scan(const Integer& a, const Integer& b, int ca, int cb, Visit& visit) const {
  if (cb == ca) return false;
  if (b - a == 1) return visit(LatticeInterval{a, cb - ca, sign_changes_across(a)});
  const Polynomial& q = sturm().square_free();
  if (q.degree() == 1) {
    // One simple root r = −c0/c1, known to lie in [aδ, bδ): its interval is floor(r·2^b) in closed form.
    // den > 0: the square-free part has a positive leading coefficient (the constructor makes it so).
    Integer num = -q[0] << static_cast<unsigned>(bits_), den = q[1];
    Integer k = num / den;
    if (k * den > num) k -= 1;  // floor for negative quotients
    KMR_CHECK(a <= k && k < b, "linear root outside the counted range");
    return visit(LatticeInterval{k, 1, sign_changes_across(k)});
  }
  Integer mid = (a + b) >> 1;  // floor for negatives too
  int cm = roots_below_lattice(mid);
  if (scan(a, mid, ca, cm, visit)) return true;
  return scan(mid, b, cm, cb, visit);
}

std::vector<LatticeInterval> LatticeRootSolver::isolate(const Dyadic& from, const Dyadic& to) const {
  std::vector<LatticeInterval> out;
  auto [a, b] = clamp_range(lattice_ceil(from, bits_), lattice_ceil(to, bits_));
  if (a >= b) return out;
  auto collect = [&](LatticeInterval i) {
    out.push_back(std::move(i));
    return false;
  };
  scan(a, b, roots_below_lattice(a), roots_below_lattice(b), collect);
  return out;
}

std::optional<Integer> LatticeRootSolver::next_failure_after(const Dyadic& t, const Dyadic& horizon,
                                                             bool zero_fails) const {
  auto [a, b] = clamp_range(lattice_ceil(t, bits_), lattice_ceil(horizon, bits_));
  if (a >= b) return std::nullopt;
  std::optional<Integer> found;
  auto first_change = [&](LatticeInterval i) {
    bool zero_start = zero_fails && lattice_point(i.k) > t && filtered_sign_at(p_, p_approx_, i.k, bits_) == 0;
    if (!i.sign_change && !zero_start) return false;
    found = i.k;
    return true;
  };
  scan(a, b, roots_below_lattice(a), roots_below_lattice(b), first_change);
  return found;
}

}  // namespace kmr::poly
