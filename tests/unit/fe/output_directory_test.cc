// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// The output directory of a run is written all at once: afterwards it holds
// exactly that run's files; a run that fails leaves nothing behind and the
// previous results intact; a directory that holds other files is refused
// before any work.

#include <dpana/base/exceptions.h>
#include <dpana/output/output_directory.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include "scratch_path.h"
#include <gtest/gtest.h>

namespace
{
  namespace fs = std::filesystem;
  using dpana::output::OutputDirectory;

  // A fresh, empty directory for one test.
  fs::path
  sandbox(const std::string &name)
  {
    const fs::path p = dpana::test::scratch_path(name);
    fs::remove_all(p);
    fs::create_directories(p);
    return p;
  }

  void
  touch(const fs::path &file, const std::string &text = "x")
  {
    std::ofstream(file) << text;
  }

  std::set<std::string>
  listing(const fs::path &directory)
  {
    std::set<std::string> names;
    for (const auto &e : fs::directory_iterator(directory))
      names.insert(e.path().filename().string());
    return names;
  }
} // namespace



TEST(OutputDirectory, CommitReplacesTheFilesOfAnEarlierRun)
{
  const fs::path top = sandbox("commit");
  const fs::path out = top / "run";
  fs::create_directories(out);
  touch(out / "body_2.vtu");  // of an earlier two-body run
  touch(out / "contact.png"); // of an earlier run with a plot
  {
    OutputDirectory directory(out.string());
    touch(fs::path(directory.staging()) / "summary.json", "new");
    touch(fs::path(directory.staging()) / "body_1.vtu");
    // Until the commit, the earlier results are there, unchanged.
    EXPECT_TRUE(fs::exists(out / "body_2.vtu"));
    directory.commit();
  }
  EXPECT_EQ(listing(out),
            (std::set<std::string>{"body_1.vtu", "summary.json"}));
  EXPECT_EQ(listing(top), (std::set<std::string>{"run"}));
  fs::remove_all(top);
}



TEST(OutputDirectory, FailedRunLeavesNothingAndKeepsThePreviousResults)
{
  const fs::path top = sandbox("failed");
  fs::create_directories(top / "old");
  touch(top / "old" / "summary.json", "previous");
  {
    OutputDirectory directory((top / "old").string());
    touch(fs::path(directory.staging()) / "summary.json", "partial");
    // no commit: the run failed
  }
  {
    OutputDirectory directory((top / "a" / "b" / "new").string());
    EXPECT_TRUE(fs::exists(directory.staging()));
  }
  EXPECT_EQ(listing(top), (std::set<std::string>{"old"}));
  std::ifstream in(top / "old" / "summary.json");
  std::string   text;
  in >> text;
  EXPECT_EQ(text, "previous");
  fs::remove_all(top);
}



TEST(OutputDirectory, DirectoriesThatAreNotOutputAreRefused)
{
  const fs::path top = sandbox("refused");
  fs::create_directories(top / "notes");
  touch(top / "notes" / "my_notes.txt");
  touch(top / "file");
  EXPECT_THROW(OutputDirectory((top / "notes").string()), dpana::InputError);
  EXPECT_THROW(OutputDirectory((top / "file").string()), dpana::InputError);
  EXPECT_THROW(OutputDirectory("."), dpana::InputError);
  EXPECT_THROW(OutputDirectory("/proc/dpana_cannot_write_here"),
               dpana::InputError);
  EXPECT_EQ(listing(top), (std::set<std::string>{"notes", "file"}));
  EXPECT_EQ(listing(top / "notes"), (std::set<std::string>{"my_notes.txt"}));
  fs::remove_all(top);
}



// A directory written with a trailing separator, as a shell completes it,
// is that directory; it used to be refused as naming no directory of its
// own. The root still is refused.
TEST(OutputDirectory, TrailingSeparatorNamesTheDirectory)
{
  const fs::path top = sandbox("trailing");
  {
    OutputDirectory directory((top / "run").string() + "/");
    touch(fs::path(directory.staging()) / "summary.json");
    directory.commit();
  }
  EXPECT_EQ(listing(top / "run"), (std::set<std::string>{"summary.json"}));
  EXPECT_EQ(listing(top), (std::set<std::string>{"run"}));
  EXPECT_THROW(OutputDirectory("/"), dpana::InputError);
  fs::remove_all(top);
}
