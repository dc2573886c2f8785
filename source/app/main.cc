// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// The dpana executable:
//
//   dpana FILE.prm                    run the scene of FILE.prm: its bodies
//                                     and, if the file has a subsection
//                                     Contact, their contact (doc/contact.md);
//                                     the phases are those of
//                                     dpana::scene::Scene (scene/scene.h)
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
#include <dpana/parallel/mpi_start.h>
#include <dpana/parallel/route.h>
#include <dpana/parameters/parameters.h>
#include <dpana/scene/run.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>

#include <iostream>
#include <optional>
#include <string>

namespace
{
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
  // Under mpirun every rank meets the same input errors; rank 0 reports
  // them.
  bool root = true;
  // MPI starts at once under mpirun, and otherwise only when the scene
  // needs it (MUMPS): a serial run on CHOLMOD saves MPI_Init's 0.4 s
  // (parallel/mpi_start.h). One thread for deal.II either way. MPI is
  // finalised when main() returns.
  std::optional<dealii::Utilities::MPI::MPI_InitFinalize> mpi;
  dpana::parallel::set_mpi_start([&]() { mpi.emplace(argc, argv, 1); });
  try
    {
      if (dpana::parallel::launched_by_mpirun())
        dpana::parallel::start_mpi();
      else
        dealii::MultithreadInfo::set_thread_limit(1);
      root = dpana::parallel::is_root();

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

      if (print_parameters)
        {
          if (root)
            dpana::scene::print_parameters(filename, std::cout);
          return 0;
        }
      return dpana::scene::run(filename);
    }
  catch (const std::exception &e)
    {
      std::cout << std::flush;
      if (root)
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
