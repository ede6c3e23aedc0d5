#include "geometry/supervised_child.h"

#include <gtest/gtest.h>

#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "geometry/atomic_file.h"

using namespace holefill;
namespace fs = std::filesystem;

namespace {

fs::path scratch(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("hf_supervised_" + std::to_string(getpid()));
  fs::create_directories(d);
  return d / name;
}

// Leftovers of a child: any file in the scratch folder whose name starts with stem.
int filesStartingWith(const fs::path& stem) {
  int n = 0;
  for (const auto& e : fs::directory_iterator(stem.parent_path()))
    if (e.path().filename().string().rfind(stem.filename().string(), 0) == 0) ++n;
  return n;
}

}  // namespace

TEST(SupervisedChild, PassesTheChildsExitCodeAndItsOutputs) {
  const fs::path out = scratch("kept.txt");
  EXPECT_FALSE(supervised());
  const int code = runSupervised([&] {
    if (!supervised()) return 9;
    writeFileAtomically(out.string(), "kept\n");
    return 3;
  });
  EXPECT_EQ(code, 3);
  std::ifstream in(out);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "kept");
  EXPECT_EQ(filesStartingWith(out), 1);  // no temporary beside it
}

TEST(SupervisedChild, ACrashRemovesWhatTheChildWroteAndBlamesTheInputOnlyInAReadingStep) {
  const fs::path done = scratch("done.txt");
  const fs::path partial = scratch("partial.txt");
  testing::internal::CaptureStderr();
  const int bug = runSupervised([&] {
    writeFileAtomically(done.string(), "finished before the crash\n");
    const std::string tmp = temporaryFileFor(partial.string());
    std::ofstream(tmp) << "half";
    SupervisedStep step("building the face", 0, false);
    std::raise(SIGSEGV);
    return 0;
  });
  const std::string bugMessage = testing::internal::GetCapturedStderr();
  EXPECT_EQ(bug, kSupervisedCrashExit);
  EXPECT_NE(bugMessage.find("while building the face"), std::string::npos) << bugMessage;
  EXPECT_NE(bugMessage.find("bug in holefill"), std::string::npos) << bugMessage;
  EXPECT_EQ(filesStartingWith(done), 0);
  EXPECT_EQ(filesStartingWith(partial), 0);

  testing::internal::CaptureStderr();
  const int input = runSupervised([&] {
    SupervisedStep step("reading 'part.step'", 0, true);
    std::abort();
    return 0;
  });
  const std::string inputMessage = testing::internal::GetCapturedStderr();
  EXPECT_EQ(input, 1);
  EXPECT_NE(inputMessage.find("reading 'part.step' crashed"), std::string::npos) << inputMessage;
  EXPECT_NE(inputMessage.find("corrupt"), std::string::npos) << inputMessage;
}

TEST(SupervisedChild, AStepPastItsTimeLimitIsStoppedAndAFinishedOneLeavesNoTimer) {
  testing::internal::CaptureStderr();
  const int code = runSupervised([] {
    {
      SupervisedStep quick("reading 'quick.brep'", 5, true);
    }
    SupervisedStep hang("reading 'cut.brep'", 0.2, true);
    for (;;) pause();
    return 0;
  });
  const std::string message = testing::internal::GetCapturedStderr();
  EXPECT_EQ(code, 1);
  EXPECT_NE(message.find("reading 'cut.brep' took longer than 0.2 s"), std::string::npos) << message;
  EXPECT_NE(message.find("truncated"), std::string::npos) << message;

  // A finished step leaves no timer running: the child outlives the step's limit.
  EXPECT_EQ(runSupervised([] {
              { SupervisedStep quick("reading 'quick.brep'", 0.1, true); }
              usleep(300000);
              return 0;
            }),
            0);
}

TEST(SupervisedChild, StepsOutsideAChildDoNothing) {
  SupervisedStep step("reading 'x.brep'", 0.05, true);
  usleep(100000);  // no alarm: this process is not a supervised child
  SUCCEED();
}
