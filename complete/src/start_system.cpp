// startSystem: the roots of one generic complex member per signature, by monodromy (Duff et al.
// 2019): from the seed member's one known root, track every known root around loops
// p0 → p1 → p2 → p0 through random complex members; a loop permutes the roots, so new ones appear
// until every root is known. Stop after kStaleLoops loops that add nothing, then cross-check
// with the total-degree homotopy when the Bézout number is small enough (above the limit, a
// second monodromy from an independent member; the generator of the stored ones adds the trace
// test, trace_test.hpp). While solving, no cross-check, and a fixed graph of members first
// (graphMonodromy: each root tracked once along each edge) with kStaleAfterGraph loops after.
// Every root is certified (Krawczyk on the member's double coefficients); two roots are taken
// as one only when a box around both passes the test, so an uncertain case counts two — a
// count too high only ever makes solveFiber say "not complete".
#include "start_system.hpp"

#include <future>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <set>

#include "homotopy.hpp"
#include "krawczyk.hpp"
#include "random.hpp"
#include "relpos/complete/encoding.hpp"
#include "relpos/complete/fiber.hpp"
#include "stored_start_systems.hpp"
#include "total_degree.hpp"

namespace relpos::complete {
namespace {

using detail::CVec;

constexpr int kStaleLoops = 8;
// After the graph monodromy of a solve (graphMonodromy): loops that add nothing before stopping.
constexpr int kStaleAfterGraph = 3;
constexpr int kMaxLoops = 400;

// A computation's predictor-corrector steps and the root tests of RootSet::add, counted whether
// limited or not (StartSystem::steps, root_tests), and the limit of the two together (0: none).
// A test counts as a step: it evaluates the system and its Jacobian over a box, about a step's
// work, and where the roots' boxes crowd together a new root meets a hundred known ones (a family
// of 3,152 roots took 440,000 tests beside its 600,000 steps: 43 s where the budget means about
// 8; counting the tests, 12 s).
struct StepBudget {
  std::int64_t limit = 0;
  std::int64_t steps = 0, tests = 0;
  bool limited() const { return limit > 0; }
  std::int64_t left() const { return limit - steps - tests; }
  bool exceeded() const { return limited() && left() < 0; }
};

// The certified roots of the start member found so far; each test charged to `budget` if given.
class RootSet {
 public:
  RootSet(const detail::CompiledShape& shape, const Complex* coefficients,
          StepBudget* budget = nullptr)
      : shape_(shape),
        coefficients_(coefficients),
        certifier_(shape, coefficients),
        scratch_(shape),
        budget_(budget) {}

  // Polishes and certifies x; adds it unless it is a root already known. True if added.
  bool add(CVec x) {
    if (detail::polish(shape_, coefficients_, x, scratch_, 6) < 0.0) return false;
    chargeTest();
    const detail::BoxCertificate c = certifier_.certify(x);
    if (!c.ok) return false;
    for (std::size_t i = 0; i < roots_.size(); ++i) {
      if (!detail::boxesOverlap(roots_[i], radii_[i], c.x, c.radius)) continue;
      // One root only if a box holding both boxes holds one root.
      const double d = detail::normInf(roots_[i] - c.x) + radii_[i] + c.radius;
      chargeTest();
      if (certifier_.testComplex(roots_[i], 1.01 * d)) return false;
      chargeTest();
      if (certifier_.testComplex(roots_[i], 10 * d)) return false;
    }
    roots_.push_back(c.x);
    radii_.push_back(c.radius);
    return true;
  }
  const std::vector<CVec>& roots() const { return roots_; }

 private:
  void chargeTest() {
    if (budget_ != nullptr) ++budget_->tests;
  }

