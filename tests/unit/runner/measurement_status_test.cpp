// A measurement's status is typed (ok, skipped, failed) with its reason, and keeps the text form
// that results, tables and the dashboard carry.
#include <gtest/gtest.h>

#include <collido/runner/measurement_status.h>

namespace collido {
namespace {

TEST(MeasurementStatus, TextRoundTripsAndUnknownTextIsAFailure) {
  EXPECT_TRUE(MeasurementStatus().ok());
  EXPECT_EQ(MeasurementStatus().text(), "ok");
  const MeasurementStatus skipped = MeasurementStatus::skipped("ode does not answer all_pairs");
  EXPECT_TRUE(skipped.skipped());
  EXPECT_EQ(skipped.text(), "skipped: ode does not answer all_pairs");
  EXPECT_EQ(MeasurementStatus::fromText(skipped.text()), skipped);
  const MeasurementStatus failed = MeasurementStatus::failed("frame 3: engine failure: boom");
  EXPECT_TRUE(failed.failed());
  EXPECT_EQ(failed.reason(), "frame 3: engine failure: boom");
  EXPECT_EQ(MeasurementStatus::fromText(failed.text()), failed);
  EXPECT_EQ(MeasurementStatus::fromText("ok"), MeasurementStatus());
  const MeasurementStatus odd = MeasurementStatus::fromText("exploded");
  EXPECT_TRUE(odd.failed());
  EXPECT_EQ(odd.reason(), "exploded");
}

}  // namespace
}  // namespace collido
