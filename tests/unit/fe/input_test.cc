// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// Checks of user input that do not need a run of the executable: the list
// syntax of the boundary entries, the quoting of input in messages, the
// material checks, and a boundary name
// that the mesh declares but no face carries.

#include <dpana/base/exceptions.h>
#include <dpana/body/body.h>
#include <dpana/parameters/list_syntax.h>
#include <dpana/parameters/parameters.h>

#include <deal.II/grid/grid_generator.h>

#include <gtest/gtest.h>

using namespace dpana;

TEST(Input, ListSyntax)
{
  const auto items =
    parameters::split_key_value_list("bottom: x, y; left: x ;", "P");
  ASSERT_EQ(items.size(), 2u);
  EXPECT_EQ(items[0].key, "bottom");
  EXPECT_EQ(items[0].value, "x, y");
  EXPECT_EQ(items[1].key, "left");
  EXPECT_EQ(parameters::parse_components(items[0].value, 2, "P"),
            (std::vector<bool>{true, true}));
  EXPECT_EQ(parameters::parse_components("all", 3, "P"),
            (std::vector<bool>{true, true, true}));
  EXPECT_TRUE(parameters::split_key_value_list("  ", "P").empty());

  const auto [mask, values] =
    parameters::parse_component_values("y = -0.01", 2, "P");
  EXPECT_EQ(mask, (std::vector<bool>{false, true}));
  EXPECT_DOUBLE_EQ(values[1], -0.01);

  // Errors name the entry.
  try
    {
      parameters::split_key_value_list("bottom x", "Body 1 / Fixed");
      FAIL() << "no exception";
    }
  catch (const InputError &e)
    {
      EXPECT_EQ(std::string(e.what()),
                "Body 1 / Fixed: item 'bottom x' has no colon (expected "
                "'name: value')");
    }
  EXPECT_THROW(parameters::parse_components("z", 2, "P"), InputError);
  EXPECT_THROW(parameters::parse_double("nan", "P"), InputError);
  EXPECT_THROW(parameters::parse_double("1.0x", "P"), InputError);
  EXPECT_THROW(parameters::parse_doubles("1, 2", 3, "P"), InputError);
}



TEST(Input, MaterialRanges)
{
  EXPECT_NO_THROW(Material(1.0, 0.49).check("M"));
  EXPECT_THROW(Material(1.0, 0.5).check("M"), InputError);
  EXPECT_THROW(Material(1.0, -1.0).check("M"), InputError);
  EXPECT_THROW(Material(0.0, 0.2).check("M"), InputError);
  EXPECT_THROW(Material(std::nan(""), 0.2).check("M"), InputError);
  // Plane stress lambda = E nu / (1 - nu^2); plane strain and 3D
  // lambda = E nu / ((1 + nu)(1 - 2 nu)).
  const Material m(100.0, 0.25, Material::PlaneState::plane_stress);
  EXPECT_DOUBLE_EQ(m.lambda(2), 100.0 * 0.25 / (1 - 0.0625));
  EXPECT_DOUBLE_EQ(m.lambda(3), 100.0 * 0.25 / (1.25 * 0.5));
  EXPECT_DOUBLE_EQ(m.mu(), 40.0);
}



TEST(Input, BoundaryNameCarriedByNoFace)
{
  Body<2> body;
  dealii::GridGenerator::subdivided_hyper_rectangle_with_simplices(
    body.triangulation(), {2, 2}, dealii::Point<2>(), dealii::Point<2>(1, 1));
  // All boundary faces keep id 0 ("outer"); "hole" is declared but absent.
  body.set_boundary_names({{"outer", 0}, {"hole", 7}});
  body.boundary_conditions().fixed.push_back(
    {"hole", {true, true}, "Body 1 / Boundary conditions / Fixed"});
  try
    {
      body.setup();
      FAIL() << "no exception";
    }
  catch (const InputError &e)
    {
      EXPECT_EQ(std::string(e.what()),
                "Body 1 / Boundary conditions / Fixed: no face of the mesh "
                "carries boundary 'hole' (id 7)");
    }
}



// Every message quotes input through parameters::quote(): unprintable bytes
// as \xNN, at most 60 characters.
TEST(Input, QuotedTextIsPrintableAndShort)
{
  EXPECT_EQ(parameters::quote("left"), "'left'");
  EXPECT_EQ(parameters::quote("a\x1b[2Jb\n"), "'a\\x1b[2Jb\\x0a'");
  const std::string digits(10000000, '1');
  EXPECT_EQ(parameters::quote(digits), "'" + digits.substr(0, 60) + "...'");
  try
    {
      parameters::parse_double(digits, "Body 1 / Loads / Pressure");
      FAIL() << "no exception";
    }
  catch (const InputError &e)
    {
      EXPECT_EQ(std::string(e.what()),
                "Body 1 / Loads / Pressure: '" + digits.substr(0, 60) +
                  "...' is not a finite number");
    }
  // The last guard of the printed line: no unprintable byte, no endless
  // word, whatever the exception says.
  const std::string line =
    parameters::one_line_message(std::runtime_error("x\x07 " + digits));
  EXPECT_EQ(line, "x\\x07 " + digits.substr(0, 100) + "...");
}
