// The backend's memory is measured apart from what the worker held before it started.
#include <collido/study/resident_memory.h>

#include <cstring>
#include <memory>

#include <gtest/gtest.h>

namespace collido::study {
namespace {

constexpr std::size_t kMebibyte = 1024 * 1024;

// Touched, so that the pages are resident; volatile reads keep the writes.
std::unique_ptr<char[]> touched(std::size_t bytes) {
  std::unique_ptr<char[]> block(new char[bytes]);
  std::memset(block.get(), 1, bytes);
  return block;
}

TEST(ResidentPeak, CountsWhatIsAddedAfterItAndNotWhatWasFreedBefore) {
  {
    const std::unique_ptr<char[]> before = touched(96 * kMebibyte);
    EXPECT_EQ(static_cast<volatile char*>(before.get())[kMebibyte], 1);
  }  // freed: the oracle's work in a worker
  const ResidentPeak peak;
  if (!peak.available()) GTEST_SKIP() << "/proc/self/clear_refs cannot reset the peak here";
  ASSERT_LT(*peak.addedBytes(), 32 * kMebibyte);
  {
    const std::unique_ptr<char[]> during = touched(64 * kMebibyte);
    EXPECT_EQ(static_cast<volatile char*>(during.get())[kMebibyte], 1);
  }
  const std::size_t added = *peak.addedBytes();
  EXPECT_GE(added, 60 * kMebibyte);
  EXPECT_LT(added, 90 * kMebibyte);  // not the 96 MiB freed before it
}

}  // namespace
}  // namespace collido::study
