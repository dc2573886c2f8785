// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// The dpana executable:
//
//   dpana FILE.prm                    run the scene of FILE.prm: a contact
//                                     run if the file has a subsection
//                                     Contact (doc/contact.md), otherwise
//                                     an elastic run of one body
//   dpana --print-parameters [FILE]   print the documented parameter file
//                                     (defaults, or FILE's values completed
//                                     with the defaults) and exit
//
// Any error of the input (an unknown entry, a value out of range, a missing
// mesh file, a boundary name no face carries, a body that is not held) is
// reported as ONE line "dpana: error: ..." on stderr, with exit status 1,
// and leaves no output directory behind. A contact run whose solver did not
// converge exits with status 2 (unless Contact / Allow non-converged).

#include <dpana/base/exceptions.h>
#include <dpana/base/simulation.h>
#include <dpana/parameters/parameters.h>
#include <dpana/scene/contact_scene.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <iostream>
#include <string>

namespace
{
  template <int dim>
  int
  run(const std::string &filename, const bool print_parameters)
  {
    dealii::ParameterHandler prm;
    dpana::parameters::declare_dimension(prm);
    dpana::Simulation<dim>::declare_parameters(prm);
    if (!filename.empty())
      dpana::parameters::parse_file(prm, filename);

    if (print_parameters)
      {
        std::cout << "# dpana parameter file (Dimension = " << dim
                  << "); units: mm, N, MPa\n";
        prm.print_parameters(std::cout,
                             dealii::ParameterHandler::PRM |
                               dealii::ParameterHandler::KeepDeclarationOrder);
        return 0;
      }

    dpana::Simulation<dim> simulation;
    simulation.parse_parameters(prm);
    simulation.run(prm);
    return 0;
  }

  void
  usage(std::ostream &out)
  {
    out << "usage: dpana FILE.prm\n"
           "       dpana --print-parameters [FILE.prm]\n";
  }
} // namespace



int
main(int argc, char **argv)
{
  try
    {
      dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

      bool        print_parameters = false;
      std::string filename;
      for (int i = 1; i < argc; ++i)
        {
          const std::string arg = argv[i];
          if (arg == "--print-parameters")
            print_parameters = true;
          else if (arg == "-h" || arg == "--help")
            {
              usage(std::cout);
              return 0;
            }
          else if (!arg.empty() && arg[0] == '-')
            throw dpana::InputError("unknown option '" + arg + "'");
          else if (filename.empty())
            filename = arg;
          else
            throw dpana::InputError("more than one parameter file given");
        }
      if (filename.empty() && !print_parameters)
        {
          usage(std::cerr);
          return 1;
        }

      // The one pre-scan of the file: dimension, number of bodies, and
      // whether it describes a contact run.
      const dpana::parameters::FileOutline outline =
        filename.empty() ? dpana::parameters::FileOutline() :
                           dpana::parameters::scan_file(filename);

      // Contact runs have their own driver (bodies, condensation, contact
      // solver, recovery, output) and their own parameter set.
      if (outline.has_contact)
        {
          if (!print_parameters)
            return dpana::scene::run_contact(filename, outline);
          dealii::ParameterHandler prm;
          dpana::scene::declare_parameters(prm,
                                           outline.dimension,
                                           outline.n_bodies);
          dpana::parameters::parse_file(prm, filename);
          std::cout << "# dpana contact parameter file (Dimension = "
                    << outline.dimension << "); units: mm, N, MPa\n";
          prm.print_parameters(
            std::cout,
            dealii::ParameterHandler::PRM |
              dealii::ParameterHandler::KeepDeclarationOrder);
          return 0;
        }

      return outline.dimension == 2 ? run<2>(filename, print_parameters) :
                                      run<3>(filename, print_parameters);
    }
  catch (const std::exception &e)
    {
      std::cout << std::flush;
      std::cerr << "dpana: error: " << dpana::parameters::one_line_message(e)
                << std::endl;
      return 1;
    }
  catch (...)
    {
      std::cerr << "dpana: error: unknown exception" << std::endl;
      return 1;
    }
}
