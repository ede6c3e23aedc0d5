// The JSON files users hand over: any JSON, then as labels, sharp edges and anchors of a cage.
#include "fitting/labeled_fit.h"
#include "fuzz_guard.h"
#include "gnurbs/cage_io.h"
#include "gnurbs/sample_cages.h"
#include "geometry/json_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string t = holefill::fuzz::text(data, size);
  holefill::fuzz::guarded([&] { holefill::parseJson(t); });
  holefill::fuzz::guarded([&] { holefill::parseLabelsJson(t); });
  static const holefill::QuadCage base = holefill::cages::sampleCage("cage_valence5");
  holefill::fuzz::guarded([&] {
    holefill::QuadCage c = base;
    holefill::addSharpEdgesFromJson(c, t);
  });
  holefill::fuzz::guarded([&] {
    holefill::QuadCage c = base;
    holefill::addAnchorsFromJson(c, t);
  });
  return 0;
}
