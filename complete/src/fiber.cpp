// solveFiber: every start root tracked to the real target along a γ arc, every finite endpoint
// polished on the target's own coefficients and certified by Krawczyk against interval
// enclosures of those coefficients; a certified box that meets one already kept is taken as the
// same root (a count too low only ever says "not complete"). Missing roots: all paths again with
// another γ. N pairwise disjoint certified boxes, N the family's root count, prove the list
// complete (a member has at most N isolated roots: Morgan & Sommese 1989).
#include "relpos/complete/fiber.hpp"

#include <algorithm>
#include <cmath>
#include <thread>

#include "homotopy.hpp"
#include "krawczyk.hpp"
#include "random.hpp"

namespace relpos::complete {
namespace {

// Real roots first, then by coordinates (real part, then imaginary), for a stable order.
bool before(const CertifiedRoot& a, const CertifiedRoot& b) {
  if (a.real != b.real) return a.real;
  for (Eigen::Index i = 0; i < a.x.size(); ++i) {
    if (a.x[i].real() != b.x[i].real()) return a.x[i].real() < b.x[i].real();
    if (a.x[i].imag() != b.x[i].imag()) return a.x[i].imag() < b.x[i].imag();
  }
  return false;
}

}  // namespace

FiberResult solveFiber(const Family& f, const std::vector<double>& target,
                       const FiberOptions& options) {
  FiberResult result;
  const StartSystem* found = findStartSystem(f, options.compute_start_system);
  if (!found) {
    result.start_system_missing = true;
    return result;
  }
  const StartSystem& start = *found;
  result.root_count = static_cast<int>(start.roots.size());
  const int np = f.parameterCount();
  if (static_cast<int>(target.size()) != np) return result;
  for (double v : target)
    if (!std::isfinite(v)) return result;
  const detail::CompiledShape shape(f.shape());
  const int terms = shape.terms();
  std::vector<Complex> p1(target.begin(), target.end());
  std::vector<Complex> c1(terms);
  f.coefficients(p1.data(), c1.data());
  std::vector<Interval> ip(target.begin(), target.end()), ic(terms);
  f.coefficients(ip.data(), ic.data());
  detail::Certifier certifier(shape, ic.data());
  const detail::CoefficientPolynomials poly =
      detail::interpolateSegment(f, start.params.data(), p1.data());

  // Path i's certificate lands in slot i whichever thread tracked it, and the slots are merged
  // in path order: the same answer for every thread count.
  const int paths = result.root_count;
  const int threads = std::clamp(options.threads, 1, std::max(1, paths));
  std::vector<detail::BoxCertificate> slots(paths), kept;
  // Which paths an attempt tracks (`redo`): at first all. The second attempt tracks again, on
  // the same γ with steps a hundred times more careful, the paths that gave no new root (failed,
  // went to infinity, not certified, or ended on a root already kept: a path that jumped), so
  // each follows its own path to its own root. Later attempts track every path on a new γ,
  // which pairs the start roots with the roots otherwise (measured on a grid member of 48 roots:
  // the root one path could not reach, careful or not, was reached from another start).
  std::vector<char> redo(paths, 1), diverged(paths, 0);
  for (int attempt = 0; attempt < std::max(1, options.attempts); ++attempt) {
    result.attempts = attempt + 1;
    const bool careful = attempt == 1;
    if (attempt > 1) std::fill(redo.begin(), redo.end(), 1);
    const Complex gamma = detail::randomGamma(detail::mixSeed(options.seed, careful ? 0 : attempt));
    detail::TrackerOptions tracking;
    if (careful) {
      tracking.initial_step *= 0.1;
      tracking.max_step *= 0.2;
      tracking.target_error *= 0.01;
      tracking.max_error *= 0.01;
      tracking.confirm_error *= 0.01;
    }
    auto work = [&](int first, detail::Certifier& cert) {
      detail::Tracker tracker(shape, poly, detail::Arc{gamma}, c1.data(), tracking);
      for (int i = first; i < paths; i += threads) {
        if (!redo[i]) continue;
        slots[i] = detail::BoxCertificate();
        const detail::PathEnd e = tracker.track(detail::CVec(start.roots[i]));
        diverged[i] = e.status == detail::PathStatus::kAtInfinity;
        if (e.status == detail::PathStatus::kFinite) slots[i] = cert.certify(e.x);
      }
    };
    if (threads == 1) {
      work(0, certifier);
    } else {
      std::vector<std::thread> pool;
      for (int t = 1; t < threads; ++t)
        pool.emplace_back([&, t] {
          detail::Certifier own(shape, ic.data());
          work(t, own);
        });
      work(0, certifier);
      for (auto& th : pool) th.join();
    }
    bool found = false, all_diverged = true;
    for (int i = 0; i < paths; ++i) {
      if (!redo[i]) continue;
      all_diverged = all_diverged && diverged[i];
      detail::BoxCertificate& c = slots[i];
      if (!c.ok) continue;
      bool known = false;
      for (const auto& k : kept)
        if (detail::boxesOverlap(k.x, k.radius, c.x, c.radius)) {
          known = true;
          break;
        }
      if (known) continue;
      kept.push_back(std::move(c));
      redo[i] = 0;
      found = true;
    }
    if (static_cast<int>(kept.size()) >= result.root_count) break;
    // Every path tracked went to infinity and none gave a root: the member's roots there are at
    // infinity (or on a set of roots no path reaches), and another γ takes the paths there
    // again (measured: a grid member of 8 roots, every path of 3 attempts at infinity).
    if (!found && all_diverged) break;
  }
  for (const auto& k : kept) {
    CertifiedRoot r;
    r.x = k.x;
    r.radius = k.radius;
    r.real = k.real;
    result.roots.push_back(std::move(r));
  }
  std::sort(result.roots.begin(), result.roots.end(), before);
  result.complete =
      result.root_count > 0 && static_cast<int>(result.roots.size()) == result.root_count;
  return result;
}

}  // namespace relpos::complete
