#pragma once
// A solution branch: a parameterised set of poses X_WM(θ) (PMF §V, Somani §IV). Manifolds are
// stored inline in a Branch (ManifoldHolder) so that solving allocates nothing; a manifold type
// must fit kManifoldStorage bytes and be copyable.
#include <array>
#include <cstddef>
#include <new>
#include <string>
#include <type_traits>
#include <utility>

#include "relpos/core/geometry.hpp"
#include "relpos/core/tolerance.hpp"

namespace relpos {

inline constexpr int kMaxDof = 6;
using Params = std::array<double, kMaxDof>;

// The built-in manifolds give angles and lengths only; kOther is for a plugin's parameter that is
// neither (docs/spec.md §2 lets results say "other"): the nearest-pose search steps it by absolute
// amounts, as an angle, but does not grid it.
enum class ParamKind : unsigned char { kAngle, kLength, kOther };
const char* toString(ParamKind k);

// What the solver must know of a manifold beyond its interface, told by the type itself (not by
// its name, which is for people: a plugin may pick any): a branch of a set turned about a fixed
// line (ConstraintSet::revolve) must be a kRevolved one, a pose turned about that line.
enum class ManifoldKind : unsigned char { kOther, kRevolved };

struct Parameter {
  const char* name = "";
  ParamKind kind = ParamKind::kAngle;
  double min = -kPi;  // -inf / +inf for unbounded lengths
  double max = kPi;
  bool periodic = false;
};

class Manifold {
 public:
  virtual ~Manifold() = default;
  virtual const char* typeName() const = 0;
  virtual int dof() const = 0;
  // -1 for a mixed (non-separable) manifold.
  virtual int rotationalDof() const = 0;
  virtual int translationalDof() const = 0;
  virtual Parameter parameter(int i) const = 0;
  virtual Isometry3d pose(const Params& theta) const = 0;
  // Parameters of a pose of this manifold near X (the projection of X, PMF 003 §V). Exact for a
  // pose on the manifold: pose(nearest(pose(θ))) == pose(θ).
  virtual Params project(const Isometry3d& X) const = 0;
  virtual std::string describe() const = 0;
  // Placement copy into raw storage (used by ManifoldHolder).
  virtual Manifold* copyInto(void* storage) const = 0;

  // The nearest-pose search in fewer dimensions: once the other parameters are fixed, the ones in
  // closedFormParams() (bit i: parameter i) have a closed form, the values nearest X (a separable
  // branch's translation, once its rotation is fixed) — only where that is the exact nearest
  // point; otherwise (the default) every parameter is searched. poseWithTail sets them in theta
  // and returns pose(theta), sharing the work both need (the rotation).
  virtual unsigned closedFormParams() const { return 0u; }
  virtual Isometry3d poseWithTail(const Isometry3d& X, Params* theta) const {
    (void)X;
    return pose(*theta);
  }

  // The solver matches branches on centred geometry (fixed features moved by −offset_W in the
  // world, mobile ones by −offset_M in the mobile frame: see solver.cpp) and then calls this to
  // make the branch that of the problem as given: the same set of poses as
  // T(offset_W)·pose(θ)·T(−offset_M) over θ (the parameters may be re-anchored). False when the
  // type cannot (the default, e.g. a plugin's manifold): the solver then solves the problem
  // uncentred instead.
  virtual bool rebase(const Vector3d& offset_W, const Vector3d& offset_M) {
    (void)offset_W;
    (void)offset_M;
    return false;
  }

  // Last in the table of virtual functions, so that the earlier entries keep their places.
  virtual ManifoldKind kind() const { return ManifoldKind::kOther; }

  // The distance the nearest-pose search weighs at θ: poseDistance(poseWithTail(X, θ), X), with
  // the closed-form parameters set in θ (the default). A type may answer without building the
  // pose, and leave unset a closed-form spin that only turns the rotation about a mobile axis:
  // the least angle over a full turn of spin is the angle between that axis's two directions, a
  // closed form of its own. The search calls poseWithTail before it reads the parameters.
  // (After kind(): added with plugin ABI 8.)
  virtual double searchDistance(const Isometry3d& X, Params* theta) const;

  // Where the rotation alone comes nearest X's, where that has a closed form: the rotation's
  // parameters (the searched ones and a closed-form spin) set in theta to the nearest rotation
  // of the branch, and that least angle returned — over the whole branch, the other parameters
  // as they are. NaN (the default) where there is none. The search starts its certificate of a
  // kink of the distance there (X's rotation reached), and skips the certificate altogether where
  // X's rotation is out of the branch's reach. (After searchDistance: added with plugin ABI 9.)
  virtual double nearestRotation(const Isometry3d& X, Params* theta) const;

  // Where the nearest pose's one searched angle is known to lie on an arc, whatever its other
  // parameters: true with that parameter's index in *i and the arc [*lo, *hi] (lo < hi <
  // lo + 2π; a periodic parameter's values count modulo 2π). The search then samples that arc
  // alone, more finely than a whole turn and in no more poses. False (the default) where
  // there is no such arc. (After nearestRotation: added with plugin ABI 10.)
  virtual bool nearestArc(const Isometry3d& X, int* i, double* lo, double* hi) const;

