// One status for every pipeline's Result (STYLE.md 3: say how it failed): Ok, Warned (the result
// is there but a goal was missed — a tolerance, the data, a valid shell, a hole left open),
// Failed (no result, and the stage that failed) or Cancelled; a one-line message, the warnings,
// and the elements at fault. Each Result maps its own diagnostics onto it once (outcome()), and
// the doors map an Outcome in one place each: the CLI's exit code (exitCode: 0 Ok, 3 Warned, 2
// Failed or Cancelled; 1 stays the CLI's own for refused arguments and input) and Python's
// HoleFillError (raised for Failed and Cancelled, from the report's "status").
#pragma once

#include <string>
#include <vector>

namespace holefill {

class JsonWriter;

enum class Status { Ok, Warned, Failed, Cancelled };

struct Outcome {
  Status status = Status::Ok;
  std::string stage;                  // the stage that failed (Failed, Cancelled); empty otherwise
  std::string message;                // one line: what was reached, or why not
  std::vector<std::string> warnings;  // what the user must still see when the result is Ok
  std::vector<int> faulting;          // the elements at fault (as the Result numbers them: 1-based B-rep edges, 0-based mesh holes)
};

std::string toString(Status s);  // "ok", "warned", "failed", "cancelled"

// The CLI's one rule: 0 Ok, 3 Warned, 2 Failed or Cancelled; of several, the worst.
int exitCode(const Outcome& o);
int exitCode(const std::vector<Outcome>& all);

// "status", "failed_stage", "message" into a report object the caller has open (its own
// "warnings" and fault lists stay the Result's).
void writeOutcomeFields(JsonWriter& j, const Outcome& o);

}  // namespace holefill
