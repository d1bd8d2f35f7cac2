// ---------------------------------------------------------------------
// Checkpoints of the sequentially linear control (<Solver/Control/Method> = sequentially linear,
// <Output/Checkpoint interval> in events): the run of app-solid/compact_tension_short (the
// compact-tension benchmark, blended FE-PD at dx = 2 mm, softening PMB bonds in 8 saw teeth, 56
// events to 0.85 of the peak, the peak at event 19) stopped after the checkpoint of event 28,
// past the peak, and restarted from it must end as the run that did not stop: the same events,
// particle and FE displacements bit for bit on the same number of ranks, statistics.csv the same
// file (no event lost or repeated). The peak (event 19) comes from the checkpoint: a restart
// that lost it would take the first event after the restart as the peak and end at another
// event, where the load falls below 0.85 of that. The harness
// (restart_tests.h) also stops on 1 rank and restarts on 2 and the other way round.
// ---------------------------------------------------------------------

#include <deal.II/base/mpi.h>

#include "restart_tests.h"

#include <tests.h>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();
  std::string text =
    coupling_tests::read_text(SOURCE_DIR "/../app-solid/compact_tension_short.prm.in");
  const std::string key = "@CMAKE_SOURCE_DIR@";
  text.replace(text.find(key), key.size(), SOURCE_DIR "/../..");
  restart_tests::check({"compact_tension", text, 0.5});
}
