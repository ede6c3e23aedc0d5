// `gnurbs`'s core entry on a small cage: the G² construction and its B-rep.
#include "fuzz_guard.h"
#include "gnurbs/cage_io.h"
#include "gnurbs/g2_gnurbs.h"
#include "gnurbs/gnurbs_brep.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  holefill::fuzz::guarded([&] {
    const holefill::QuadCage cage = holefill::parseCageObj(holefill::fuzz::text(data, size));
    if (cage.quads.rows() > 64) return;  // small cages: many executions, not one slow one
    holefill::gnurbsToBrep(holefill::buildG2Gnurbs(cage));
  });
  return 0;
}
