// Shared by the unit tests of the scene driver: a contact Scene built
// from the text of a parameter file, quiet.
#ifndef dpana_tests_scene_test_tools_h
#define dpana_tests_scene_test_tools_h

#include <dpana/scene/run.h>
#include <dpana/scene/scene.h>

#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <utility>

#include <gtest/gtest.h>

namespace dpana
{
  namespace test
  {
    template <int dim>
    std::unique_ptr<scene::Scene<dim>>
    make_scene(const std::string &text, const unsigned int n_bodies = 1)
    {
      dealii::ParameterHandler prm;
      scene::declare_parameters(prm, {dim, n_bodies, true});
      prm.parse_input_from_string(text);
      auto s = std::make_unique<scene::Scene<dim>>();
      s->parse_parameters(prm, n_bodies, true);
      s->set_quiet(true);
      return s;
    }

    /**
     * The log of the first two phases of @p s (assembly and the contact
     * surface), where the warnings about the input are printed.
     */
    template <int dim>
    std::string
    contact_surface_log(scene::Scene<dim> &s)
    {
      s.set_quiet(false);
      testing::internal::CaptureStdout();
      s.assemble();
      s.build_contact_surface();
      return testing::internal::GetCapturedStdout();
    }

    /**
     * Body 1 of the 2D receding scene (the reference formulation,
     * section 4.2.1): the half
     * model [0, 40] x [0, 40] with @p nx x @p ny cells, symmetric on x = 0,
     * 50 MPa on the top and 100 MPa on the right side. @p material holds
     * entries of its Material subsection ("set Poisson's ratio = 0\n"),
     * @p rectangle more entries of its Rectangle subsection ("set Diagonals
     * = alternating\n"). With @p whole, the whole block [-40, 40] x [0, 40]
     * instead (@p nx cells across it), with 100 MPa on both sides and no
     * condition on x = 0.
     */
    inline std::string
    receding_block(const unsigned int nx,
                   const unsigned int ny,
                   const std::string &material,
                   const std::string &rectangle = "",
                   const bool         whole     = false)
    {
      return std::string("subsection Body 1\n"
                         "  subsection Geometry\n"
                         "    set Type = rectangle\n"
                         "    subsection Rectangle\n"
                         "      set Lower corner = ") +
             (whole ? "-40" : "0") +
             ", 0\n"
             "      set Upper corner = 40, 40\n"
             "      set Subdivisions = " +
             std::to_string(nx) + ", " + std::to_string(ny) + "\n" + rectangle +
             "    end\n"
             "  end\n"
             "  subsection Material\n" +
             material + "  end\n" +
             (whole ? "" :
                      "  subsection Boundary conditions\n"
                      "    set Symmetry = left\n"
                      "  end\n") +
             "  subsection Loads\n"
             "    set Pressure = top: 50; right: 100" +
             (whole ? "; left: 100" : "") +
             "\n"
             "  end\n"
             "end\n";
    }

    /**
     * |N| and the largest |T| component of the difference between the
     * tractions of element @p i of @p a and element @p j of @p b.
     */
    template <int dim>
    std::pair<double, double>
    traction_differences(const scene::Scene<dim> &a,
                         const unsigned int       i,
                         const scene::Scene<dim> &b,
                         const unsigned int       j)
    {
      double dT = 0;
      for (unsigned int k = 0; k + 1 < dim; ++k)
        dT = std::max(dT,
                      std::abs(a.tangential_traction(i, k) -
                               b.tangential_traction(j, k)));
      return {std::abs(a.normal_traction(i) - b.normal_traction(j)), dT};
    }

    /**
     * The size of the contact elements at the edge of the contact zone: the
     * largest tangential extent of the elements that begin inside it. The
     * half width a is known to this size (the element that ends the zone).
     */
    template <int dim>
    double
    contact_element_size(const scene::Scene<dim> &s)
    {
      double size = 0;
      for (const auto &e : s.surface(0).get_elements())
        if (e.s_min < s.summary().half_width)
          size = std::max(size, e.s_max - e.s_min);
      return size;
    }

