// The Timoshenko-bond model (rotations) blended with linear elasticity (issue #14, sec. 2), a
// static patch test through the overlap in 3D (timoshenko_coupling_01: 2D; _03: a uniform strain
// in 3D; one case each, so that each stays short), the slaved particles taking u = P U and
// theta = 1/2 curl U: a rigid translation and rotation (u = c + phi x (x - x0), theta = phi) is
// reproduced to round-off (particles' displacements and rotations, FE nodes). 1 and 2 MPI ranks.

#include "timoshenko_coupling.h"

int
main(int argc, char *argv[])
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();
  deallog.depth_file(1); // no iteration lines of the linear solvers
  report("3D rigid (c + phi x (x - x0), theta = phi = (1, 2, 3) 1e-3)",
         run<3>(input_3d,
                {{"FIELD3",
                  "1e-6 + 1e-3*(2*(z - 0.012) - 3*(y - 0.012)); 1e-3*(3*(x - 0.012) - (z - "
                  "0.012)); -2e-6 + 1e-3*((y - 0.012) - 2*(x - 0.012))"},
                 {"ROTATION3", "1e-3; 2e-3; 3e-3"}}),
         true);
}
