#include "exclusion.hpp"

#include <Eigen/Core>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <tuple>

#include "rounded_interval.hpp"

namespace relpos::complete::detail {
namespace {

// Krawczyk's test is tried on boxes no wider than this fraction of the domain in the primary
// variables: on wider ones its linearisation rarely decides and costs the most.
constexpr double kKrawczykWidth = 1.0 / 16.0;

struct Box {
  FI x[kMaxVariables];
};

enum class Verdict { kNoRoot, kOneRoot, kUndecided };

// Y = A⁻¹ (n × n, row-major) by Gauss-Jordan with partial pivoting; false when A is singular to
// working precision. Any Y will do for Krawczyk's test (only the bounds must be rigorous): an
// approximate inverse, computed in whatever rounding mode is on.
bool invert(const double* A, int n, double* Y) {
  double a[kMaxVariables * kMaxVariables];
  for (int k = 0; k < n * n; ++k) a[k] = A[k], Y[k] = 0.0;
  for (int i = 0; i < n; ++i) Y[i * n + i] = 1.0;
  for (int col = 0; col < n; ++col) {
    int p = col;
    for (int i = col + 1; i < n; ++i)
      if (std::abs(a[i * n + col]) > std::abs(a[p * n + col])) p = i;
    const double pivot = a[p * n + col];
    if (!(std::abs(pivot) > 0.0) || !std::isfinite(pivot)) return false;
    if (p != col)
      for (int j = 0; j < n; ++j) {
        std::swap(a[p * n + j], a[col * n + j]);
        std::swap(Y[p * n + j], Y[col * n + j]);
      }
    const double inv = 1.0 / pivot;
    for (int j = 0; j < n; ++j) a[col * n + j] *= inv, Y[col * n + j] *= inv;
    for (int i = 0; i < n; ++i) {
      if (i == col) continue;
      const double f = a[i * n + col];
      if (f == 0.0) continue;
      for (int j = 0; j < n; ++j) a[i * n + j] -= f * a[col * n + j], Y[i * n + j] -= f * Y[col * n + j];
    }
  }
  for (int k = 0; k < n * n; ++k)
    if (!std::isfinite(Y[k])) return false;
  return true;
}


// Krawczyk's operator on boxes of any shape (Rump's form, as krawczyk.hpp, with a radius per
// coordinate): for the centre c, r the half-widths and Y ≈ mid(J(X))⁻¹,
// K = c − Y F(c) + (I − Y J(X)) [−r, r]. Every root in X lies in K; K ∩ X = ∅ proves none;
// K ⊂ int X proves exactly one. All of it runs under the caller's RoundUp.
class Krawczyk {
 public:
  Krawczyk(const SystemShape& shape, const FI* coefficients)
      : shape_(shape),
        n_(shape.variables),
        coeffs_(coefficients, coefficients + shape.terms.size()),
        values_(shape_.nodes()),
        f_(n_),
        J_(n_ * n_) {}

