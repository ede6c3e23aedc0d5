// The bridge between OCCT and Eigen: point/vector conversion and the surface
// jet (point, first and second derivatives) of a face at (u, v), with the
// face's orientation applied so normals point out of the material the way the
// face is used in its shell.
#pragma once

#include <BRepAdaptor_Surface.hxx>
#include <Eigen/Dense>
#include <TopoDS_Face.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

#include "geometry/differential_geometry.h"

namespace holefill {

inline Eigen::Vector3d toEigen(const gp_Pnt& p) { return {p.X(), p.Y(), p.Z()}; }
inline Eigen::Vector3d toEigen(const gp_Vec& v) { return {v.X(), v.Y(), v.Z()}; }
inline gp_Pnt toPnt(const Eigen::Vector3d& p) { return gp_Pnt(p.x(), p.y(), p.z()); }

// Jet of the face's surface at (u, v); when the face is REVERSED the v-derivatives are
// negated, which flips su x sv to the face's outward normal and keeps curvature signs consistent.
SurfaceJet faceJet(const BRepAdaptor_Surface& surface, bool reversed, double u, double v);

}  // namespace holefill
