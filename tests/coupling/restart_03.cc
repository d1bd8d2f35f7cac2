// ---------------------------------------------------------------------
// Checkpoint and restart of runs with softening Timoshenko bonds (explicit dynamics, coupled
// adaptive dynamic relaxation): the histories of the bonds are restored, a restarted run ends with
// the numbers of the run that did not stop.
// The harness, the cases and what is checked: restart_tests.h.
// ---------------------------------------------------------------------

#include <deal.II/base/mpi.h>

#include "restart_tests.h"

#include <tests.h>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();
  const auto cases = restart_tests::cases(SOURCE_DIR "/../app-solid/");
  for (unsigned int c = 3; c < 5; ++c)
    restart_tests::check(cases[c]);
}