  // X is replaced by K ∩ X when undecided (every root of X is still in it).
  Verdict test(Box& X) {
    evaluateBox(shape_, coeffs_.data(), X.x, values_.data(), f_.data(), J_.data());
    for (int i = 0; i < n_; ++i) {
      if (!std::isfinite(f_[i].lower()) || !std::isfinite(f_[i].upper())) return Verdict::kUndecided;
      if (f_[i].lower() > 0.0 || f_[i].upper() < 0.0) return Verdict::kNoRoot;
    }
    // Y = mid(J)⁻¹; then |I − Y J| ≤ |I − Y Jm| + |Y| Jr over the box, J = Jm ± Jr (Rump's
    // midpoint-radius form: three products of doubles instead of n³ interval products), the
    // rounding of Y Jm bounded by γ |Y| |Jm|. Every bound is computed rounding upward.
    const int n = n_;
    double Jm[kMaxVariables * kMaxVariables], Jr[kMaxVariables * kMaxVariables];
    double Y[kMaxVariables * kMaxVariables];
    for (int k = 0; k < n * n; ++k) {
      Jm[k] = midpoint(J_[k]);
      Jr[k] = std::max(J_[k].upper() - Jm[k], Jm[k] - J_[k].lower());
      if (!std::isfinite(Jm[k]) || !std::isfinite(Jr[k])) return Verdict::kUndecided;
    }
    if (!invert(Jm, n, Y)) return Verdict::kUndecided;
    FI c[kMaxVariables], fc[kMaxVariables];
    double r[kMaxVariables];
    for (int i = 0; i < n; ++i) {
      const double m = midpoint(X.x[i]);
      c[i] = FI(m);
      r[i] = std::max(X.x[i].upper() - m, m - X.x[i].lower());  // upward: bounds the reach
    }
    evaluateBox(shape_, coeffs_.data(), c, values_.data(), fc, static_cast<FI*>(nullptr));
    // γ_{n+2} for directed rounding (unit 2⁻⁵², each operation off by less than one unit).
    const double gamma = (n + 2) * 0x1p-52 / (1.0 - (n + 2) * 0x1p-52);
    bool inside = true, disjoint = false;
    FI K[kMaxVariables];
    for (int i = 0; i < n; ++i) {
      FI a(0.0);
      for (int k = 0; k < n; ++k) a = a - Y[i * n + k] * fc[k];
      double s = 0.0;
      for (int j = 0; j < n; ++j) {
        double p = 0.0, abs_m = 0.0, abs_r = 0.0;
        for (int k = 0; k < n; ++k) {
          const double y = Y[i * n + k];
          p += y * Jm[k * n + j];
          abs_m += std::abs(y) * std::abs(Jm[k * n + j]);
          abs_r += std::abs(y) * Jr[k * n + j];
        }
        const double d = i == j ? 1.0 : 0.0;
        const double bound = std::max(d - p, p - d) + abs_r + gamma * abs_m;
        s += bound * r[j];
      }
      if (!std::isfinite(s) || !std::isfinite(a.lower()) || !std::isfinite(a.upper()))
        return Verdict::kUndecided;
      K[i] = c[i] + a + FI(-s, s);
      inside = inside && K[i].lower() > X.x[i].lower() && K[i].upper() < X.x[i].upper();
      disjoint = disjoint || K[i].upper() < X.x[i].lower() || K[i].lower() > X.x[i].upper();
    }
    if (disjoint) return Verdict::kNoRoot;
    if (inside) return Verdict::kOneRoot;
    for (int i = 0; i < n_; ++i) X.x[i] = intersect(X.x[i], K[i]);
    return Verdict::kUndecided;
  }

 private:
  CompiledShape shape_;
  int n_;
  std::vector<FI> coeffs_, values_, f_, J_;
};

// [√lo, √hi] under the caller's upward rounding: std::sqrt rounds up, so the double below it
// is a lower bound. (Boost's sqrt switches the rounding mode twice per call.)
FI sqrtUp(double lo, double hi) {
  const double low = std::sqrt(lo);
  return FI(low > 0.0 ? std::nextafter(low, 0.0) : 0.0, std::sqrt(hi));
}

// One term c · x_vars[0] ⋯ x_vars[degree−1] (variables sorted).
struct Term {
  FI c;
  std::uint8_t degree = 0;
  std::array<std::uint8_t, kMaxMonomialDegree> vars{};
  std::uint16_t monomial = 0;  // its index in the contractor's table of distinct monomials
};
using Equation = std::vector<Term>;

// The monomial over the box, each run of one variable as a power (x² ≥ 0 is kept).
FI monomialValue(const Term& t, const FI* x) {
  FI v(1.0);
  for (int i = 0; i < t.degree;) {
    int j = i;
    while (j < t.degree && t.vars[j] == t.vars[i]) ++j;
    const int power = j - i;
    v = v * (power == 1 ? x[t.vars[i]] : power == 2 ? square(x[t.vars[i]]) : pow(x[t.vars[i]], power));
    i = j;
  }
  return v;
}

// The equation linear in the secondary variables: Σ a_j(x) s_j + b(x) = 0, where a_j are the
// terms holding secondary s_j once (s_j removed) and b the rest (terms free of secondary
// variables, and any of higher degree in them, enclosed over the whole box).
struct LinearRow {
  std::vector<Term> rest;
  std::vector<std::pair<int, Term>> linear;  // (index among the secondary variables, a term)
};

// Whether the (sorted) term holds variable v more than once, or holds none of `mask`.
int degreeIn(const Term& t, const std::vector<bool>& mask) {
  int d = 0;
  for (int i = 0; i < t.degree; ++i) d += mask[t.vars[i]] ? 1 : 0;
  return d;
}

class Contractor {
 public:
  Contractor(const SystemShape& shape, const FI* coefficients, const std::vector<bool>& secondary)
      : n_(shape.variables), secondary_(secondary) {
    if (static_cast<int>(secondary_.size()) != n_) secondary_.assign(n_, false);
    for (int v = 0; v < n_; ++v)
      if (secondary_[v]) index_of_[v] = static_cast<int>(secondaries_.size()), secondaries_.push_back(v);
    equations_.resize(n_);
    for (std::size_t t = 0; t < shape.terms.size(); ++t) {
      const Monomial& m = shape.monomials[shape.terms[t].monomial];
      Term term;
      term.c = coefficients[t];
      term.degree = m.degree;
      for (int i = 0; i < m.degree; ++i) term.vars[i] = m.vars[i];
      if (term.c.lower() == 0.0 && term.c.upper() == 0.0) continue;
      equations_[shape.terms[t].equation].push_back(term);
    }
    if (!secondaries_.empty()) buildLinearRows();
    for (Equation& e : equations_)
      for (Term& t : e) intern(t);
    for (LinearRow& row : rows_) {
      for (Term& t : row.rest) intern(t);
      for (auto& [j, t] : row.linear) intern(t);
    }
  }

