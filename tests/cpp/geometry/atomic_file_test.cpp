#include "geometry/atomic_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "geometry/error.h"

using namespace holefill;
namespace fs = std::filesystem;

namespace {
fs::path scratchDir() {
  const fs::path d = fs::temp_directory_path() / ("hf_atomic_" + std::to_string(getpid()));
  fs::create_directories(d);
  return d;
}
std::string contents(const fs::path& p) {
  std::ifstream in(p);
  return std::string(std::istreambuf_iterator<char>(in), {});
}
}  // namespace

TEST(AtomicFile, ReplacesTheTargetWholeAndLeavesNoTemporary) {
  const fs::path d = scratchDir();
  const fs::path p = d / "out.obj";
  std::ofstream(p) << "old contents that are longer than the new ones";
  writeFileAtomically(p.string(), "new\n");
  EXPECT_EQ(contents(p), "new\n");
  int files = 0;
  for (const auto& e : fs::directory_iterator(d)) files += e.path().filename().string().rfind("out.obj", 0) == 0;
  EXPECT_EQ(files, 1);
}

TEST(AtomicFile, AMissingFolderIsAClearErrorAndWritesNothing) {
  const fs::path p = scratchDir() / "no_such_folder" / "out.json";
  try {
    writeFileAtomically(p.string(), "{}");
    FAIL() << "wrote into a missing folder";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(p.string()), std::string::npos);
  }
  EXPECT_FALSE(fs::exists(p.parent_path()));
}

TEST(AtomicFile, TemporariesKeepTheTargetsExtension) {
  const std::string tmp = temporaryFileFor("/x/part.step");
  EXPECT_EQ(tmp.rfind("/x/part.step.tmp", 0), 0u);
  EXPECT_EQ(tmp.substr(tmp.size() - 5), ".step");
  EXPECT_FALSE(commitTemporaryFile("/no/such/tmp.step", "/no/such/part.step"));
}

TEST(AtomicFile, AnOutputSetAppearsWholeOrNotAtAll) {
  const fs::path d = scratchDir() / "set";
  fs::create_directories(d);
  const fs::path a = d / "model.brep", b = d / "report.json", bad = d / "model.brep" / "face.brep";
  writeFileAtomically(a.string(), "old model");
  {
    // The second file's folder is a file: the first, already staged, must not replace the old one.
    OutputSet set;
    set.write(a.string(), [](const std::string& p) { writeFileAtomically(p, "new model"); });
    try {
      set.write(bad.string(), [](const std::string& p) { writeFileAtomically(p, "face"); });
      FAIL() << "a file under a file was written";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(bad.string() + "'"), std::string::npos) << e.what();  // names the target, not the staged name
    }
  }
  EXPECT_EQ(contents(a), "old model");
  size_t files = 0;
  for (const auto& entry : fs::directory_iterator(d)) files += entry.is_regular_file();
  EXPECT_EQ(files, 1u);  // nothing staged was left
  {
    OutputSet set;
    set.write(a.string(), [](const std::string& p) { writeFileAtomically(p, "new model"); });
    set.write(b.string(), [](const std::string& p) { writeFileAtomically(p, "{}"); });
    EXPECT_EQ(contents(a), "old model");  // not before commit
    set.commit();
  }
  EXPECT_EQ(contents(a), "new model");
  EXPECT_EQ(contents(b), "{}");
  fs::remove_all(d);
}
