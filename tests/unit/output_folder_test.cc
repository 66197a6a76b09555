// One writer per output folder: another process or another holder in this process is refused
// until the holder lets go; the kinds of output do not mix.
#include "run/output_folder.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>

#include "temp_dir.h"

namespace crowdsim {
namespace {

using testing::TempDir;

TEST(OutputFolder, OneHolderAtATimeInThisProcessAndAcrossProcesses) {
  TempDir dir;
  std::string why;
  auto first = OutputFolderLock::Acquire(dir.path(), &why);
  ASSERT_TRUE(first) << why;
  // Another holder in this process (two Python threads evaluating into one folder).
  EXPECT_FALSE(OutputFolderLock::Acquire(dir.path(), &why));
  EXPECT_NE(why.find("this process is already writing into"), std::string::npos) << why;
  // Another process sees the lock (a POSIX record lock, as Python's lockf takes one).
  const std::string lock_file = (dir.path() / ".crowdsim-bench.lock").string();
  const std::string try_lock =
      "python3 -c \"import fcntl,sys; f=open(sys.argv[1],'a'); "
      "fcntl.lockf(f, fcntl.LOCK_EX | fcntl.LOCK_NB)\" " +
      lock_file + " 2>/dev/null";
  EXPECT_NE(std::system(try_lock.c_str()), 0) << "another process took the held lock";
  first.reset();
  EXPECT_EQ(std::system(try_lock.c_str()), 0) << "the lock outlived its holder";
  EXPECT_TRUE(OutputFolderLock::Acquire(dir.path(), &why)) << why;  // free again
}

TEST(OutputFolder, ARunAndATrainingDoNotShareAFolder) {
  TempDir dir;
  std::ofstream(dir.path() / "training.yaml") << "# copy of t.yaml\n";
  std::string why;
  EXPECT_FALSE(ClaimOutputFolder(dir.path(), "a suite run", &why));
  EXPECT_NE(why.find("holds a training (training.yaml); a suite run writes into a folder of its "
                     "own"),
            std::string::npos)
      << why;
  EXPECT_TRUE(ClaimOutputFolder(dir.path(), "a training", &why)) << why;
}

}  // namespace
}  // namespace crowdsim
