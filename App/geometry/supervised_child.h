// Running a whole command in a forked child that its parent watches (DESIGN.md "Files are
// untrusted"). OCCT's readers can hang on a truncated BREP and crash on a malformed STEP, and
// a crash anywhere in a geometry kernel must not leave a half-written output or an unexplained
// signal. The parent only waits: it learns from the child, over a pipe, which step it is in,
// which temporary files it has open and which outputs it has finished. When the child dies of
// a signal or runs past a step's time limit, the parent removes those files and says in one
// line which step failed and whether the input or holefill is to blame.
//
// One supervised child replaces the trial read in a throwaway child that readShape did
// before: a 1.5 MB BREP is parsed once instead of twice (20 ms of the CLI's 156 ms).
#pragma once

#include <functional>
#include <string>

namespace holefill {

// Exit code of a supervised command whose child crashed outside any input-reading step: a bug
// in holefill, reported as such; nothing it was writing is left behind.
constexpr int kSupervisedCrashExit = 4;

// Runs job in a forked child and returns its exit code. When the child dies of a signal, the
// parent prints one line on stderr (prefixed by `who`), removes the child's temporary and
// completed output files, and returns 1 if a step that blames its input was running, else
// kSupervisedCrashExit. When fork is unavailable, job runs in this process.
int runSupervised(const std::function<int()>& job, const std::string& who = "holefill");

// True inside the child of runSupervised.
bool supervised();

// A step of the child's work named in the user's words ("reading 'part.brep'"). While it lives,
// a crash is reported as this step's; with a time limit > 0 the child is stopped (SIGALRM) once
// the step runs longer. blameInput: a crash or timeout means the input is corrupt (exit 1), not
// a bug. Outside a supervised child it does nothing.
class SupervisedStep {
 public:
  SupervisedStep(const std::string& what, double timeLimitSeconds, bool blameInput);
  ~SupervisedStep();
  SupervisedStep(const SupervisedStep&) = delete;
  SupervisedStep& operator=(const SupervisedStep&) = delete;
};

// The child is filling this temporary file: the parent removes it if the child dies.
void noteTemporaryFile(const std::string& path);
// The child has finished this output: the parent removes it if the child dies later on.
void noteOutputWritten(const std::string& path);

}  // namespace holefill
