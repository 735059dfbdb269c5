// openflight/atomic_file.h: the final path never holds a partial file.
#include "openflight/atomic_file.h"
#include "cli_runner.h"

#include <gtest/gtest.h>

#include <fstream>

namespace cadlod::test {
namespace {

TEST(AtomicFile, FinalPathAppearsOnlyWhenComplete)
{
    const std::string dir = freshDirectory("atomic");
    const std::string path = dir + "/out.bin";
    std::string error;
    bool sawFinalDuringWrite = true;
    ASSERT_TRUE(flt::writeThroughTemporary(
        path,
        [&](const std::string& temporary) {
            std::ofstream(temporary) << "half";
            sawFinalDuringWrite = fileExists(path);
            return true;
        },
        error))
        << error;
    EXPECT_FALSE(sawFinalDuringWrite);
    EXPECT_EQ(readFile(path), "half");
    EXPECT_EQ(filesIn(dir).size(), 1u);
}

TEST(AtomicFile, FailedWriteLeavesTheOldFileAndNoTemporary)
{
    const std::string dir = freshDirectory("atomic_fail");
    const std::string path = dir + "/out.bin";
    std::ofstream(path) << "old";
    std::string error;
    EXPECT_FALSE(flt::writeThroughTemporary(
        path,
        [&](const std::string& temporary) {
            std::ofstream(temporary) << "partial";
            return false;
        },
        error));
    EXPECT_EQ(readFile(path), "old");
    EXPECT_EQ(filesIn(dir).size(), 1u);
    EXPECT_FALSE(error.empty());
}

TEST(AtomicFile, WritesBytes)
{
    const std::string dir = freshDirectory("atomic_bytes");
    std::string error;
    ASSERT_TRUE(flt::writeFileAtomically(dir + "/b", {1, 2, 3}, error)) << error;
    EXPECT_EQ(readFile(dir + "/b"), std::string("\x01\x02\x03", 3));
}

}  // namespace
}  // namespace cadlod::test
