#pragma once
/// \file
/// spar::iga — spline geometry for analysis: knot vectors, B-spline/NURBS bases and their
/// derivatives, NURBS curves, Gauss–Legendre quadrature. Overview and sources: docs/iga.md.

#include <spar/iga/basis.hpp>
#include <spar/iga/bezier_extraction.hpp>
#include <spar/iga/circular_arc.hpp>
#include <spar/iga/knot_operations.hpp>
#include <spar/iga/knot_vector.hpp>
#include <spar/iga/nurbs_curve.hpp>
#include <spar/iga/quadrature.hpp>
#include <spar/iga/rational_bezier.hpp>
#include <spar/iga/straight_line.hpp>
