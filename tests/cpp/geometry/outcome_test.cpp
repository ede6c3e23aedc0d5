#include <gtest/gtest.h>

#include "geometry/json_reader.h"
#include "geometry/json_writer.h"
#include "geometry/outcome.h"

using namespace holefill;

TEST(Outcome, OneExitCodeRuleForEveryVerb) {
  Outcome ok, warned, failed, cancelled;
  warned.status = Status::Warned;
  failed.status = Status::Failed;
  cancelled.status = Status::Cancelled;
  EXPECT_EQ(exitCode(ok), 0);
  EXPECT_EQ(exitCode(warned), 3);
  EXPECT_EQ(exitCode(failed), 2);
  EXPECT_EQ(exitCode(cancelled), 2);
  // Of several (holefill fill --hole all), the worst; a failure outranks a missed goal in any order.
  EXPECT_EQ(exitCode(std::vector<Outcome>{}), 0);
  EXPECT_EQ(exitCode({ok, warned, ok}), 3);
  EXPECT_EQ(exitCode({warned, failed, ok}), 2);
  EXPECT_EQ(exitCode({failed, warned}), 2);
}

TEST(Outcome, ReportFieldsNameTheStatusStageAndMessage) {
  Outcome o;
  o.status = Status::Failed;
  o.stage = "solve";
  o.message = "the system is singular";
  JsonWriter j;
  j.beginObject();
  writeOutcomeFields(j, o);
  j.endObject();
  const JsonValue v = parseJson(j.str());
  EXPECT_EQ(v.find("status")->string, "failed");
  EXPECT_EQ(v.find("failed_stage")->string, "solve");
  EXPECT_EQ(v.find("message")->string, "the system is singular");
  EXPECT_EQ(toString(Status::Ok), "ok");
  EXPECT_EQ(toString(Status::Warned), "warned");
  EXPECT_EQ(toString(Status::Cancelled), "cancelled");
}
