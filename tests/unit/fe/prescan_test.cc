// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// The pre-scan of a parameter file, parameters::scan_file(): the dimension,
// the number of bodies and whether the file is a contact run are read from
// the top level only, with the ParameterHandler's comment and continuation
// rules, and bad values are refused with a message that names the entry.

#include <dpana/base/exceptions.h>
#include <dpana/parameters/parameters.h>

#include <deal.II/base/parameter_handler.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <list>
#include <string>

#include "scratch_path.h"
#include <gtest/gtest.h>

using namespace dpana;

namespace
{
  // The files write_file() made, removed when the test program ends.
  std::list<dpana::test::ScratchFile> scratch_files;

  // Writes @p text to a file of the temporary directory and returns its
  // name.
  std::string
  write_file(const std::string &name, const std::string &text)
  {
    const auto &file = scratch_files.emplace_back("prescan_" + name);
    std::ofstream(file.path) << text;
    return file.path;
  }
} // namespace

TEST(PreScan, Defaults)
{
  const auto outline =
    parameters::scan_file(write_file("empty.prm", "subsection Output\nend\n"));
  EXPECT_EQ(outline.dimension, 2u);
  EXPECT_EQ(outline.n_bodies, 1u);
  EXPECT_FALSE(outline.has_contact);
}

TEST(PreScan, TopLevelOnly)
{
  // Entries of the same names inside subsections, a subsection Contact
  // nested in another one and commented-out lines do not count.
  const std::string text = "set Dimension=3   # a comment\n"
                           "# set Number of bodies = 1\n"
                           "set   Number of bodies   =  2\n"
                           "subsection Body 1\n"
                           "  set Dimension = 2\n"
                           "  subsection Contact\n"
                           "    set Number of bodies = 1\n"
                           "  end\n"
                           "end\n"
                           "subsection Body 2\n"
                           "end\n";
  const auto outline = parameters::scan_file(write_file("nested.prm", text));
  EXPECT_EQ(outline.dimension, 3u);
  EXPECT_EQ(outline.n_bodies, 2u);
  EXPECT_FALSE(outline.has_contact);

  const auto contact = parameters::scan_file(
    write_file("contact.prm",
               text + "subsection   Contact  # the contact run\nend\n"));
  EXPECT_TRUE(contact.has_contact);
}

TEST(PreScan, SameReadingAsTheParameterHandler)
{
  // A continued line and an escaped '#': the pre-scan must read the values
  // the ParameterHandler reads from the same file.
  const std::string        file = write_file("continued.prm",
                                      "set Dimension = \\\n  3\n"
                                             "set Title = a \\# b\n"
                                             "set Number of bodies = 2 # c\n"
                                             "subsection Body 2\nend\n");
  dealii::ParameterHandler prm;
  parameters::declare_dimension(prm);
  prm.declare_entry("Number of bodies", "1", dealii::Patterns::Integer(1, 2));
  prm.declare_entry("Title", "", dealii::Patterns::Anything());
  prm.enter_subsection("Body 2");
  prm.leave_subsection();
  parameters::parse_file(prm, file);
  const auto outline = parameters::scan_file(file);
  EXPECT_EQ(outline.dimension, prm.get_integer("Dimension"));
  EXPECT_EQ(outline.n_bodies, prm.get_integer("Number of bodies"));
  EXPECT_EQ(outline.dimension, 3u);
}

TEST(PreScan, Errors)
{
  const auto message = [](const std::string &file) -> std::string {
    try
      {
        parameters::scan_file(file);
      }
    catch (const InputError &e)
      {
        return e.what();
      }
    return "";
  };
  EXPECT_NE(message(write_file("dim.prm", "set Dimension = 4\n"))
              .find("dim.prm, line 1: Dimension: must be 2 or 3, got '4'"),
            std::string::npos);
  EXPECT_NE(
    message(write_file("bodies.prm",
                       "set Dimension = 2\n"
                       "set Number of bodies = \\\n 3\n"))
      .find("bodies.prm, line 2: Number of bodies: must be 1 or 2, got '3'"),
    std::string::npos);
  // A file that sets nothing, a directory, and the number of bodies
  // against the subsections and the contact boundary of Body 2.
  EXPECT_NE(message(write_file("comments.prm", "# nothing\n"))
              .find("comments.prm' sets nothing"),
            std::string::npos);
  EXPECT_NE(message(std::filesystem::temp_directory_path().string())
              .find("is a directory"),
            std::string::npos);
  EXPECT_NE(message(write_file("two.prm", "set Number of bodies = 2\n"))
              .find("two.prm, line 1: Number of bodies = 2, but the file has "
                    "no subsection 'Body 2'"),
            std::string::npos);
  EXPECT_NE(message(write_file("one.prm",
                               "subsection Contact\n  set Boundary 2 = top\n"
                               "end\n"))
              .find("one.prm, line 2: Contact / Boundary 2 is set in a run "
                    "with one body"),
            std::string::npos);
  EXPECT_NE(message("/nonexistent/dpana.prm")
              .find("cannot read parameter file '/nonexistent/dpana.prm'"),
            std::string::npos);
}

// The same entry set twice in one subsection is an error; the same name in
// two subsections, or a subsection entered twice with different entries,
// is not.
TEST(PreScan, EntrySetTwice)
{
  dealii::ParameterHandler prm;
  prm.declare_entry("Radius", "1", dealii::Patterns::Double());
  prm.enter_subsection("Body 1");
  prm.declare_entry("Radius", "1", dealii::Patterns::Double());
  prm.declare_entry("Width", "1", dealii::Patterns::Double());
  prm.leave_subsection();
  const std::string good = "set Radius = 2\n"
                           "subsection Body 1\n  set Radius = 3\nend\n"
                           "subsection Body 1\n  set Width = 4\nend\n";
  EXPECT_NO_THROW(parameters::parse_file(prm, write_file("once.prm", good)));
  const std::string twice = good + "subsection Body 1\n"
                                   "  set   Radius = 5 # again\n"
                                   "end\n";
  try
    {
      parameters::parse_file(prm, write_file("twice.prm", twice));
      FAIL() << "no exception";
    }
  catch (const InputError &e)
    {
      EXPECT_NE(std::string(e.what()).find(
                  "twice.prm, line 9: entry 'Radius' of subsection "
                  "'Body 1' is set twice (first on line 3)"),
                std::string::npos);
    }
}