  // Contracts X by every contractor until they stop paying; false when X holds no root.
  bool contract(Box& X) {
    for (int round = 0; round < 2; ++round) {
      double before[kMaxVariables];
      for (int i = 0; i < n_; ++i) before[i] = width(X.x[i]);
      if (!project(X) || !gaussSeidel(X)) return false;
      bool shrank = false;
      for (int i = 0; i < n_; ++i) shrank = shrank || width(X.x[i]) < 0.8 * before[i];
      if (!shrank) break;
    }
    return true;
  }

 private:
  // Each distinct monomial once over the box (the equations share most of them).
  void evaluateMonomials(const Box& X) {
    for (std::size_t i = 0; i < monomials_.size(); ++i)
      monomial_values_[i] = monomialValue(monomials_[i], X.x);
  }

  void intern(Term& t) {
    const std::uint32_t key = keyOf(t);
    auto it = monomial_index_.find(key);
    if (it == monomial_index_.end()) {
      it = monomial_index_.emplace(key, static_cast<std::uint16_t>(monomials_.size())).first;
      monomials_.push_back(t);
      monomial_values_.emplace_back(0.0);
    }
    t.monomial = it->second;
  }

  // x_i^k ∈ −(Σ others) / c for each term c x_i^k (k ≤ 2) alone in its variable (the terms
  // enclosed over the box as it was on entry: later projections only make them looser).
  bool project(Box& X) {
    evaluateMonomials(X);
    for (const Equation& e : equations_) {
      const std::size_t T = e.size();
      values_.resize(T);
      before_.resize(T + 1);
      after_.resize(T + 1);
      for (std::size_t t = 0; t < T; ++t) values_[t] = e[t].c * monomial_values_[e[t].monomial];
      before_[0] = FI(0.0);
      for (std::size_t t = 0; t < T; ++t) before_[t + 1] = before_[t] + values_[t];
      if (before_[T].lower() > 0.0 || before_[T].upper() < 0.0) return false;
      after_[T] = FI(0.0);
      for (std::size_t t = T; t-- > 0;) after_[t] = after_[t + 1] + values_[t];
      for (std::size_t t = 0; t < T; ++t) {
        const Term& term = e[t];
        if (term.degree == 0 || term.degree > 2 || term.vars[0] != term.vars[term.degree - 1])
          continue;
        if (term.c.lower() <= 0.0 && term.c.upper() >= 0.0) continue;
        const FI rhs = -(before_[t] + after_[t + 1]) / term.c;
        FI& x = X.x[term.vars[0]];
        if (term.degree == 1) {
          if (!overlap(x, rhs)) return false;
          x = intersect(x, rhs);
          continue;
        }
        if (rhs.upper() < 0.0) return false;
        const FI root = sqrtUp(std::max(rhs.lower(), 0.0), rhs.upper());
        const FI neg = -root;
        const bool p = overlap(x, root), q = overlap(x, neg);
        if (!p && !q) return false;
        x = p && q ? hull(intersect(x, root), intersect(x, neg))
                   : intersect(x, p ? root : neg);
      }
    }
    return true;
  }

