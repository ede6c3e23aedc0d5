#include "geometry/supervised_child.h"

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <sstream>
#include <sys/prctl.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace holefill {

namespace {

// The child's end of the report pipe; -1 outside a supervised child.
int gReportFd = -1;

// One line per event, written with a single write(2) so that lines never interleave:
// S<limit>\t<blame 0|1>\t<what> a step begins, E it ends, T<path> temporary, D<path> done.
void report(const std::string& line) {
  if (gReportFd < 0) return;
  const std::string l = line + "\n";
  const char* p = l.data();
  size_t left = l.size();
  while (left > 0) {
    const ssize_t n = write(gReportFd, p, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;  // the parent is gone: the death signal follows
    p += n;
    left -= static_cast<size_t>(n);
  }
}

struct Step {
  std::string what;
  double limit = 0;
  bool blameInput = false;
};

struct ChildRecord {
  std::vector<Step> steps;
  std::vector<std::string> files;  // temporaries and finished outputs, both removed on a crash
};

void applyReport(const std::string& line, ChildRecord& rec) {
  if (line.empty()) return;
  const char kind = line[0];
  const std::string rest = line.substr(1);
  if (kind == 'S') {
    Step s;
    std::istringstream in(rest);
    std::string limit, blame;
    std::getline(in, limit, '\t');
    std::getline(in, blame, '\t');
    std::getline(in, s.what);
    s.limit = std::atof(limit.c_str());
    s.blameInput = blame == "1";
    rec.steps.push_back(s);
  } else if (kind == 'E') {
    if (!rec.steps.empty()) rec.steps.pop_back();
  } else if (kind == 'T' || kind == 'D') {
    rec.files.push_back(rest);
  }
}

std::string formatSeconds(double s) {
  std::ostringstream o;
  o << s;
  return o.str();
}

// The parent's one line about a child that died of signal sig, and the exit code to pass on.
int explainDeath(int sig, const ChildRecord& rec, const std::string& who) {
  for (const auto& f : rec.files) std::remove(f.c_str());
  const std::string name = std::string(strsignal(sig)) + ", signal " + std::to_string(sig);
  const std::string nothing = rec.files.empty() ? "" : "; its unfinished outputs were removed";
  const Step* step = rec.steps.empty() ? nullptr : &rec.steps.back();
  std::string msg;
  int code = kSupervisedCrashExit;
  if (step && sig == SIGALRM && step->limit > 0) {
    msg = step->what + " took longer than " + formatSeconds(step->limit) + " s";
    if (step->blameInput) {
      msg += ": the file is corrupt or truncated";
      code = 1;
    }
  } else if (step && step->blameInput) {
    msg = step->what + " crashed (" + name + "): the file is corrupt or not supported";
    code = 1;
  } else if (sig == SIGKILL) {
    msg = std::string("was killed (") + name + ")" + (step ? " while " + step->what : "") +
          ", perhaps for lack of memory";
  } else {
    msg = std::string("crashed (") + name + ")" + (step ? " while " + step->what : "") +
          ": this is a bug in holefill; please report it with the input";
  }
  std::fprintf(stderr, "%s: %s%s\n", who.c_str(), msg.c_str(), nothing.c_str());
  return code;
}

}  // namespace

bool supervised() { return gReportFd >= 0; }

int runSupervised(const std::function<int()>& job, const std::string& who) {
  int fds[2];
  if (pipe(fds) != 0) return job();
  std::cout.flush();
  std::fflush(nullptr);
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid < 0) {
    close(fds[0]);
    close(fds[1]);
    return job();
  }
  if (pid == 0) {
    close(fds[0]);
    gReportFd = fds[1];
    // A parent killed by a time limit of its own must not leave the child running.
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (getppid() != parent) _exit(kSupervisedCrashExit);
    int code = job();
    std::cout.flush();
    std::cerr.flush();
    std::fflush(nullptr);
    // The parent ends the process; the shapes' destructors would only cost time (6 ms on a
    // 1.5 MB model).
    _exit(code);
  }
  close(fds[1]);
  ChildRecord rec;
  std::string pending;
  char buf[4096];
  for (;;) {
    const ssize_t n = read(fds[0], buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    pending.append(buf, static_cast<size_t>(n));
    size_t nl;
    while ((nl = pending.find('\n')) != std::string::npos) {
      applyReport(pending.substr(0, nl), rec);
      pending.erase(0, nl + 1);
    }
  }
  close(fds[0]);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  if (WIFSIGNALED(status)) return explainDeath(WTERMSIG(status), rec, who);
  return kSupervisedCrashExit;
}

namespace {
// The time limits of the steps around the current one, to put back when it ends.
std::vector<itimerval> gOuterTimers;
}  // namespace

SupervisedStep::SupervisedStep(const std::string& what, double timeLimitSeconds, bool blameInput) {
  if (!supervised()) return;
  const double limit = timeLimitSeconds > 0 ? timeLimitSeconds : 0;
  report("S" + formatSeconds(limit) + "\t" + (blameInput ? "1" : "0") + "\t" + what);
  itimerval t{}, old{};
  if (limit > 0) {
    t.it_value.tv_sec = static_cast<time_t>(limit);
    t.it_value.tv_usec = static_cast<suseconds_t>((limit - static_cast<double>(t.it_value.tv_sec)) * 1e6);
    setitimer(ITIMER_REAL, &t, &old);
  } else {
    getitimer(ITIMER_REAL, &old);
  }
  gOuterTimers.push_back(old);
}

SupervisedStep::~SupervisedStep() {
  if (!supervised() || gOuterTimers.empty()) return;
  itimerval outer = gOuterTimers.back();
  gOuterTimers.pop_back();
  setitimer(ITIMER_REAL, &outer, nullptr);
  report("E");
}

void noteTemporaryFile(const std::string& path) { report("T" + path); }

void noteOutputWritten(const std::string& path) { report("D" + path); }

}  // namespace holefill
