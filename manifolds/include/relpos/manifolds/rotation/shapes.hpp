#pragma once
// Every built-in rotation shape. A new shape is its own header and source, its #include and one
// line in the list below, and its source in manifolds/CMakeLists.txt; the registry's catalogue
// (catalogue.cpp) and every std::visit pick it up from here. The order is the catalogue's.
#include <variant>

#include "relpos/manifolds/rotation/angle_with_range.hpp"
#include "relpos/manifolds/rotation/fixed.hpp"
#include "relpos/manifolds/rotation/free.hpp"
#include "relpos/manifolds/rotation/one_angle.hpp"
#include "relpos/manifolds/rotation/one_angle_range.hpp"
#include "relpos/manifolds/rotation/one_parallel.hpp"
#include "relpos/manifolds/rotation/two_angle.hpp"
#include "relpos/manifolds/rotation/two_angle_range.hpp"

namespace relpos::manifolds {

using RotationShape = std::variant<rotation::Fixed,        //
                                   rotation::OneParallel,  //
                                   rotation::OneAngle,     //
                                   rotation::TwoAngle,     //
                                   rotation::Free,         //
                                   rotation::OneAngleRange,  //
                                   rotation::TwoAngleRange,  //
                                   rotation::AngleWithRange>;

}  // namespace relpos::manifolds
