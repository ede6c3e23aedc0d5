// A quad cage OBJ (vertices, quads, `# sharp`, `# knot`, `# anchor` comments).
#include "fuzz_guard.h"
#include "gnurbs/cage_io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  holefill::fuzz::guarded([&] { holefill::parseCageObj(holefill::fuzz::text(data, size)); });
  return 0;
}
