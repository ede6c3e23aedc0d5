#include "geometry/outcome.h"

#include <algorithm>

#include "geometry/json_writer.h"

namespace holefill {

std::string toString(Status s) {
  switch (s) {
    case Status::Ok: return "ok";
    case Status::Warned: return "warned";
    case Status::Failed: return "failed";
    case Status::Cancelled: return "cancelled";
  }
  return "failed";
}

int exitCode(const Outcome& o) {
  switch (o.status) {
    case Status::Ok: return 0;
    case Status::Warned: return 3;
    case Status::Failed:
    case Status::Cancelled: return 2;
  }
  return 2;
}

int exitCode(const std::vector<Outcome>& all) {
  int code = 0;
  for (const Outcome& o : all) {
    const int c = exitCode(o);
    if (c == 2 || (c == 3 && code == 0)) code = c;
  }
  return code;
}

void writeOutcomeFields(JsonWriter& j, const Outcome& o) {
  j.field("status", toString(o.status)).field("failed_stage", o.stage).field("message", o.message);
}

}  // namespace holefill
