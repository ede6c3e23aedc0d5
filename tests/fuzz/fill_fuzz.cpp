// `fill`'s core entry: a model as BREP text, its first hole filled G1 and sewn in.
#include "fill/hole_fill.h"
#include "brep/shape_io.h"
#include "fuzz_guard.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  holefill::fuzz::guarded([&] {
    const TopoDS_Shape model = holefill::shapeFromBrepString(holefill::fuzz::text(data, size), 5.0);
    holefill::HoleFillOptions o;
    o.autoUvtran = false;  // the learned model is not what this harness is after
    holefill::fillHole(model, 0, o);
  });
  return 0;
}
