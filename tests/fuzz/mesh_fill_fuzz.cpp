// `mesh-fill`'s core entry on a small OBJ mesh: every hole filled (refinement and fairing on).
#include "fuzz_guard.h"
#include "mesh/mesh_hole_fill.h"
#include "mesh/mesh_io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  holefill::fuzz::guarded([&] {
    const holefill::TriangleMesh m = holefill::parseMesh(holefill::fuzz::text(data, size), "obj");
    holefill::MeshFillOptions o;
    o.maxBoundary = 400;  // the fuzzer's meshes are small; a big hole would only slow it down
    holefill::fillMeshHoles(m, o);
  });
  return 0;
}
