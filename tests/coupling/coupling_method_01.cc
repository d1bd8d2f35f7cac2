// ---------------------------------------------------------------------
// The coupling-method interface: a method defined outside the library (here, in the test) plugs
// into CoupledProblem through the registry, with no change to its solvers. The test method is a
// sharp interface: the FE energy where beta < 1/2, the particles' where beta >= 1/2 (bonds that
// cross the interface carry half their energy), particles in cells with FE unknowns slaved as in
// the blended method, whose equilibrium solve it reuses. On the plate of
// tests/app-solid/coupled_static_*_2d: a rigid translation is exact for both methods; in
// tension both balance the load exactly, and the sharp interface's ghost forces give a larger
// displacement error than the 10 mm blending ramp.
// ---------------------------------------------------------------------
#include <deal.II/base/parameter_handler.h>

#include <perideal/base/parameter_utilities.h>
#include <perideal/base/region.h>
#include <perideal/coupling/blended_coupling.h>
#include <perideal/coupling/coupled_problem.h>

#include "coupling_tests.h"

#include <fstream>
#include <iostream>
#include <sstream>

#include <tests.h>

using namespace dealii;

namespace
{
  template <int dim>
  class SharpInterface : public perideal::BlendedCoupling<dim>
  {
  public:
    double
    fe_weight(const double beta) const override
    {
      return beta < 0.5 ? 1. : 0.;
    }
    double
    particle_weight(const double beta) const override
    {
      return beta < 0.5 ? 0. : 1.;
    }
  };

  const std::string base = R"(
set Dimension = 2
subsection Discretization
  set Lattice spacing = 1e-3
  set Horizon factor  = 3.015
  set Thickness       = 1e-3
  set Body            = plate
end
subsection Regions
  set Names = plate
  subsection plate
    set Shape        = box
    set Lower corner = 0, 0
    set Upper corner = 0.1, 0.1
  end
end
subsection Material
  set Model   = bond based
  set Density = 7800
  subsection bond based
    set Young's modulus = 200e9
  end
end
subsection Finite elements
  set Generator           = subdivided_hyper_rectangle
  set Generator arguments = 25, 25 : 0, 0 : 0.1, 0.1 : true
  set Density             = 7800
  subsection Elasticity
    set Young's modulus = 200e9
    set Poisson's ratio = 0.3333333333333333
  end
  subsection Boundary conditions
CONDITIONS
  end
end
subsection Coupling
  set Method            = METHOD
  set Blending function = min(1, max(0, min(min((x - 0.03) / 0.01, (0.07 - x) / 0.01), min((y - 0.03) / 0.01, (0.07 - y) / 0.01))))
  set Exact displacement = EXACT
end
subsection Solver
  set Type          = static
  set Linear solver = direct
end
subsection Output
  set Directory  = results
  set Write HDF5 = false
  set Progress   = false
end
)";

  const std::string translation = R"(
    set Names = all
    subsection all
      set Boundary ids = 0, 1, 2, 3
      set Function     = 1e-6; 2e-6
    end)";

  const std::string tension = R"(
    set Names = left, bottom, right
    subsection left
      set Boundary ids = 0
      set Components   = x
      set Function     = 0
    end
    subsection bottom
      set Boundary ids = 2
      set Components   = y
      set Function     = 0
    end
    subsection right
      set Boundary ids = 1
      set Type         = traction
      set Function     = 20e6; 0
    end)";

  void
  run_case(const std::string &method,
           const std::string &conditions,
           const std::string &exact,
           const std::string &name)
  {
    const std::string file = "coupling_method.prm";
    coupling_tests::write_file(file,
                               coupling_tests::substitute(base,
                                                          {{"CONDITIONS", conditions},
                                                           {"METHOD", method},
                                                           {"EXACT", exact}}));
    std::ostringstream          log;
    perideal::CoupledProblem<2> problem(MPI_COMM_WORLD, log);
    coupling_tests::parse(problem, file);
    problem.setup();
    problem.run();
    MPI_Barrier(MPI_COMM_WORLD);

    // The lines that state the method and the verification numbers.
    std::cout << name << std::endl;
    std::istringstream lines(log.str());
    for (std::string line; std::getline(lines, line);)
      for (const std::string key :
           {"Coupling: ", "Reaction ", "Force balance", "Energy error", "Displacement error ("})
        if (line.rfind(key, 0) == 0)
          std::cout << "  " << line << std::endl;
  }
} // namespace

PERIDEAL_REGISTER_COUPLING_METHOD(SharpInterface,
                                  "sharp interface",
                                  "(test) FE energy where beta < 1/2, particles' elsewhere.")

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
    std::cout.setstate(std::ios::failbit);
  for (const std::string method : {"blended", "sharp interface"})
    {
      run_case(method, translation, "1e-6; 2e-6", method + ", rigid translation");
      run_case(method, tension, "1e-4*x; -1e-4*y/3", method + ", tension 20 MPa");
    }
}
