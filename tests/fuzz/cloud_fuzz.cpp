// The point-cloud text of `param` and `fit-points` (x y z [flag [u v]] lines).
#include "fuzz_guard.h"
#include "geometry/flagged_cloud.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  holefill::fuzz::guarded([&] { holefill::parseFlaggedCloud(holefill::fuzz::text(data, size)); });
  return 0;
}
