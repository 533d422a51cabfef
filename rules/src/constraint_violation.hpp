#pragma once
// The built-in constraint types' ConstraintType::violation (constraint_violation.cpp).
#include "relpos/core/registry.hpp"

namespace relpos::rules {

double distanceViolation(const InputConstraint& c, const Feature& fixed_W, const Feature& mobile_W,
                         const Tolerance& tol, const void* /*context*/);
double coincidentViolation(const InputConstraint& c, const Feature& fixed_W,
                           const Feature& mobile_W, const Tolerance& tol, const void* /*context*/);
double angleViolation(const InputConstraint& c, const Feature& fixed_W, const Feature& mobile_W,
                      const Tolerance& tol, const void* /*context*/);
double parallelViolation(const InputConstraint& c, const Feature& fixed_W, const Feature& mobile_W,
                         const Tolerance& tol, const void* /*context*/);
double perpendicularViolation(const InputConstraint& c, const Feature& fixed_W,
                              const Feature& mobile_W, const Tolerance& tol,
                              const void* /*context*/);
double tangentViolation(const InputConstraint& c, const Feature& fixed_W, const Feature& mobile_W,
                        const Tolerance& tol, const void* /*context*/);

}  // namespace relpos::rules
