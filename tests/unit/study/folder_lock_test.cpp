// One study driver per folder: a second hold is refused, naming the holder's PID, and the hold
// ends with its owner.
#include <unistd.h>

#include <string>
#include <utility>

#include <gtest/gtest.h>

#include <collido/study/folder_lock.h>

#include "support/test_paths.h"

namespace collido::study {
namespace {

TEST(FolderLock, ASecondHoldIsRefusedNamingTheHolderUntilTheFirstEnds) {
  const std::string folder = test::makeTempDirectory("folder_lock") + "/study";
  {
    Result<FolderLock> first = FolderLock::acquire(folder);  // creates the folder
    ASSERT_TRUE(first.ok()) << first.status().message();
    const Result<FolderLock> second = FolderLock::acquire(folder);
    ASSERT_FALSE(second.ok());
    EXPECT_NE(second.status().message().find("in use by another collido study (PID " +
                                             std::to_string(getpid()) + ")"),
              std::string::npos)
        << second.status().message();
    FolderLock moved = std::move(first).value();  // the hold moves with the object
    EXPECT_FALSE(FolderLock::acquire(folder).ok());
  }
  EXPECT_TRUE(FolderLock::acquire(folder).ok());
}

}  // namespace
}  // namespace collido::study