  // How far the distance from X's position to the positions the branch pairs with a rotation R
  // moves, at most, per radian R turns: L with |g(R) − g(R')| ≤ L·angle(R, R'), g(R) that
  // distance. Finite only where the position for a given rotation has a closed form (every
  // parameter of the translation in closedFormParams()): a separable branch whose translational
  // constraints all hold one mobile point p (its positions for R are S − R·p, and R·p moves no
  // farther than |p| per radian) answers |p|. With L ≤ 1 and X's rotation among the branch's
  // (a pose of it with X's rotation), no turn gains more in position than it costs in angle: the
  // nearest pose keeps X's rotation, proven. +inf (the default) where not known. (After nearestArc:
  // added with plugin ABI 11.)
  virtual double rotationCoupling() const;

  // Whether X lies on the manifold: its projection maps back onto X.
  bool contains(const Isometry3d& X, const Tolerance& tol) const;
};

// CRTP helper providing copyInto.
template <typename Derived>
class ManifoldBase : public Manifold {
 public:
  Manifold* copyInto(void* storage) const override {
    return new (storage) Derived(static_cast<const Derived&>(*this));
  }
};

// A mixed (non-separable) manifold: its DOF do not split into rotational and translational ones,
// so the result writes `null` for both (docs/spec.md §2).
template <typename Derived>
class MixedManifoldBase : public ManifoldBase<Derived> {
 public:
  int rotationalDof() const override { return -1; }
  int translationalDof() const override { return -1; }
};

// The largest built-in type (a revolved separable manifold) with room to spare for plugins'.
inline constexpr std::size_t kManifoldStorage = 1152;

class ManifoldHolder {
 public:
  // User-provided: value-initialising a holder would otherwise zero its buffer first.
  ManifoldHolder() noexcept {}  // NOLINT(modernize-use-equals-default)
  ManifoldHolder(const ManifoldHolder& o) { copyFrom(o); }
  ManifoldHolder& operator=(const ManifoldHolder& o) {
    if (this != &o) {
      reset();
      copyFrom(o);
    }
    return *this;
  }
  ~ManifoldHolder() { reset(); }

  template <typename T, typename... Args>
  T& emplace(Args&&... args) {
    static_assert(sizeof(T) <= kManifoldStorage, "manifold type too large for inline storage");
    static_assert(alignof(T) <= 16, "manifold type over-aligned");
    reset();
    T* t = new (buf_) T(std::forward<Args>(args)...);
    ptr_ = t;
    return *t;
  }
  void reset() {
    if (ptr_) ptr_->~Manifold();
    ptr_ = nullptr;
  }
  const Manifold* get() const { return ptr_; }
  Manifold* get() { return ptr_; }
  const Manifold& operator*() const { return *ptr_; }
  const Manifold* operator->() const { return ptr_; }
  explicit operator bool() const { return ptr_ != nullptr; }

 private:
  void copyFrom(const ManifoldHolder& o) { ptr_ = o.ptr_ ? o.ptr_->copyInto(buf_) : nullptr; }
  alignas(16) unsigned char buf_[kManifoldStorage];
  Manifold* ptr_ = nullptr;
};

// Distance used for "nearest" (docs/spec.md §2): translation distance plus rotation angle.
double poseDistance(const Isometry3d& a, const Isometry3d& b);

// A point of every manifold: each parameter at the middle of its bounds (0 for a full turn), at
// its finite bound when it has only one, else 0 (NaN for a NaN bound). The solver checks every
// branch there, so its pose is finite; the nearest-pose search falls back to it where a
// projection is not.
Params referenceParams(const Manifold& m);

// The pose of manifold m nearest to X: m.project(X) refined by a deterministic search on
// poseDistance within the parameter bounds (one searched angle: samples and Brent's method; more:
// a grid, pattern search and Newton steps); the parameters with a closed form (closedFormParams)
// are set, not searched, and where the rotation is already right (a kink of the metric) a
// first-order certificate of the minimum ends the search. Never worse than the projection.
Params nearestParams(const Manifold& m, const Isometry3d& X);

// Whether the pose `nearest` at nearestParams(m, X), `distance` from X, is proven the nearest of
// the whole manifold: every parameter has a closed form (the answer is then the global minimum,
// not a search's), or the distance is X's own rounding (X lies on the manifold; no pose is
// nearer), or it keeps X's rotation (to rounding) and rotationCoupling() is at most 1 (no turn
// away from X's rotation is nearer). The second form finds `nearest` itself.
bool nearestIsGlobal(const Manifold& m, const Isometry3d& X, const Isometry3d& nearest,
                     double distance);
bool nearestIsGlobal(const Manifold& m, const Isometry3d& X, double distance);

}  // namespace relpos