  const detail::CompiledShape& shape_;
  const Complex* coefficients_;
  detail::Certifier certifier_;
  detail::EvalScratch scratch_;
  StepBudget* budget_;
  std::vector<CVec> roots_;
  std::vector<double> radii_;
};

// Endpoints at p_to of the paths from `starts` at p_from (straight segment: both generic).
// `budget` (when set): each path's steps taken from it; past it the tracking stops.
std::vector<CVec> trackSegment(const Family& f, const detail::CompiledShape& shape,
                               const std::vector<Complex>& p_from, const std::vector<Complex>& p_to,
                               const std::vector<CVec>& starts, StepBudget* budget = nullptr) {
  const detail::CoefficientPolynomials poly =
      detail::interpolateSegment(f, p_from.data(), p_to.data());
  std::vector<Complex> end(shape.terms());
  f.coefficients(p_to.data(), end.data());
  detail::Tracker tracker(shape, poly, detail::Arc{}, end.data());
  std::vector<CVec> out;
  out.reserve(starts.size());
  for (const CVec& s : starts) {
    const detail::PathEnd e = tracker.track(s);
    if (budget) {
      budget->steps += e.steps;
      if (budget->exceeded()) break;
    }
    if (e.status == detail::PathStatus::kFinite) out.push_back(e.x);
  }
  return out;
}

// The scale of member p0's parameters (their root mean square; 1 when 0): random members are
// complex Gaussian at that scale.
double memberScale(const std::vector<Complex>& p0) {
  double scale = 0.0;
  for (const Complex& p : p0) scale += std::norm(p);
  scale = p0.empty() ? 1.0 : std::sqrt(scale / static_cast<double>(p0.size()));
  return scale > 0.0 ? scale : 1.0;
}

// Monodromy loops at p0 from the roots in `set` until `stale_loops` loops add nothing (or
// kMaxLoops, or the budget runs out); returns the loops run.
int monodromy(const Family& f, const detail::CompiledShape& shape, const std::vector<Complex>& p0,
              std::uint64_t seed, RootSet& set, StepBudget& budget, int stale_loops = kStaleLoops) {
  const int np = f.parameterCount();
  const double scale = memberScale(p0);
  detail::SplitMix64 rng(seed);
  auto randomPoint = [&] {
    std::vector<Complex> p(np);
    for (auto& v : p) v = scale * rng.complexGaussian();
    return p;
  };
  int stale = 0, loops = 0;
  while (stale < stale_loops && loops < kMaxLoops && !budget.exceeded()) {
    ++loops;
    const std::vector<Complex> p1 = randomPoint(), p2 = randomPoint();
    std::vector<CVec> x = trackSegment(f, shape, p0, p1, set.roots(), &budget);
    x = trackSegment(f, shape, p1, p2, x, &budget);
    x = trackSegment(f, shape, p2, p0, x, &budget);
    if (budget.exceeded()) break;
    int added = 0;
    for (const CVec& e : x) added += set.add(e) ? 1 : 0;
    stale = added == 0 ? stale + 1 : 0;
  }
  return loops;
}

// Monodromy on a fixed graph (Duff et al. 2019): the seed member p0 and two random members,
// each pair joined by two edges either way (the segment between them on two random γ arcs);
// every root known at a member is tracked once along every edge leaving it, its endpoint added
// at the other end, until no root is left untracked. Each root costs four tracks at each of
// three members, where the loops of `monodromy` track every known root thrice a loop, eight
// loops past the last one found. Returns the paths tracked.
int graphMonodromy(const Family& f, const detail::CompiledShape& shape,
                   const std::vector<Complex>& p0, std::uint64_t seed, RootSet& set0,
                   StepBudget& budget) {
  const double scale = memberScale(p0);
  detail::SplitMix64 rng(seed);
  std::vector<std::vector<Complex>> node(3, p0), coefficients(3);
  for (int k = 1; k < 3; ++k)
    for (auto& v : node[static_cast<std::size_t>(k)]) v = scale * rng.complexGaussian();
  for (int k = 0; k < 3; ++k) {
    coefficients[static_cast<std::size_t>(k)].resize(static_cast<std::size_t>(shape.terms()));
    f.coefficients(node[static_cast<std::size_t>(k)].data(),
                   coefficients[static_cast<std::size_t>(k)].data());
  }
  RootSet set1(shape, coefficients[1].data(), &budget),
      set2(shape, coefficients[2].data(), &budget);
  RootSet* sets[3] = {&set0, &set1, &set2};
  struct Edge {
    int from, to;
    detail::CoefficientPolynomials poly;
    Complex gamma;
    std::size_t done = 0;  // the roots of `from` tracked along it so far
  };
  std::vector<Edge> edges;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b)
      for (int twice = 0; a != b && twice < 2; ++twice)
        edges.push_back({a, b,
                         detail::interpolateSegment(f, node[static_cast<std::size_t>(a)].data(),
                                                    node[static_cast<std::size_t>(b)].data()),
                         detail::randomGamma(detail::mixSeed(seed, edges.size() + 1))});
  int tracked = 0;
  for (bool progress = true; progress && !budget.exceeded();) {
    progress = false;
    for (Edge& e : edges) {
      const std::vector<CVec>& from = sets[e.from]->roots();
      if (e.done == from.size()) continue;
      detail::Tracker tracker(shape, e.poly, detail::Arc{e.gamma},
                              coefficients[static_cast<std::size_t>(e.to)].data());
      while (e.done < sets[e.from]->roots().size() && !budget.exceeded()) {
        const CVec x = sets[e.from]->roots()[e.done++];
        const detail::PathEnd end = tracker.track(x);
        ++tracked;
        budget.steps += end.steps;
        if (end.status == detail::PathStatus::kFinite) sets[e.to]->add(end.x);
        progress = true;
      }
    }
  }
  return tracked;
}

}  // namespace

