// ---------------------------------------------------------------------
// Checkpoint and restart of runs without softening bonds (explicit dynamics with bond breaking,
// a static run with bond breaking, a coupled explicit run): a run stopped after a checkpoint and
// restarted from it ends with the numbers of the run that did not stop.
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
  for (unsigned int c = 0; c < 3; ++c)
    restart_tests::check(cases[c]);
}
