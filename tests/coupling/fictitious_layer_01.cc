// ---------------------------------------------------------------------
// Declared fictitious layers (<Boundary conditions/NAME/Layer thickness> > 0 on a 'value'
// condition) against the depth the model's force reaches (MaterialModel::force_reach()): the
// square bar of doc/benchmarks/antiplane_square_bar (clamped sides) at dx = 0.02, horizon
// 3.015 dx, whose clamps are regions beyond the sides held at w = 0. A layer of 3 lattice
// layers (0.06) is deep enough for the bond-based model (delta - dx/2 = 0.0503) and too thin for
// the state-based one (2 delta - dx/2 = 0.1106: the held particles' shear angles would come from
// cut families): stopped with a message naming the entry and the accepted values, when the file
// is read. 6 layers (0.12) are accepted for the state-based model; an undeclared layer
// (thickness 0, a hold of any shape) is not checked.
// ---------------------------------------------------------------------
#include <perideal/coupling/coupled_problem.h>

#include "coupling_tests.h"

#include <iostream>

#include <tests.h>

using namespace dealii;

namespace
{
  void
  run_case(const std::string &name,
           const std::string &model,
           const double       depth,
           const double       declared)
  {
    const std::string text =
      "include " SOURCE_DIR "/../../doc/benchmarks/antiplane_square_bar/square_bar_pd.prm\n"
      "subsection Discretization\n  set Lattice spacing = 0.02\nend\n"
      "subsection Regions\n"
      "  subsection left\n    set Lower corner = " +
      std::to_string(-0.5 - depth) +
      ", -0.5\n  end\n"
      "  subsection right\n    set Upper corner = " +
      std::to_string(0.5 + depth) +
      ", 0.5\n  end\n"
      "  subsection top\n    set Lower corner = -0.5, 0.48\n  end\n"
      "end\n"
      "subsection Material\n  set Model = " +
      model +
      "\n  subsection antiplane state based\n    set Stabilization = 0.1\n  end\nend\n"
      "subsection Boundary conditions\n"
      "  subsection left\n    set Layer thickness = " +
      std::to_string(declared) +
      "\n  end\n"
      "  subsection right\n    set Layer thickness = " +
      std::to_string(declared) +
      "\n  end\n"
      "  subsection load\n    set Layer thickness = 0.02\n  end\n"
      "end\n"
      "subsection Output\n  set Directory  = results\n  set Write HDF5 = false\n"
      "  set Progress   = false\nend\n";
    const std::string file = "fictitious_layer.prm";
    coupling_tests::write_file(file, text);
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
  run_case("bond-based, 3 layers declared", "antiplane bond based", 0.06, 0.06);
  run_case("state-based, 3 layers declared", "antiplane state based", 0.06, 0.06);
  run_case("state-based, 6 layers declared", "antiplane state based", 0.12, 0.12);
  run_case("state-based, 3 layers not declared", "antiplane state based", 0.06, 0.);
}
