#include "geometry/occt_bridge.h"

namespace holefill {

SurfaceJet faceJet(const BRepAdaptor_Surface& s, bool reversed, double u, double v) {
  gp_Pnt p;
  gp_Vec su, sv, suu, svv, suv;
  s.D2(u, v, p, su, sv, suu, svv, suv);
  SurfaceJet j{toEigen(p), toEigen(su), toEigen(sv), toEigen(suu), toEigen(suv), toEigen(svv)};
  if (reversed) {
    // v -> -v: d/dv flips sign, d2/dv2 does not, d2/dudv flips.
    j.sv = -j.sv;
    j.suv = -j.suv;
  }
  return j;
}

}  // namespace holefill
