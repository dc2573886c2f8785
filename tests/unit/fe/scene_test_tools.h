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
  } // namespace test
} // namespace dpana

#endif
