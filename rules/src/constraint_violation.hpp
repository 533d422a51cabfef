#pragma once
// The built-in constraint types' ConstraintType::violation (constraint_violation.cpp).
#include "relpos/core/registry.hpp"

namespace relpos::rules {

double distanceViolation(const InputConstraint& c, const Feature& fixed_W, const Feature& mobile_W,
                         const Tolerance& tol);
double coincidentViolation(const InputConstraint& c, const Feature& fixed_W,
                           const Feature& mobile_W, const Tolerance& tol);
double angleViolation(const InputConstraint& c, const Feature& fixed_W, const Feature& mobile_W,
                      const Tolerance& tol);
double parallelViolation(const InputConstraint& c, const Feature& fixed_W, const Feature& mobile_W,
                         const Tolerance& tol);
double perpendicularViolation(const InputConstraint& c, const Feature& fixed_W,
                              const Feature& mobile_W, const Tolerance& tol);
double tangentViolation(const InputConstraint& c, const Feature& fixed_W, const Feature& mobile_W,
                        const Tolerance& tol);

}  // namespace relpos::rules
