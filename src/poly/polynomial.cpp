#include "poly/polynomial.hpp"

#include <algorithm>
#include <sstream>

#include "exact/error.hpp"

namespace kmr::poly {

Polynomial::Polynomial(Integer c) {
  if (!c.is_zero()) c_.push_back(std::move(c));
}

Polynomial::Polynomial(std::vector<Integer> coefficients) : c_(std::move(coefficients)) { trim(); }

void Polynomial::trim() {
  while (!c_.empty() && c_.back().is_zero()) c_.pop_back();
}

Polynomial Polynomial::monomial(Integer c, int k) {
  std::vector<Integer> v(static_cast<std::size_t>(k) + 1);
  v.back() = std::move(c);
  return Polynomial(std::move(v));
}

Polynomial Polynomial::linear_with_root(const Dyadic& x) {
  if (x.exponent() >= 0) return Polynomial(std::vector<Integer>{Integer(-x.floor()), Integer(1)});
  Integer denominator = Integer(1) << static_cast<unsigned>(-x.exponent());
  return Polynomial(std::vector<Integer>{Integer(-x.mantissa()), denominator});
}

Polynomial operator+(const Polynomial& a, const Polynomial& b) {
  std::vector<Integer> r(std::max(a.c_.size(), b.c_.size()));
  for (std::size_t i = 0; i < a.c_.size(); ++i) r[i] = a.c_[i];
  for (std::size_t i = 0; i < b.c_.size(); ++i) r[i] += b.c_[i];
  return Polynomial(std::move(r));
}

Polynomial operator-(const Polynomial& a, const Polynomial& b) { return a + (-b); }

Polynomial Polynomial::operator-() const {
  Polynomial r = *this;
  for (auto& c : r.c_) c = -c;
  return r;
}

Polynomial operator*(const Polynomial& a, const Polynomial& b) {
  if (a.is_zero() || b.is_zero()) return Polynomial();
  std::vector<Integer> r(a.c_.size() + b.c_.size() - 1);
  for (std::size_t i = 0; i < a.c_.size(); ++i)
    for (std::size_t j = 0; j < b.c_.size(); ++j) r[i + j] += a.c_[i] * b.c_[j];
  return Polynomial(std::move(r));
}

Polynomial operator*(const Integer& k, const Polynomial& p) {
  std::vector<Integer> r(p.c_);
  for (auto& c : r) c *= k;
  return Polynomial(std::move(r));
}

Polynomial Polynomial::derivative() const {
  if (c_.size() <= 1) return Polynomial();
  std::vector<Integer> r(c_.size() - 1);
  for (std::size_t i = 1; i < c_.size(); ++i) r[i - 1] = c_[i] * static_cast<long>(i);
  return Polynomial(std::move(r));
}

Polynomial Polynomial::mirrored() const {
  Polynomial r = *this;
  for (std::size_t i = 1; i < r.c_.size(); i += 2) r.c_[i] = -r.c_[i];
  return r;
}

Polynomial Polynomial::shifted_by(const Integer& a) const {
  // Horner in polynomial arithmetic: p(t + a) = (...(cn·(t+a) + c_{n−1})·(t+a) + ...).
  Polynomial x(std::vector<Integer>{a, Integer(1)}), r;
  for (auto it = c_.rbegin(); it != c_.rend(); ++it) r = r * x + Polynomial(*it);
  return r;
}

Integer Polynomial::content() const {
  Integer g(0);
  for (const auto& c : c_) {
    g = boost::multiprecision::gcd(g, c);
    if (g == 1) break;
  }
  return abs(g);
}

Polynomial Polynomial::primitive_part() const {
  if (is_zero()) return *this;
  Integer g = content();
  if (g == 1) return *this;
  Polynomial r = *this;
  for (auto& c : r.c_) c /= g;
  return r;
}

Integer Polynomial::evaluate(const Integer& t) const {
  Integer acc(0);
  for (auto it = c_.rbegin(); it != c_.rend(); ++it) acc = acc * t + *it;
  return acc;
}

int Polynomial::sign_at(const Integer& m, long long s) const {
  KMR_CHECK(s >= 0, "sign_at needs s >= 0");
  if (s == 0) return evaluate(m).sign();
  // 2^(s·n)·p(m/2^s) = Σ ci·m^i·2^(s·(n−i)): Horner on the homogenized form.
  int n = degree();
  if (n < 0) return 0;
  Integer acc = c_.back();
  for (int i = n - 1; i >= 0; --i) {
    acc *= m;
    if (!c_[static_cast<std::size_t>(i)].is_zero())
      acc += c_[static_cast<std::size_t>(i)] << static_cast<unsigned>(s * (n - i));
  }
  return acc.sign();
}

int Polynomial::sign_at(const Dyadic& t) const {
  if (t.exponent() >= 0) return evaluate(t.floor()).sign();
  return sign_at(t.mantissa(), -t.exponent());
}

std::string Polynomial::to_string() const {
  if (is_zero()) return "0";
  std::ostringstream out;
  bool first = true;
  for (int i = degree(); i >= 0; --i) {
    const Integer& c = c_[static_cast<std::size_t>(i)];
    if (c.is_zero()) continue;
    out << (first ? (c.sign() < 0 ? "-" : "") : (c.sign() < 0 ? " - " : " + "));
    Integer a = abs(c);
    if (a != 1 || i == 0) out << a;
    if (i >= 1) out << (a != 1 ? "·t" : "t");
    if (i >= 2) out << "^" << i;
    first = false;
  }
  return out.str();
}

Polynomial pseudo_remainder(const Polynomial& a, const Polynomial& b) {
  if (b.is_zero()) throw ContractError("pseudo_remainder by the zero polynomial");
  int db = b.degree();
  if (a.degree() < db) return a;
  std::vector<Integer> r = a.coefficients();
  const auto& bc = b.coefficients();
  const Integer& lb = b.leading();
  int steps = a.degree() - db + 1;
  // Each step: r ← lb·r − lc(r)·t^(deg r − db)·b, which cancels r's leading term.
  for (int deg = a.degree(); deg >= db; --deg) {
    Integer lr = r[static_cast<std::size_t>(deg)];
    for (auto& c : r) c *= lb;
    if (!lr.is_zero())
      for (int j = 0; j <= db; ++j) r[static_cast<std::size_t>(deg - db + j)] -= lr * bc[static_cast<std::size_t>(j)];
    --steps;
  }
  KMR_CHECK(steps == 0, "pseudo_remainder step count");
  r.resize(static_cast<std::size_t>(db));
  return Polynomial(std::move(r));
}

Polynomial exact_quotient(const Polynomial& a, const Polynomial& b) {
  if (b.is_zero()) throw ContractError("exact_quotient by the zero polynomial");
  if (a.degree() < b.degree()) {
    KMR_CHECK(a.is_zero(), "exact_quotient: divisor does not divide");
    return Polynomial();
  }
  std::vector<Integer> r = a.coefficients();
  std::vector<Integer> q(static_cast<std::size_t>(a.degree() - b.degree() + 1));
  const auto& bc = b.coefficients();
  int db = b.degree();
  for (int deg = a.degree(); deg >= db; --deg) {
    Integer quotient, remainder;
    boost::multiprecision::divide_qr(r[static_cast<std::size_t>(deg)], b.leading(), quotient, remainder);
    KMR_CHECK(remainder.is_zero(), "exact_quotient: coefficient not divisible");
    q[static_cast<std::size_t>(deg - db)] = quotient;
    for (int j = 0; j <= db; ++j) r[static_cast<std::size_t>(deg - db + j)] -= quotient * bc[static_cast<std::size_t>(j)];
  }
  for (const auto& c : r) KMR_CHECK(c.is_zero(), "exact_quotient: nonzero remainder");
  return Polynomial(std::move(q));
}

Polynomial gcd(const Polynomial& a, const Polynomial& b) {
  // Primitive polynomial remainder sequence: exact, with coefficients kept small.
  Polynomial x = a.primitive_part(), y = b.primitive_part();
  if (x.degree() < y.degree()) std::swap(x, y);
  while (!y.is_zero()) {
    Polynomial r = pseudo_remainder(x, y).primitive_part();
    x = std::move(y);
    y = std::move(r);
  }
  if (x.sign() < 0) x = -x;
  return x;
}

Polynomial square_free_part(const Polynomial& p) {
  if (p.degree() <= 0) return p.is_zero() ? p : Polynomial(1);
  Polynomial g = gcd(p, p.derivative());
  Polynomial q = g.degree() == 0 ? p.primitive_part() : exact_quotient(p.primitive_part(), g);
  return q.sign() < 0 ? -q : q;
}

namespace {
// Sign of the first non-vanishing derivative at t and its order k.
std::pair<int, int> first_nonvanishing_derivative(const Polynomial& p, const Dyadic& t) {
  if (p.is_zero()) throw InputError("identically zero polynomial: its sign is undefined");
  Polynomial d = p;
  for (int k = 0;; ++k) {
    int s = d.sign_at(t);
    if (s != 0) return {s, k};
    d = d.derivative();
  }
}
}  // namespace

int sign_before(const Polynomial& p, const Dyadic& t) {
  auto [s, k] = first_nonvanishing_derivative(p, t);
  return k % 2 == 0 ? s : -s;
}

int sign_after(const Polynomial& p, const Dyadic& t) { return first_nonvanishing_derivative(p, t).first; }

}  // namespace kmr::poly
