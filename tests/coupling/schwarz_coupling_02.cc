// ---------------------------------------------------------------------
// <Coupling/Method> = overlapping schwarz: iterations against the overlap width, and bad input.
//  1. The uniform-strain patch of schwarz_coupling_01 (PMB, dx = 1 mm, delta = 3.015 mm) on a
//     finer mesh (2 mm cells), the ramp width W of beta from 6 to 20 mm: Schwarz iterations to
//     the tolerance 1e-10 without relaxation and with Aitken's (from omega = 0.5). The
//     free parts overlap on about W - delta - h; the contraction of alternating Schwarz falls
//     as the overlap widens, so the counts fall with W; every run stays exact (error < 1e-8).
//  2. Bad input, each stopped with a message naming the entry: a ramp narrower than the horizon,
//     a ramp that leaves the FE nodes prescribed by the PD field next to the PD volume
//     constraint (narrower than a horizon plus an FE cell), explicit dynamics (<Solver/Type>),
//     a relaxation factor outside (0, 1], and a Schwarz
//     iteration stopped by <Maximum iterations> (its residual history, the state written).
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>

#include "coupling_tests.h"

#include <filesystem>
#include <iomanip>
#include <iostream>
#include <map>
#include <string>

#include <tests.h>

using namespace dealii;

namespace
{
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
  set Generator arguments = CELL_COUNT, CELL_COUNT : 0, 0 : 0.1, 0.1 : true
  set Density             = 7800
  subsection Elasticity
    set Young's modulus = 200e9
    set Poisson's ratio = 0.3333333333333333
  end
  subsection Boundary conditions
    set Names = boundary
    subsection boundary
      set Boundary ids = 0, 1, 2, 3
      set Function     = 1e-4*x + 2e-5*y; 3e-5*x - 5e-5*y
    end
  end
end
subsection Coupling
  set Method             = overlapping schwarz
  set Blending function  = min(1, max(0, min(min((x - 0.04 + RAMP_W) / RAMP_W, (0.06 + RAMP_W - x) / RAMP_W), min((y - 0.04 + RAMP_W) / RAMP_W, (0.06 + RAMP_W - y) / RAMP_W))))
  set Exact displacement = 1e-4*x + 2e-5*y; 3e-5*x - 5e-5*y
  subsection overlapping schwarz
    set Tolerance          = 1e-10
    set Maximum iterations = MAX_ITERATIONS
    set Relaxation         = RELAX_KIND
    set Relaxation factor  = RELAX_FACTOR
  end
end
subsection Solver
  set Type          = SOLVER_TYPE
  set Linear solver = direct
end
subsection Time stepping
  set End time = 1e-6
end
subsection Output
  set Directory  = results_schwarz
  set Write HDF5 = true
  set Progress   = false
end
)";

  std::map<std::string, std::string>
  values(const std::map<std::string, std::string> &changes)
  {
    std::map<std::string, std::string> result{{"CELL_COUNT", "50"},
                                              {"RAMP_W", "0.01"},
                                              {"MAX_ITERATIONS", "400"},
                                              {"RELAX_KIND", "none"},
                                              {"RELAX_FACTOR", "0.5"},
                                              {"SOLVER_TYPE", "static"}};
    for (const auto &[key, value] : changes)
      result[key] = value;
    return result;
  }

  // The Schwarz iterations of a run and whether its error is below 1e-8.
  std::pair<double, bool>
  iterations(const std::map<std::string, std::string> &changes)
  {
    const std::string log =
      coupling_tests::run("schwarz_width.prm", coupling_tests::substitute(base, values(changes)));
    const auto error =
      coupling_tests::numbers_of(log,
                                 "Displacement error (largest, relative to the largest exact "
                                 "value): ");
    return {coupling_tests::numbers_of(log, "Overlapping Schwarz: ")[0],
            std::max(error[0], error[1]) < 1e-8};
  }

  void
  bad_input(const std::string &name, const std::map<std::string, std::string> &changes)
  {
    const std::string file = "schwarz_bad_input.prm";
    coupling_tests::write_file(file, coupling_tests::substitute(base, values(changes)));
    try
      {
        std::ostringstream          log;
        perideal::CoupledProblem<2> problem(MPI_COMM_WORLD, log);
        coupling_tests::parse(problem, file);
        problem.setup();
        problem.run();
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

  std::cout << "Schwarz iterations to 1e-10 against the ramp width W (delta = 3.015 mm, h = 2 mm)"
            << std::endl
            << "| W [mm] | (W - delta - h) / delta | none | aitken |" << std::endl
            << "|---|---|---|---|" << std::endl;
  bool all_exact = true;
  for (const double width : {6., 8., 10., 14., 20.})
    {
      std::cout << "| " << width << " | " << std::fixed << std::setprecision(2)
                << (width - 3.015 - 2.) / 3.015 << std::defaultfloat;
      for (const std::string kind : {"none", "aitken"})
        {
          const auto [count, exact] =
            iterations({{"RAMP_W", std::to_string(width * 1e-3)}, {"RELAX_KIND", kind}});
          all_exact = all_exact && exact;
          std::cout << " | " << static_cast<unsigned int>(count);
        }
      std::cout << " |" << std::endl;
    }
  std::cout << "every run exact (error < 1e-8): " << (all_exact ? "yes" : "no (FAILED)")
            << std::endl;

  bad_input("ramp narrower than the horizon", {{"RAMP_W", "0.002"}});
  bad_input("ramp narrower than a horizon plus an FE cell",
            {{"RAMP_W", "0.005"}, {"CELL_COUNT", "20"}});
  bad_input("explicit dynamics", {{"SOLVER_TYPE", "explicit"}});
  bad_input("relaxation factor above 1", {{"RELAX_KIND", "fixed factor"}, {"RELAX_FACTOR", "1.5"}});
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    std::filesystem::remove_all("results_schwarz");
  MPI_Barrier(MPI_COMM_WORLD);
  bad_input("maximum iterations reached", {{"MAX_ITERATIONS", "3"}});
  std::cout << "  state written: "
            << (std::filesystem::exists("results_schwarz/solution_not_converged.xdmf") ? "yes" :
                                                                                         "no")
            << std::endl;
  return 0;
}
