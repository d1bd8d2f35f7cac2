// ---------------------------------------------------------------------
// Particles with rotations (x, y, rz) coupled to FE translations (linear elasticity, x, y)
// through the whole driver: the test model "rotational springs" (tests/rotational_springs.h)
// blended with elasticity, the slaved particles' rotations following 1/2 curl U. A rigid
// rotation is exact only if those rows are right: the springs' shear strain
// e_t = t . (u_j - u_i) - L (theta_i + theta_j) / 2 vanishes only if every particle turns with
// the body.
//  1. Static: the FE boundary turned by omega; the solve finds the rigid rotation everywhere
//     (translations and the free particles' rotations), with no strain energy.
//  2. Explicit: a rigid angular velocity Omega (v = Omega e_z x x, rotation rate Omega) stays
//     a rigid motion: no strain energy appears, the kinetic energy is conserved.
//  3. A problem whose FE translations the particles do not share is refused.
// 1 and 2 ranks.
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>

#include <perideal/coupling/coupled_problem.h>

#include "../rotational_springs.h"
#include "coupling_tests.h"

#include <cmath>
#include <iostream>
#include <map>
#include <string>

#include <tests.h>

namespace
{
  using coupling_tests::numbers_of;
  using coupling_tests::ok;

  const std::string base = R"(
set Dimension = 2
subsection Discretization
  set Lattice spacing = 1e-3
  set Horizon factor  = 3.015
  set Thickness       = 1e-3
  set Body            = strip
end
subsection Regions
  set Names = strip
  subsection strip
    set Shape        = box
    set Lower corner = 0, 0
    set Upper corner = 0.04, 0.012
  end
end
subsection Material
  set Model   = rotational springs
  set Density = 7800
end
subsection Finite elements
  set Physics             = PHYSICS
  set Generator           = subdivided_hyper_rectangle
  set Generator arguments = 20, 6 : 0, 0 : 0.04, 0.012 : true
  set Density             = 7800
  subsection Elasticity
    set Young's modulus = 2e11
    set Poisson's ratio = 0.3
  end
  subsection scalar laplace
    set Coefficient = 1
  end
  subsection Boundary conditions
CONDITIONS
  end
end
subsection Coupling
  set Blending function  = min(1, max(0, min((x - 0.01) / 0.005, (0.03 - x) / 0.005)))
  set Exact displacement = EXACT
end
subsection Initial conditions
  set Velocity = VELOCITY
end
subsection Solver
  set Type          = SOLVER
  set Linear solver = direct
end
subsection Time stepping
  set End time = END_TIME
end
subsection Output
  set Directory  = results
  set Write HDF5 = false
  set Progress   = false
end
)";

  std::string
  run(const std::map<std::string, std::string> &values)
  {
    return coupling_tests::run("micropolar_coupling.prm", coupling_tests::substitute(base, values));
  }

  // 1.
  void
  static_rotation()
  {
    // The whole FE boundary turned by omega = 1e-3.
    const std::string log = run({{"PHYSICS", "linear elasticity"},
                                 {"CONDITIONS",
                                  "    set Names = turned\n"
                                  "    subsection turned\n"
                                  "      set Boundary ids = 0, 1, 2, 3\n"
                                  "      set Function     = -1e-3 * y; 1e-3 * x\n"
                                  "    end"},
                                 {"EXACT", "-1e-3 * y; 1e-3 * x; 1e-3"},
                                 {"VELOCITY", "0"},
                                 {"SOLVER", "static"},
                                 {"END_TIME", "0"}});
    const auto        error =
      numbers_of(log, "Displacement error (largest, relative to the largest exact value): ");
    const double strain = numbers_of(log, "Strain energy: ")[0];
    // The energy a strain of the size of omega would store: E omega^2 V / 2.
    const double scale = 0.5 * 2e11 * 1e-6 * (0.04 * 0.012 * 1e-3);
    std::cout << "static rigid rotation 1e-3 rad: largest error / exact value at FE nodes < 1e-10 "
              << ok(error[0] < 1e-10) << ", at particles (x, y, rz) < 1e-10 "
              << ok(error[1] < 1e-10) << ", strain energy / (E omega^2 V / 2) < 1e-12 "
              << ok(std::abs(strain) < 1e-12 * scale) << std::endl;
  }

  // 2.
  void
  explicit_rotation()
  {
    // Omega = 10 rad/s about the origin for 2 us: rigid, no strain.
    const std::string log     = run({{"PHYSICS", "linear elasticity"},
                                     {"CONDITIONS", "    set Names ="},
                                     {"EXACT", ""},
                                     {"VELOCITY", "-10 * y; 10 * x; 10"},
                                     {"SOLVER", "explicit"},
                                     {"END_TIME", "2e-6"}});
    const double      kinetic = numbers_of(log, "Kinetic energy: ")[0];
    const double      strain  = numbers_of(log, "Strain energy: ")[0];
    const double      error   = numbers_of(log, "Energy error: ")[0];
    std::cout << "explicit rigid angular velocity 10 rad/s for 2 us: strain / kinetic energy "
                 "< 1e-12 "
              << ok(std::abs(strain) < 1e-12 * kinetic) << ", |energy error| / kinetic < 1e-12 "
              << ok(std::abs(error) < 1e-12 * kinetic) << std::endl;
  }

  // 3.
  void
  mismatch()
  {
    try
      {
        run({{"PHYSICS", "scalar laplace"},
             {"CONDITIONS", "    set Names ="},
             {"EXACT", ""},
             {"VELOCITY", "0"},
             {"SOLVER", "static"},
             {"END_TIME", "0"}});
        std::cout << "rotations over a scalar FE field accepted: FAILED" << std::endl;
      }
    catch (const dealii::ExceptionBase &exc)
      {
        std::cout << "rotations over a scalar FE field refused: "
                  << perideal_tests::exception_text(exc) << std::endl;
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
    std::cout.setstate(std::ios::failbit);
  static_rotation();
  explicit_rotation();
  mismatch();
}