  // Preconditioned interval Gauss-Seidel on the secondary variables, from the linear rows.
  bool gaussSeidel(Box& X) {
    const int m = static_cast<int>(secondaries_.size());
    const int L = std::min(static_cast<int>(rows_.size()), kMaxVariables);
    if (m == 0 || L < m) return true;
    std::vector<FI>& A = A_;
    A.assign(static_cast<std::size_t>(L) * m, FI(0.0));
    b_.assign(L, FI(0.0));
    RMat Am(L, m);
    evaluateMonomials(X);
    for (int k = 0; k < L; ++k) {
      for (const Term& t : rows_[k].rest) b_[k] = b_[k] + t.c * monomial_values_[t.monomial];
      for (const auto& [j, t] : rows_[k].linear)
        A[k * m + j] = A[k * m + j] + t.c * monomial_values_[t.monomial];
      for (int j = 0; j < m; ++j) Am(k, j) = midpoint(A[k * m + j]);
    }
    if (!Am.allFinite()) return true;
    // Y ≈ pseudo-inverse of mid A, (AᵀA)⁻¹ Aᵀ: Y A ≈ I.
    double normal[kMaxVariables * kMaxVariables], inverse[kMaxVariables * kMaxVariables];
    for (int i = 0; i < m; ++i)
      for (int j = 0; j < m; ++j) normal[i * m + j] = Am.col(i).dot(Am.col(j));
    if (!invert(normal, m, inverse)) return true;
    const RMat Y = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic,
                                                  Eigen::RowMajor, kMaxVariables, kMaxVariables>>(
                       inverse, m, m) *
                   Am.transpose();
    if (!Y.allFinite()) return true;
    for (int j = 0; j < m; ++j) {
      FI r(0.0);
      for (int k = 0; k < L; ++k) r = r - Y(j, k) * b_[k];
      FI diag(0.0), off(0.0);
      for (int l = 0; l < m; ++l) {
        FI M(0.0);
        for (int k = 0; k < L; ++k) M = M + Y(j, k) * A[k * m + l];
        if (l == j)
          diag = M;
        else
          off = off + M * X.x[secondaries_[l]];
      }
      if (diag.lower() <= 0.0 && diag.upper() >= 0.0) continue;
      const FI s = (r - off) / diag;
      FI& x = X.x[secondaries_[j]];
      if (!std::isfinite(s.lower()) || !std::isfinite(s.upper())) continue;
      if (!overlap(x, s)) return false;
      x = intersect(x, s);
    }
    return true;
  }

  // The rows of the Gauss-Seidel step: each equation free of products of secondary variables,
  // and the differences of equations whose products of them are proportional with constant
  // coefficients (two point-point distances: 4 g·g each). Another equation's quadratic part
  // would be enclosed over the whole secondary box, which pins nothing: left out.
  void buildLinearRows() {
    std::vector<std::pair<const Equation*, std::map<std::uint32_t, double>>> quadratic;
    for (const Equation& e : equations_) {
      bool pure = true, linear = true;
      std::map<std::uint32_t, double> q;
      for (const Term& t : e) {
        const int d = degreeIn(t, secondary_);
        if (d < 2) continue;
        linear = false;
        if (d != 2 || t.degree != 2) pure = false;
        q[keyOf(t)] = midpoint(t.c);
      }
      if (linear)
        addRow(e);
      else if (pure)
        quadratic.push_back({&e, std::move(q)});
    }
    // Each pure quadratic equation minus the first one proportional to it.
    for (std::size_t a = 0; a < quadratic.size(); ++a)
      for (std::size_t b = 0; b < a; ++b) {
        const double lambda = proportion(quadratic[a].second, quadratic[b].second);
        if (!std::isfinite(lambda)) continue;
        addRow(difference(*quadratic[a].first, lambda, *quadratic[b].first));
        break;
      }
  }

  static std::uint32_t keyOf(const Term& t) {
    std::uint32_t k = t.degree;
    for (int i = 0; i < t.degree; ++i) k = k * 16 + t.vars[i] + 1;
    return k;
  }

  // λ with p = λ q (coefficients equal to 1e-12 relative), or NaN.
  static double proportion(const std::map<std::uint32_t, double>& p,
                           const std::map<std::uint32_t, double>& q) {
    if (p.size() != q.size() || p.empty()) return std::nan("");
    const double lambda = p.begin()->second / q.begin()->second;
    for (auto i = p.begin(), j = q.begin(); i != p.end(); ++i, ++j)
      if (i->first != j->first ||
          std::abs(i->second - lambda * j->second) > 1e-12 * std::abs(i->second))
        return std::nan("");
    return std::isfinite(lambda) ? lambda : std::nan("");
  }

