// One mesh reader (HOLEFILL_FUZZ_FORMAT: obj, off, ply, stl), then the mesh's holes.
#include "fuzz_guard.h"
#include "mesh/mesh_holes.h"
#include "mesh/mesh_io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  holefill::fuzz::guarded([&] {
    const holefill::TriangleMesh m = holefill::parseMesh(holefill::fuzz::text(data, size), HOLEFILL_FUZZ_FORMAT);
    holefill::findMeshHoles(m);
  });
  return 0;
}
