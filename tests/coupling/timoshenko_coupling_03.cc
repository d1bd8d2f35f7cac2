// The Timoshenko-bond model (rotations) blended with linear elasticity (issue #14, sec. 2), a
// static patch test through the overlap in 3D (timoshenko_coupling_01: 2D; _02: a rigid motion
// in 3D), the slaved particles taking u = P U and theta = 1/2 curl U: a general uniform strain
// with its rotation 1/2 curl u (nu = 0.2, overlap width W = 4 mm): the ghost force (the residual
// of the exact field relative to the FE force scale) and the largest errors of the FE nodes and
// the particles are reported; the energy balance closes. 1 and 2 MPI ranks.

#include "timoshenko_coupling.h"

int
main(int argc, char *argv[])
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();
  deallog.depth_file(1); // no iteration lines of the linear solvers
  report("3D uniform strain, nu = 0.2, W = 0.004 m",
         run<3>(input_3d,
                {{"FIELD3",
                  "1e-3*x + 0.5e-3*y + 0.2e-3*z; 0.3e-3*x - 0.2e-3*y + 0.1e-3*z; -0.4e-3*x + "
                  "0.3e-3*y + 0.4e-3*z"},
                 {"ROTATION3", "0.1e-3; 0.3e-3; -0.1e-3"}}),
         false);
}
