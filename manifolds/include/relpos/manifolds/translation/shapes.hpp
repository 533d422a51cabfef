#pragma once
// Every built-in translation shape. A new shape is its own header and source, its #include and one
// line in the list below, and its source in manifolds/CMakeLists.txt; the registry's catalogue
// (catalogue.cpp) and every std::visit pick it up from here. The order is the catalogue's.
#include <variant>

#include "relpos/manifolds/translation/bounded_cylinder.hpp"
#include "relpos/manifolds/translation/circle.hpp"
#include "relpos/manifolds/translation/cylinder.hpp"
#include "relpos/manifolds/translation/ellipse.hpp"
#include "relpos/manifolds/translation/free.hpp"
#include "relpos/manifolds/translation/line.hpp"
#include "relpos/manifolds/translation/line_of_planes.hpp"
#include "relpos/manifolds/translation/plane.hpp"
#include "relpos/manifolds/translation/planes.hpp"
#include "relpos/manifolds/translation/point.hpp"
#include "relpos/manifolds/translation/point_of_line_plane.hpp"
#include "relpos/manifolds/translation/shell.hpp"
#include "relpos/manifolds/translation/slab.hpp"
#include "relpos/manifolds/translation/sphere.hpp"
#include "relpos/manifolds/translation/thick_cylinder.hpp"

namespace relpos::manifolds {

using TranslationShape = std::variant<translation::Free,              //
                                      translation::Point,             //
                                      translation::Line,              //
                                      translation::Plane,             //
                                      translation::Sphere,            //
                                      translation::Cylinder,          //
                                      translation::LineOfPlanes,      //
                                      translation::PointOfLinePlane,  //
                                      translation::Ellipse,           //
                                      translation::Shell,             //
                                      translation::ThickCylinder,     //
                                      translation::Slab,              //
                                      translation::Planes,            //
                                      translation::BoundedCylinder,   //
                                      translation::Circle>;

}  // namespace relpos::manifolds
