// The Timoshenko-bond model (rotations) blended with linear elasticity (issue #14, sec. 2), static
// patch tests through the overlap in 2D (timoshenko_coupling_02 and _03: 3D; cases apart, so that
// each stays short), the slaved particles taking u = P U and theta = 1/2 curl U:
//  1. a rigid translation and rotation (u = c + phi (-(y - y0), x - x0), theta = phi) is
//     reproduced to round-off (particles' displacements and rotations, FE nodes);
//  2. a uniform strain (nu = 0.1 and 0.2 on both sides, plane stress) with the overlap width
//     W = 4 and 8 mm: the ghost force (the residual of the exact field relative to the FE force
//     scale, halving when W doubles) and the largest errors of the FE nodes and the particles
//     (whose rotations, 1/2 curl of the FE field on slaved particles, carry gradient errors) are
//     reported; the energy balance closes.
// 1 and 2 MPI ranks.

#include "timoshenko_coupling.h"

int
main(int argc, char *argv[])
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();
  deallog.depth_file(1); // no iteration lines of the linear solvers
  // 1. Rigid motions.
  report("2D rigid (c + phi (-(y - 0.03), x - 0.03), theta = phi = 1e-3)",
         run<2>(input_2d,
                {{"NU", "0.2"},
                 {"WIDTH", "0.004"},
                 {"UX", "1e-6 - 1e-3*(y - 0.03)"},
                 {"UY", "-2e-6 + 1e-3*(x - 0.03)"},
                 {"RZ", "1e-3"}}),
         true);
  // 2. Uniform strain, ghost force against the overlap width.
  for (const std::string nu : {"0.1", "0.2"})
    for (const std::string width : {"0.004", "0.008"})
      report("2D uniform strain, nu = " + nu + ", W = " + width + " m",
             run<2>(input_2d,
                    {{"NU", nu},
                     {"WIDTH", width},
                     {"UX", "1e-3*x + 0.5e-3*y"},
                     {"UY", "-0.2e-3*y + 0.3e-3*x"},
                     {"RZ", "-1e-4"}}),
             false);
}
