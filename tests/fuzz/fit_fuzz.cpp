// `fit`'s core entry: an OBJ region, a line "---", then its labels JSON; a small control net.
#include "fitting/labeled_fit.h"
#include "fuzz_guard.h"
#include "mesh/mesh_io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  holefill::fuzz::guarded([&] {
    const auto [mesh, labels] = holefill::fuzz::split(holefill::fuzz::text(data, size));
    const holefill::TriangleMesh region = holefill::parseMesh(mesh, "obj");
    const auto segments = holefill::parseLabelsJson(labels);
    if (region.vertices.rows() > 3000) return;
    holefill::LabeledFitOptions o;
    o.maxControl = 12;
    holefill::fitLabeled(region, segments, o);
  });
  return 0;
}
