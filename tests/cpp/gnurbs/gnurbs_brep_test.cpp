#include <gtest/gtest.h>

#include "geometry/error.h"
#include "geometry/text_file.h"
#include "gnurbs/cage_io.h"
#include "gnurbs/g2_gnurbs.h"
#include "gnurbs/gnurbs_brep.h"

using namespace holefill;

// Found by fuzzing (tests/fuzz/corpus/gnurbs/degenerate_patch_sewn_away): a cage whose patch
// collapses, which sewing drops; the null shape it left in its place was added to the shell and
// OCCT crashed (SIGSEGV in TopoDS_Builder::Add). A clear error instead.
TEST(GnurbsBrep, APatchSewingDropsIsAClearError) {
  const QuadCage cage = parseCageObj(readFileBytes(std::string(HOLEFILL_FUZZ_CORPUS) + "/gnurbs/degenerate_patch_sewn_away"));
  const G2GnurbsResult g = buildG2Gnurbs(cage);
  try {
    gnurbsToBrep(g);
    FAIL() << "a shell was built with a patch sewing dropped";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("degenerate"), std::string::npos) << e.what();
  }
}
