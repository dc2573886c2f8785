// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// The quantities by which the serial and the MPI route are compared
// (tests/mpi/README.md):
//
//   dpana_route_outputs FILE.prm DIR      run the contact scene of FILE.prm
//                                         (every phase but the output) and
//                                         write, on rank 0, A, r and the
//                                         displacement of every body to DIR
//   dpana_route_outputs --compare D1 D2   compare two such directories:
//                                         ||x1 - x2|| / ||x2|| (Euclidean, A
//                                         as a vector: Frobenius) against
//                                         1e-10 for A and 1e-8 for r and u;
//                                         exit 1 if one is exceeded, a file
//                                         is missing or sizes differ
//   dpana_route_outputs --compare D1 D2 T the same with the one tolerance T
//                                         for A, r and u
//
// Started by mpirun with P ranks, the first form runs the MPI route on P
// ranks; without, the serial route.

#include <dpana/parallel/route.h>
#include <dpana/parameters/parameters.h>
#include <dpana/scene/run.h>
#include <dpana/scene/scene.h>

#include <deal.II/base/mpi.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

namespace
{
  void
  write(const std::string &file, const double *values, const std::size_t n)
  {
    std::ofstream out(file);
    out << std::setprecision(17);
    for (std::size_t i = 0; i < n; ++i)
      out << values[i] << '\n';
  }



  template <int dim>
  void
  run(const std::string                    &prm_file,
      const dpana::parameters::FileOutline &outline,
      const std::string                    &directory)
  {
    dealii::ParameterHandler prm;
    dpana::scene::declare_parameters(prm, outline);
    dpana::parameters::parse_file(prm, prm_file);
    dpana::scene::Scene<dim> scene;
    scene.set_quiet(true);
    scene.parse_parameters(prm, outline.n_bodies, outline.has_contact);
    scene.assemble();
    scene.build_contact_surface();
    scene.condense();
    scene.solve();
    scene.recover();
    if (!dpana::parallel::is_root())
      return;
    const auto &A = scene.problem().A;
    write(directory + "/A.txt", A.data(), A.size());
    const auto &r = scene.summary().result.r;
    write(directory + "/r.txt", r.data(), r.size());
    for (unsigned int b = 0; b < scene.n_bodies(); ++b)
      {
        // In the serial numbering of the dofs, which a body partitioned
        // over the ranks has renumbered by subdomains.
        const auto         &u = scene.displacement(b);
        std::vector<double> serial(u.size());
        for (unsigned int i = 0; i < u.size(); ++i)
          serial[scene.body(b).serial_dof_index(i)] = u[i];
        write(directory + "/u_" + std::to_string(b + 1) + ".txt",
              serial.data(),
              serial.size());
      }
  }



  bool
  read(const std::string &file, std::vector<double> &values)
  {
    std::ifstream in(file);
    double        x;
    values.clear();
    while (in >> x)
      values.push_back(x);
    return static_cast<bool>(std::ifstream(file));
  }



  // Whether the file @p name of the two directories agrees to @p tolerance.
  bool
  agrees(const std::string &d1,
         const std::string &d2,
         const std::string &name,
         const double       tolerance)
  {
    std::vector<double> x1, x2;
    if (!read(d1 + "/" + name, x1) || !read(d2 + "/" + name, x2) ||
        x1.size() != x2.size() || x1.empty())
      {
        std::cout << name << ": missing, empty or of different sizes ("
                  << x1.size() << ", " << x2.size() << ")" << std::endl;
        return false;
      }
    double difference = 0, norm = 0;
    for (std::size_t i = 0; i < x1.size(); ++i)
      {
        difference += (x1[i] - x2[i]) * (x1[i] - x2[i]);
        norm += x2[i] * x2[i];
      }
    const double relative = std::sqrt(difference / norm);
    std::cout << name << ": " << x1.size() << " values, relative difference "
              << relative << " (tolerance " << tolerance << ")" << std::endl;
    return relative <= tolerance;
  }
} // namespace



int
main(int argc, char **argv)
{
  try
    {
      dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
      if ((argc == 4 || argc == 5) && std::string(argv[1]) == "--compare")
        {
          const double tolerance_A = argc == 5 ? std::stod(argv[4]) : 1e-10;
          const double tolerance   = argc == 5 ? std::stod(argv[4]) : 1e-8;
          bool         ok = agrees(argv[2], argv[3], "A.txt", tolerance_A) &&
                    agrees(argv[2], argv[3], "r.txt", tolerance) &&
                    agrees(argv[2], argv[3], "u_1.txt", tolerance);
          std::ifstream second(std::string(argv[3]) + "/u_2.txt");
          if (second)
            ok = agrees(argv[2], argv[3], "u_2.txt", tolerance) && ok;
          return ok ? 0 : 1;
        }
      if (argc != 3)
        {
          std::cerr << "usage: dpana_route_outputs FILE.prm DIR\n"
                       "       dpana_route_outputs --compare DIR1 DIR2 "
                       "[TOLERANCE]\n";
          return 1;
        }
      const auto outline = dpana::parameters::scan_file(argv[1]);
      if (outline.dimension == 2)
        run<2>(argv[1], outline, argv[2]);
      else
        run<3>(argv[1], outline, argv[2]);
      return 0;
    }
  catch (const std::exception &e)
    {
      std::cerr << "dpana_route_outputs: " << e.what() << std::endl;
      return 1;
    }
}
