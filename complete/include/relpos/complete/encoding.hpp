#pragma once
// The polynomial encodings of relpos's constraints (issue 15): families of square systems whose
// parameters are the features' coordinates and the constraints' values, so that every problem
// of one signature (which equations, on which shared features) is solved from one start system.
//
// PoseFamily: the mobile object's pose in Study (dual-quaternion) parameters x = (e0..e3,
// g0..g3): a world point of mobile point b is p = R b + t, R b = e b ẽ / (e·e), t = 2 g ẽ / (e·e)
// (ẽ the conjugate). v = e b − a e + 2 g = (p − a) e is linear in x, so point constraints are
// quadrics once multiplied by e·e; a random chart c·e = 1 fixes the scale of e (the chart e0 = 1
// would lose every pose turned by 180°) and the Study quadric e·g = 0 makes t a pure vector.
//
// LineFamily: a line's pose when the mobile features are one line (spin about it and slide along
// it are exact parameters, not unknowns): x = (w, q), the world direction (w·w = 1) and the foot
// of the line from the origin (q·w = 0).
//
// Every product is the algebraic one (no complex conjugation), so the formulas hold for complex
// parameters; every value parameter (a squared distance, an offset, a cosine) appears in one
// equation only and affinely, which is what seedMember solves for.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "relpos/complete/poly_family.hpp"

namespace relpos::complete {

// One scalar equation of a pose. Offsets index the family's parameters: a 3-vector slot takes
// three (x, y, z), the chart four (c0..c3), a value one. Slots shared by equations are shared
// features (the same point in two legs): the sharing is part of the signature.
enum class PoseEquationKind : std::uint8_t {
  kChart,       // c·e − 1                                    value: c (4)
  kStudy,       // e·g
  kPointPoint,  // v·v − D e·e, v = e b − a e + 2g             fixed a, mobile b, value D = d²
  kPointPlane,  // n·vec((e b + 2g) ẽ) − h e·e                 mobile b, fixed n, value h = d + n·a
  kPlanePoint,  // m·vec(ẽ (a e − 2g)) − h e·e                 fixed a, mobile m, value h = d + m·b
  kPointLine,  // (v·v)(e·e)|u|² − (u·vec(v ẽ))² − D |u|² (e·e)²   mobile b, fixed a, line u
  kLinePoint,  // (v·v)(e·e)|m|² − (m·vec(ẽ v))² − D |m|² (e·e)²   fixed a, mobile b, line m
  kDirection,  // u·vec(e m ẽ) − κ e·e                        fixed u, mobile m, value κ
  // e·e − 1 (added for issue 15's completeness proof): in place of the chart, the real system
  // whose real roots are exactly the poses (each twice, ±(e, g)), on a bounded domain.
  kNorm,
};
const char* toString(PoseEquationKind k);

struct PoseEquation {
  PoseEquationKind kind = PoseEquationKind::kStudy;
  int fixed = -1;   // a (point), n or u (direction)
  int mobile = -1;  // b (point) or m (direction)
  int line = -1;    // the line's direction: u (kPointLine) or m (kLinePoint)
  int value = -1;   // D, h, κ; the chart's c
};

class PoseFamily final : public PolyFamilyOf<PoseFamily> {
 public:
  // Eight equations over parameterCount parameters; throws std::invalid_argument when they do
  // not make a family (a slot out of range, a value parameter shared or used as a coordinate).
  PoseFamily(std::vector<PoseEquation> equations, int parameter_count);
  void seedMember(std::uint64_t seed, Complex* params, Complex* root) const override;
  const std::vector<PoseEquation>& poseEquations() const { return equations_; }

  // PolyFamilyOf's equations.
  std::size_t equationCount() const { return equations_.size(); }
  template <typename S>
  Poly<S> equation(std::size_t k, const S* params) const;

 private:
  std::vector<PoseEquation> equations_;
  std::vector<int> value_param_;  // per equation, the parameter seedMember solves (chart: -1)
};

enum class LineEquationKind : std::uint8_t {
  kUnit,           // w·w − 1
  kFoot,           // q·w
  kPointDistance,  // |p − q|² − (p·w)² − D     fixed p, value D = d²
  kDirection,      // u·w − κ                   fixed u, value κ
  kPlaneOffset,    // n·q − h                   fixed n, value h = d + n·a
};
const char* toString(LineEquationKind k);

struct LineEquation {
  LineEquationKind kind = LineEquationKind::kUnit;
  int fixed = -1;
  int value = -1;
};

class LineFamily final : public PolyFamilyOf<LineFamily> {
 public:
  // Six equations (w·w = 1 and q·w = 0 among them).
  LineFamily(std::vector<LineEquation> equations, int parameter_count);
  void seedMember(std::uint64_t seed, Complex* params, Complex* root) const override;
  const std::vector<LineEquation>& lineEquations() const { return equations_; }

  // PolyFamilyOf's equations.
  std::size_t equationCount() const { return equations_.size(); }
  template <typename S>
  Poly<S> equation(std::size_t k, const S* params) const;

 private:
  std::vector<LineEquation> equations_;
  std::vector<int> value_param_;
};

// The family a signature spells out (PoseFamily::signature(), LineFamily::signature()): the same
// equations and parameter count, so the same signature. nullptr when the text is not one
// (added for issue 15: the stored start systems are loaded by signature, before any problem).
std::unique_ptr<Family> familyOfSignature(const std::string& signature);

}  // namespace relpos::complete