  // a − λ b (a consequence of a = 0 and b = 0 for any λ), terms merged by monomial.
  static Equation difference(const Equation& a, double lambda, const Equation& b) {
    std::map<std::uint32_t, Term> merged;
    for (const Term& t : a) merged.emplace(keyOf(t), t);
    for (const Term& t : b) {
      Term scaled = t;
      scaled.c = -(FI(lambda) * t.c);
      const auto [it, fresh] = merged.emplace(keyOf(t), scaled);
      if (!fresh) it->second.c = it->second.c + scaled.c;
    }
    Equation out;
    for (auto& [key, t] : merged) out.push_back(t);
    return out;
  }

  void addRow(const Equation& e) {
    LinearRow row;
    for (const Term& t : e) {
      const int d = degreeIn(t, secondary_);
      if (d != 1) {
        row.rest.push_back(t);
        continue;
      }
      Term rest;
      rest.c = t.c;
      int which = -1;
      for (int i = 0; i < t.degree; ++i) {
        if (secondary_[t.vars[i]])
          which = index_of_[t.vars[i]];
        else
          rest.vars[rest.degree++] = t.vars[i];
      }
      row.linear.push_back({which, rest});
    }
    if (!row.linear.empty()) rows_.push_back(std::move(row));
  }

  int n_;
  std::vector<bool> secondary_;
  std::vector<int> secondaries_;
  std::map<int, int> index_of_;
  std::vector<Equation> equations_;
  std::vector<LinearRow> rows_;
  std::vector<Term> monomials_;  // distinct monomials (their coefficients unused)
  std::map<std::uint32_t, std::uint16_t> monomial_index_;
  std::vector<FI> monomial_values_, values_, before_, after_, A_, b_;
};

Box boxOf(const RealBox& b, int n) {
  Box out;
  for (int i = 0; i < n; ++i) out.x[i] = FI(b.lo[i], b.hi[i]);
  return out;
}

bool contains(const Box& outer, const Box& inner, int n) {
  for (int i = 0; i < n; ++i)
    if (!subset(inner.x[i], outer.x[i])) return false;
  return true;
}

bool meets(const Box& a, const Box& b, int n) {
  for (int i = 0; i < n; ++i)
    if (!overlap(a.x[i], b.x[i])) return false;
  return true;
}

// The largest cube about a known root's enclosure, from a ladder of radii, in which Krawczyk
// proves exactly one root (that root is the known one: its enclosure is inside). Boxes of the
// branch and prune inside it need no test of their own, which also settles the boxes that a
// bisection plane through the root would leave undecided forever.
bool uniquenessBox(Krawczyk& k, const Box& known, const Box& domain, int n, Box* out) {
  double centre[kMaxVariables], reach = 0.0, span = 0.0;
  for (int i = 0; i < n; ++i) {
    centre[i] = midpoint(known.x[i]);
    reach = std::max(reach, width(known.x[i]));
    span = std::max(span, width(domain.x[i]));
  }
  bool found = false;
  for (double rho = std::max(2.0 * reach, 1e-12 * span); rho <= 0.25 * span; rho *= 4.0) {
    Box u;
    for (int i = 0; i < n; ++i) u.x[i] = FI(centre[i]) + FI(-rho, rho);
    Box tested = u;
    if (!contains(u, known, n) || k.test(tested) != Verdict::kOneRoot) {
      if (found) break;
      continue;  // the smallest radii may be below what the coefficients' enclosures allow
    }
    *out = u;
    found = true;
  }
  return found;
}

}  // namespace

ExclusionResult excludeUnknownRoots(const SystemShape& shape, const Interval* coefficients,
                                   const RealBox& domain, const std::vector<RealBox>& known,
                                   const std::vector<bool>& secondary,
                                   const std::vector<int>& negated,
                                   const ExclusionOptions& options) {
  ExclusionResult result;
  const int n = shape.variables;
  RoundUp up;
  std::vector<FI> coeffs;
  for (std::size_t t = 0; t < shape.terms.size(); ++t)
    coeffs.emplace_back(coefficients[t].lower(), coefficients[t].upper());
  Krawczyk krawczyk(shape, coeffs.data());
  Contractor contractor(shape, coeffs.data(), secondary);
  std::vector<bool> is_secondary = secondary;
  is_secondary.resize(n, false);
  const Box whole = boxOf(domain, n);
  double span[kMaxVariables];
  for (int i = 0; i < n; ++i) span[i] = width(whole.x[i]);

  std::vector<Box> roots, unique;
  for (const RealBox& k : known) {
    roots.push_back(boxOf(k, n));
    Box u;
    if (uniquenessBox(krawczyk, roots.back(), whole, n, &u)) unique.push_back(u);
  }
  auto fail = [&](std::string why) {
    result.why = std::move(why);
    return result;
  };
  // The symmetry's image of each known root holds a root: it must be a known one, the one of a
  // uniqueness box holding the image.
  for (const Box& r : roots) {
    if (negated.empty()) break;
    Box image = r;
    for (int v : negated) image.x[v] = -r.x[v];
    bool known_image = false;
    for (const Box& u : unique) known_image = known_image || contains(u, image, n);
    if (!known_image) return fail("the mirror image of a root found is not among them");
  }
  auto inUniquenessBox = [&](const Box& X) {
    for (const Box& u : unique)
      if (contains(u, X, n)) return true;
    return false;
  };
  // A box that meets a uniqueness box without lying in it: one root in their hull (Krawczyk)
  // is the known one, so the box holds no other. Saves refining the boxes along the uniqueness
  // box's faces, where most of the search's boxes would otherwise go.
  auto nearKnownRoot = [&](const Box& X) {
    for (const Box& u : unique) {
      if (!meets(u, X, n)) continue;
      Box h;
      for (int i = 0; i < n; ++i) h.x[i] = hull(u.x[i], X.x[i]);
      return krawczyk.test(h) == Verdict::kOneRoot;
    }
    return false;
  };

  std::vector<Box> stack = {whole};
  while (!stack.empty()) {
    Box X = stack.back();
    stack.pop_back();
    if (++result.boxes > options.max_boxes)
      return fail("the interval proof gave up after " + std::to_string(options.max_boxes) +
                  " boxes");
    if (inUniquenessBox(X) || !contractor.contract(X) || inUniquenessBox(X) || nearKnownRoot(X))
      continue;
    // Krawczyk once the box is small enough for its linearisation to decide.
    bool settled = false;
    double primary_width = 0.0;
    for (int j = 0; j < n; ++j)
      if (!is_secondary[j]) primary_width = std::max(primary_width, width(X.x[j]) / span[j]);
    for (int round = 0; round < 4 && !settled && primary_width <= kKrawczykWidth; ++round) {
      double before[kMaxVariables];
      for (int i = 0; i < n; ++i) before[i] = width(X.x[i]);
      const Verdict v = krawczyk.test(X);
      if (v == Verdict::kNoRoot) {
        settled = true;
      } else if (v == Verdict::kOneRoot) {
        for (const Box& r : roots) settled = settled || contains(X, r, n);
        if (settled) break;
        bool near_known = false;
        for (const Box& r : roots) near_known = near_known || meets(X, r, n);
        for (const Box& u : unique) near_known = near_known || meets(X, u, n);
        // One root there, and no known root near: a real root the homotopy did not return.
        if (!near_known) return fail("a real root of the encoding that was not found");
        break;  // split until the known root's enclosure or uniqueness box takes it
      } else {
        if (inUniquenessBox(X)) settled = true;
        bool shrank = false;
        for (int i = 0; i < n; ++i) shrank = shrank || width(X.x[i]) < 0.5 * before[i];
        if (!shrank) break;
      }
    }
    if (settled) continue;
    // Split the widest primary variable (relative to the domain), or a secondary one the
    // contractors left much wider.
    int split = 0;
    double primary = -1.0, secondary_max = -1.0, widest = 0.0;
    int split_primary = -1, split_secondary = -1;
    for (int j = 0; j < n; ++j) {
      const double w = width(X.x[j]) / span[j];
      widest = std::max(widest, w);
      if (is_secondary[j]) {
        if (w > secondary_max) secondary_max = w, split_secondary = j;
      } else if (w > primary) {
        primary = w, split_primary = j;
      }
    }
    split = split_primary < 0 || (split_secondary >= 0 && secondary_max > 4.0 * primary)
                ? split_secondary
                : split_primary;
    if (!(widest > options.min_width))
      return fail("an undecided box too narrow to split (a singular root or a set of roots)");
    Box lower = X, upper = X;
    std::tie(lower.x[split], upper.x[split]) = halves(X.x[split]);
    stack.push_back(upper);
    stack.push_back(lower);
  }
  result.proven = true;
  return result;
}

}  // namespace relpos::complete::detail
