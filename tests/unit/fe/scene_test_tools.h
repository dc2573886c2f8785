// Shared by the unit tests of the contact scene driver: a ContactScene built
// from the text of a parameter file, quiet.
#ifndef dpana_tests_scene_test_tools_h
#define dpana_tests_scene_test_tools_h

#include <dpana/scene/contact_scene.h>

#include <deal.II/base/parameter_handler.h>

#include <memory>
#include <string>

namespace dpana
{
  namespace test
  {
    template <int dim>
    std::unique_ptr<scene::ContactScene<dim>>
    make_scene(const std::string &text, const unsigned int n_bodies = 1)
    {
      dealii::ParameterHandler prm;
      scene::declare_parameters(prm, dim, n_bodies);
      prm.parse_input_from_string(text);
      auto s = std::make_unique<scene::ContactScene<dim>>();
      s->parse_parameters(prm, n_bodies);
      s->set_quiet(true);
      return s;
    }

    /**
     * The Hertz cylinder of seed 000, section 4.3, as a half model: the
     * quarter disc R = 40 centred at (0, 40), 2 global refinements and @p m
     * contact refinements within 14 mm of the lowest point, loaded by
     * 100 kN/mm at the top of its axis; candidate surface the arc within
     * @p half_width of the origin, contact direction (0, -1), friction
     * coefficient @p mu. Without @p foundation the obstacle is the rigid
     * plane y = 0; otherwise @p foundation is the text of the subsections
     * of Body 2 (its boundary `top` is the other side of the contact).
     */
    inline std::string
    hertz_prm(const unsigned int m,
              const double       half_width,
              const double       mu,
              const std::string &foundation = "")
    {
      return std::string("set Dimension = 2\n") +
             (foundation.empty() ? "" : "set Number of bodies = 2\n") +
             "subsection Body 1\n"
             "  subsection Geometry\n"
             "    set Type = quarter disc\n"
             "    set Radius = 40\n"
             "    set Centre = 0, 40\n"
             "    set Global refinements = 2\n"
             "    set Contact refinements = " +
             std::to_string(m) +
             "\n"
             "    set Contact refinement radius = 14\n"
             "  end\n"
             "  subsection Boundary conditions\n"
             "    set Symmetry = axis\n"
             "  end\n"
             "  subsection Loads\n"
             "    set Concentrated forces = 0, 40: 0, -100000\n"
             "  end\n"
             "end\n" +
             (foundation.empty() ?
                "" :
                "subsection Body 2\n" + foundation + "end\n") +
             "subsection Contact\n"
             "  set Boundary 1 = curved\n"
             "  set Boundary 2 = top\n"
             "  set Candidate centre = 0, 0\n"
             "  set Candidate half width = " +
             std::to_string(half_width) +
             "\n"
             "  set Contact direction = 0, -1\n"
             "  set Friction coefficient = " +
             std::to_string(mu) +
             "\n"
             "end\n";
    }
  } // namespace test
} // namespace dpana

#endif
