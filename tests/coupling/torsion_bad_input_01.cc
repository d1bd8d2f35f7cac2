// ---------------------------------------------------------------------
// Bad input of torsion problems (the twist of 'scalar laplace' and 'antiplane bond based'): valid
// FE and PD files are accepted; each bad case stops, with a message naming the entry and the
// accepted values, before the solve: a twist axis outside the section (FE: outside the mesh,
// found right after the mesh is made; PD: outside the body, here the particles' section, found
// once the particles are made), a horizon that does not fit the section (fewer than two
// horizons across), the static linear solve with a PD twist (found when the file is read).
// ---------------------------------------------------------------------
#include <perideal/coupling/coupled_problem.h>

#include "coupling_tests.h"

#include <iostream>

#include <tests.h>

using namespace dealii;

namespace
{
  const std::string fe_file = R"(
set Dimension = 2
subsection Finite elements
  set Physics             = scalar laplace
  set Generator           = subdivided_hyper_rectangle
  set Generator arguments = 1, 2 : -0.5, -1 : 0.5, 1 : false
  set Global refinements  = 2
  subsection scalar laplace
    set Twist per unit length = 1
    set Twist axis            = AXIS
  end
end
subsection Solver
  set Type = static
end
subsection Output
  set Directory  = results
  set Write HDF5 = false
  set Progress   = false
end
)";

  const std::string pd_file = R"(
set Dimension = 2
subsection Discretization
  set Lattice spacing = SPACING
  set Horizon factor  = 3.015
  set Body            = section
end
subsection Regions
  set Names = section, hold
  subsection section
    set Shape        = box
    set Lower corner = -0.5, -1
    set Upper corner = 0.5, 1
  end
  subsection hold
    set Shape        = box
    set Lower corner = -0.01, -0.01
    set Upper corner = 0.11, 0.11
  end
end
subsection Material
  set Model   = antiplane bond based
  set Density = 1
  subsection antiplane bond based
    set Shear modulus         = 1
    set Twist per unit length = 1
    set Twist axis            = AXIS
  end
end
subsection Boundary conditions
  set Names = hold
  subsection hold
    set Region   = hold
    set Function = 0
  end
end
subsection Solver
  set Type = SOLVER
end
subsection Output
  set Directory  = results
  set Write HDF5 = false
  set Progress   = false
end
)";

  void
  run_case(const std::string                        &name,
           const std::string                        &base,
           const std::map<std::string, std::string> &values)
  {
    const std::string file = "torsion_bad_input.prm";
    coupling_tests::write_file(file, coupling_tests::substitute(base, values));
    try
      {
        std::ostringstream          log;
        perideal::CoupledProblem<2> problem(MPI_COMM_WORLD, log);
        coupling_tests::parse(problem, file);
        problem.setup();
        std::cout << name << ": accepted" << std::endl;
      }
    catch (const ExceptionBase &exc)
      {
        std::cout << name << ": " << perideal_tests::exception_text(exc) << std::endl;
      }
    MPI_Barrier(MPI_COMM_WORLD);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
    std::cout.setstate(std::ios::failbit);
  run_case("FE, valid input", fe_file, {{"AXIS", "0.1, -0.2"}});
  run_case("FE, twist axis outside the section", fe_file, {{"AXIS", "0.7, 0"}});
  const std::map<std::string, std::string> pd_valid = {{"SPACING", "0.1"},
                                                       {"AXIS", "0, 0"},
                                                       {"SOLVER", "adaptive dynamic relaxation"}};
  run_case("PD, valid input", pd_file, pd_valid);
  auto values    = pd_valid;
  values["AXIS"] = "0, 1.2";
  run_case("PD, twist axis outside the section", pd_file, values);
  values            = pd_valid;
  values["SPACING"] = "0.2";
  run_case("PD, fewer than two horizons across", pd_file, values);
  values           = pd_valid;
  values["SOLVER"] = "static";
  run_case("PD, static solve with a twist", pd_file, values);
}