namespace detail {

std::unique_ptr<StartSystem> computeStartSystem(const Family& f, std::uint64_t max_bezout,
                                                std::uint64_t seed, std::uint64_t max_steps,
                                                bool cross_check) {
  auto out = std::make_unique<StartSystem>();
  StepBudget budget;
  budget.limit = static_cast<std::int64_t>(
      std::min<std::uint64_t>(max_steps, std::numeric_limits<std::int64_t>::max()));
  auto done = [&] {
    out->steps = budget.steps;
    out->root_tests = budget.tests;
    return std::move(out);
  };
  auto overBudget = [&] {
    out->roots.clear();
    out->check = "over the step budget";
    return done();
  };
  const CompiledShape shape(f.shape());
  const int n = shape.variables();
  const int np = f.parameterCount();
  if (seed == 0) seed = stableHash(f.signature());
  std::vector<Complex> p0(np);
  CVec x0(n);
  f.seedMember(seed, p0.data(), x0.data());
  out->params = p0;
  std::vector<Complex> c0(shape.terms());
  f.coefficients(p0.data(), c0.data());
  RootSet set(shape, c0.data(), &budget);
  set.add(x0);
  if (set.roots().empty()) {
    out->check = "seed root not certified";
    return done();
  }
  if (!cross_check) {
    // While solving: the graph's tracks first, then random loops until kStaleAfterGraph add
    // nothing (what the graph alone misses: 3 of 376 families of 30,000 random specs lost 1-5
    // roots to it; with the loops, every family's count as the loops alone gave, in 0.6-0.7 of
    // their time — and a family whose loops alone ran over the step budget got its 16)
    graphMonodromy(f, shape, p0, mixSeed(seed, 1), set, budget);
    if (budget.exceeded()) return overBudget();
    out->monodromy_loops = monodromy(f, shape, p0, mixSeed(seed, 6), set, budget, kStaleAfterGraph);
    if (budget.exceeded()) return overBudget();
    out->check = "monodromy";
    for (const CVec& r : set.roots()) out->roots.push_back(r);
    return done();
  }
  out->monodromy_loops = monodromy(f, shape, p0, mixSeed(seed, 1), set, budget);
  if (budget.exceeded()) return overBudget();
  out->check = "monodromy";
  const std::uint64_t bezout = bezoutNumber(shape);
  if (bezout > 0 && bezout <= max_bezout) {
    // Cross-check: every root the total-degree homotopy finds, added.
    const std::size_t before = set.roots().size();
    // (Its own counter, started at what is left: counted in the budget's steps either way.)
    const std::int64_t start =
        budget.limited() ? budget.left() : std::numeric_limits<std::int64_t>::max();
    std::int64_t left = start;
    const std::vector<CVec> ends =
        totalDegreeEndpoints(f.shape(), c0.data(), mixSeed(seed, 2), &left);
    budget.steps += start - left;
    if (budget.exceeded()) return overBudget();
    for (const CVec& e : ends) set.add(e);
    if (budget.exceeded()) return overBudget();
    out->total_degree_paths = static_cast<int>(bezout);
    out->total_degree_added = static_cast<int>(set.roots().size() - before);
    out->check = "monodromy+total-degree";
  } else {
    // Too many Bézout paths: monodromy again from an independent seed member, its roots
    // carried to p0 and added (a root both runs missed is unlikely; neither is a proof).
    std::vector<Complex> q0(np), d0(shape.terms());
    CVec y0(n);
    f.seedMember(mixSeed(seed, 3), q0.data(), y0.data());
    f.coefficients(q0.data(), d0.data());
    RootSet other(shape, d0.data(), &budget);
    other.add(y0);
    if (!other.roots().empty()) monodromy(f, shape, q0, mixSeed(seed, 4), other, budget);
    if (budget.exceeded()) return overBudget();
    out->second_monodromy_roots = static_cast<int>(other.roots().size());
    const std::size_t before = set.roots().size();
    const std::vector<CVec> carried = trackSegment(f, shape, q0, p0, other.roots(), &budget);
    if (budget.exceeded()) return overBudget();
    for (const CVec& e : carried) set.add(e);
    if (budget.exceeded()) return overBudget();
    out->second_monodromy_added = static_cast<int>(set.roots().size() - before);
    out->check = "monodromy+second-monodromy";
  }
  for (const CVec& r : set.roots()) out->roots.push_back(r);
  return done();
}

}  // namespace detail

