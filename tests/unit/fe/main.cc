// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// The main() of the finite element unit tests. deal.II is built with MPI,
// PETSc and Trilinos, which must be initialised before (and finalised after)
// anything touches them, so GoogleTest runs inside MPI_InitFinalize, with a
// single thread to keep the two cores of a test machine for ctest itself.

#include <deal.II/base/mpi.h>

#include <gtest/gtest.h>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
