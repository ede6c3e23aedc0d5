// BREP text through the Python door's path (shapeFromBrepString), with a 5 s limit instead of 60.
#include "brep/shape_io.h"
#include "fuzz_guard.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  holefill::fuzz::guarded([&] { holefill::shapeFromBrepString(holefill::fuzz::text(data, size), 5.0); });
  return 0;
}