    /**
     * The Hertz cylinder of the reference formulation, section 4.3, as a half
     * model: the
     * quarter disc R = 40 centred at (0, 40), 2 global refinements and @p m
     * contact refinements within 14 mm of the lowest point, loaded by
     * 100 kN/mm at the top of its axis; candidate surface the arc within
     * @p half_width of the origin, contact direction (0, -1), friction
     * coefficient @p mu. Without @p foundation the obstacle is the rigid
     * plane y = 0; otherwise @p foundation is the text of the subsections
     * of Body 2, whose boundary @p boundary_2 is the other side of the
     * contact. @p refinement_radius is the radius of the contact
     * refinements of the cylinder (mm), @p contact holds more entries of
     * the Contact subsection (e.g. a Reference subsection).
     */
    inline std::string
    hertz_prm(const unsigned int m,
              const double       half_width,
              const double       mu,
              const std::string &foundation        = "",
              const std::string &boundary_2        = "top",
              const double       refinement_radius = 14,
              const std::string &contact           = "")
    {
      return std::string("set Dimension = 2\n") +
             (foundation.empty() ? "" : "set Number of bodies = 2\n") +
             "subsection Body 1\n"
             "  subsection Geometry\n"
             "    set Type = quarter disc\n"
             "    set Global refinements = 2\n"
             "    subsection Quarter disc\n"
             "      set Radius = 40\n"
             "      set Centre = 0, 40\n"
             "      set Contact refinements = " +
             std::to_string(m) +
             "\n"
             "      set Contact refinement radius = " +
             std::to_string(refinement_radius) +
             "\n"
             "    end\n"
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
             "  set Boundary 2 = " +
             boundary_2 +
             "\n"
             "  set Candidate centre = 0, 0\n"
             "  set Candidate half width = " +
             std::to_string(half_width) +
             "\n"
             "  set Contact direction = 0, -1\n"
             "  set Friction coefficient = " +
             std::to_string(mu) + "\n" + contact + "end\n";
    }

    /**
     * Body 2 of hertz_prm(): a 40 x 40 foundation under the plane y = 0,
     * held only in x (free to move along the axis), pressed from below by
     * 2500 MPa over its 40 mm base, which balances the 100 kN/mm that press
     * the cylinder of hertz_prm() down (otherwise the contact could not hold
     * the pair, scene::check_held_by_contact()).
     */
    inline std::string
    floating_foundation()
    {
      return "  subsection Geometry\n"
             "    set Type = rectangle\n"
             "    subsection Rectangle\n"
             "      set Lower corner = 0, -40\n"
             "      set Upper corner = 40, 0\n"
             "      set Subdivisions = 8, 8\n"
             "    end\n"
             "  end\n"
             "  subsection Boundary conditions\n"
             "    set Symmetry = left\n"
             "    set Fixed = bottom: x\n"
             "  end\n"
             "  subsection Loads\n"
             "    set Pressure = bottom: 2500\n"
             "  end\n";
    }

    // A body of type rectangle or box between `lower` and `upper` with
    // `cells` subdivisions, with the given lines of its Boundary conditions
    // and Loads subsections.
    inline std::string
    brick_body(const std::string &name,
               const std::string &type,
               const std::string &lower,
               const std::string &upper,
               const std::string &cells,
               const std::string &conditions,
               const std::string &loads)
    {
      return "subsection " + name +
             "\n"
             "  subsection Geometry\n"
             "    set Type = " +
             type + "\n    subsection " +
             (type == "box" ? "Box" : "Rectangle") +
             "\n      set Lower corner = " + lower +
             "\n      set Upper corner = " + upper +
             "\n      set Subdivisions = " + cells +
             "\n"
             "    end\n"
             "  end\n"
             "  subsection Boundary conditions\n" +
             conditions +
             "  end\n"
             "  subsection Loads\n" +
             loads +
             "  end\n"
             "end\n";
    }
  } // namespace test
} // namespace dpana

#endif