namespace {

// findStartSystem with the step budget of a computation (0: none). One computation per
// signature for the process. The map's lock is not held while computing (a new signature's
// monodromy takes up to seconds): a thread asking for a signature being computed waits for that
// one only, the others go on (a batch's other lines). The cache keeps every start system for
// the process, so the pointers returned stay valid. A family over the budget is remembered as
// such (nullptr for the budgeted lookups), not cached: a lookup without a budget computes it.
const StartSystem* lookUp(const Family& f, bool compute, std::uint64_t max_steps) {
  using Entry = std::shared_future<std::shared_ptr<const StartSystem>>;
  static std::mutex mutex;
  static std::map<std::string, Entry> cache;
  static std::set<std::string> not_stored;   // looked up without computing: none stored
  static std::set<std::string> over_budget;  // computed with a budget: more steps needed
  const std::string signature = f.signature();
  std::unique_lock<std::mutex> lock(mutex);
  if (auto it = cache.find(signature); it != cache.end()) {
    const Entry entry = it->second;
    lock.unlock();
    return entry.get().get();
  }
  if (!compute && not_stored.count(signature)) return nullptr;
  if ((!compute || max_steps > 0) && over_budget.count(signature)) return nullptr;
  // The stored one first (deterministic: always preferred for its signature); a stored file
  // that fails its check against f is ignored and the start system computed.
  std::promise<std::shared_ptr<const StartSystem>> promise;
  if (std::unique_ptr<StartSystem> stored = detail::loadStoredStartSystem(f)) {
    promise.set_value(std::move(stored));
    return cache.emplace(signature, promise.get_future().share()).first->second.get().get();
  }
  if (!compute) {
    not_stored.insert(signature);
    return nullptr;
  }
  const Entry entry = promise.get_future().share();
  cache.emplace(signature, entry);
  lock.unlock();
  std::unique_ptr<StartSystem> computed;
  try {
    // while solving (a step budget): monodromy alone, no cross-check
    computed =
        detail::computeStartSystem(f, detail::kDefaultMaxBezout, 0, max_steps, max_steps == 0);
  } catch (...) {
    promise.set_exception(std::current_exception());  // to those waiting for it
    lock.lock();
    cache.erase(signature);  // a later call tries again
    throw;
  }
  if (computed->check == "over the step budget") {
    lock.lock();
    cache.erase(signature);
    over_budget.insert(signature);
    lock.unlock();
    promise.set_value(nullptr);  // those waiting: none (startSystem asks again, unbudgeted)
    return nullptr;
  }
  promise.set_value(std::move(computed));
  return entry.get().get();
}

}  // namespace

const StartSystem* findStartSystem(const Family& f, bool compute) {
  return lookUp(f, compute, detail::kSolvingStepBudget);
}

const StartSystem& startSystem(const Family& f) {
  // nullptr only after waiting for a budgeted computation that ran out: then computed here
  const StartSystem* s = lookUp(f, true, 0);
  return s ? *s : *lookUp(f, true, 0);
}

int preloadStoredStartSystems() {
  int loaded = 0;
  for (const detail::EmbeddedText& e : detail::embeddedStartSystems()) {
    detail::StoredStartSystem s;
    std::string why;
    if (!detail::parseStoredStartSystem(e.text, &s, &why)) continue;
    const std::unique_ptr<Family> f = familyOfSignature(s.signature);
    if (f && findStartSystem(*f, false)) ++loaded;
  }
  return loaded;
}

}  // namespace relpos::complete
