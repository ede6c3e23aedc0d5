// Tolerances of HoleFill, defined once (STYLE.md #8). Model-space tolerances
// derive from OCCT's Precision so HoleFill agrees with the kernel it feeds;
// the continuity tiers are the ones DESIGN.md fixes for reports and benchmarks.
#pragma once

#include <Precision.hxx>

namespace holefill::tol {

// Points closer than this (model units) are the same point (OCCT Precision::Confusion, 1e-7).
inline double confusion() { return Precision::Confusion(); }
// Parameter values closer than this are the same parameter.
inline double parametric() { return 1e-9; }
// Angle below which two directions are parallel (OCCT Precision::Angular, 1e-12 rad).
inline double angular() { return Precision::Angular(); }

// Tangent break between consecutive boundary edges that makes a corner (5 degrees).
constexpr double kCornerAngleDeg = 5.0;

// DESIGN.md continuity tiers; G0 tiers are relative to the hole scale (bbox diagonal).
constexpr double kG0Strict = 1e-6;
constexpr double kG0Loose = 1e-4;
constexpr double kG1Strict = 1e-3;  // radians
constexpr double kG1Loose = 1e-2;   // radians
constexpr double kG2Tier = 0.1;     // relative curvature deviation

// Coordinates beyond this magnitude are rejected as corrupt input (model units).
constexpr double kMaxCoordinate = 1e7;

}  // namespace holefill::tol
