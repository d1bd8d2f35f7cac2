// ---------------------------------------------------------------------
// <Solver/Control/Load history> = time: load step k of N evaluates the condition functions at
// t = (k/N) End time, unscaled, so that a load path that is not proportional can be written as
// functions of t (the Nooru-Mohamed benchmark: a force applied and held, then a displacement).
// A PMB plate (20 x 10 mm, dx = 1 mm, no damage: linear) clamped on the left; the right column
// pulled in x by 10 um min(1, 2t) (applied, then held) and the top row loaded in y by
// 1 MPa max(0, 2t - 1) (only after t = 0.5). Each of the 4 load steps must equal a one-step
// proportional run whose End time is that step's t (the model is linear, so only the
// conditions at t matter): probes and reactions to round-off (direct solver). Negative control:
// the proportional 4-step run differs by O(1) at the steps before the last. Bad input: the event
// control with a time history; a time history with End time = 0.
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>

#include "coupling_tests.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>

using namespace dealii;

namespace
{
  const std::string plate = R"(
set Dimension = 2
subsection Discretization
  set Lattice spacing = 0.001
  set Horizon factor  = 3.015
  set Thickness       = 0.001
  set Body            = plate
end
subsection Regions
  set Names = plate, left, right, top
  subsection plate
    set Shape        = box
    set Lower corner = 0, 0
    set Upper corner = 0.02, 0.01
  end
  subsection left
    set Shape        = box
    set Lower corner = 0, 0
    set Upper corner = 0.001, 0.01
  end
  subsection right
    set Shape        = box
    set Lower corner = 0.019, 0
    set Upper corner = 0.02, 0.01
  end
  subsection top
    set Shape        = box
    set Lower corner = 0.001, 0.009
    set Upper corner = 0.019, 0.01
  end
end
subsection Material
  set Model        = bond based
  set Density      = 7800
  set Damage model = none
  subsection bond based
    set Young's modulus = 200e9
  end
end
subsection Boundary conditions
  set Names = clamp, pull, press
  subsection clamp
    set Region = left
    set Type   = value
  end
  subsection pull
    set Region     = right
    set Type       = displacement
    set Components = x
    set Function   = 1e-5 * min(1, 2 * t)
  end
  subsection press
    set Region          = top
    set Type            = traction
    set Function        = 0; 1e6 * max(0, 2 * t - 1)
    set Layer thickness = 0.001
  end
end
subsection Solver
  set Type          = static
  set Linear solver = direct
end
subsection Output
  set Directory    = DIRECTORY
  set Probe points = 0.0105, 0.0055; 0.0185, 0.0095
end
)";

  const std::vector<std::string> columns =
    {"probe1_x", "probe1_y", "probe2_x", "probe2_y", "reaction_clamp_x", "reaction_clamp_y"};

  // The statistics of the plate run with @p solver (<Solver> entries) and @p end_time.
  std::map<std::string, std::vector<double>>
  run_plate(const std::string &directory, const std::string &solver, const double end_time)
  {
    const std::string text =
      coupling_tests::substitute(plate, {{"DIRECTORY", directory}}) +
      "subsection Time stepping\n  set End time = " + std::to_string(end_time) +
      "\nend\nsubsection Solver\n" + solver + "end\n";
    coupling_tests::run(directory + ".prm", text);
    return perideal_tests::read_statistics(directory + "/statistics.csv");
  }

  // The largest difference of the columns in row @p row of @p a and the last row of @p b,
  // relative to the largest value of each column in @p b.
  double
  difference(const std::map<std::string, std::vector<double>> &a,
             const unsigned int                                row,
             const std::map<std::string, std::vector<double>> &b)
  {
    double largest = 0.;
    for (const auto &c : columns)
      {
        double scale = 0.;
        for (const double v : b.at(c))
          scale = std::max(scale, std::abs(v));
        largest = std::max(largest, std::abs(a.at(c)[row] - b.at(c).back()) / scale);
      }
    return largest;
  }

  // @p v, or 0 below round-off of @p scale (so that 1 and 2 ranks print the same).
  double
  clean(const double v, const double scale)
  {
    return std::abs(v) < 1e-10 * scale ? 0. : v;
  }

  void
  bad_case(const std::string &name, const std::string &overrides)
  {
    const std::string file = "bad_input.prm";
    coupling_tests::write_file(file,
                               coupling_tests::substitute(plate, {{"DIRECTORY", "bad"}}) +
                                 overrides);
    try
      {
        std::ostringstream          log;
        perideal::CoupledProblem<2> problem(MPI_COMM_WORLD, log);
        coupling_tests::parse(problem, file);
        problem.setup();
        problem.run();
        std::cout << name << ": accepted (FAILED)" << std::endl;
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
  std::cout << std::scientific << std::setprecision(2);

  const std::string history =
    "  set Load steps = 4\n  subsection Control\n    set Load history = time\n  end\n";
  const auto path = run_plate("time_history", history, 1.);
  // Row 0 is the unloaded state; row k the load step k.
  std::cout << "time history, 4 load steps: t, probe 2 (x, y) [um], reaction of the clamp (x, y) "
               "[N]"
            << std::endl;
  double largest = 0.;
  for (unsigned int k = 1; k <= 4; ++k)
    {
      const double t         = 0.25 * k;
      const auto   reference = run_plate("reference_" + std::to_string(k), "", t);
      const double d         = difference(path, k, reference);
      largest                = std::max(largest, d);
      std::cout << "  t = " << std::fixed << std::setprecision(2) << t << std::scientific << ": "
                << 1e6 * path.at("probe2_x")[k] << ", " << 1e6 * path.at("probe2_y")[k] << "; "
                << path.at("reaction_clamp_x")[k] << ", "
                << clean(path.at("reaction_clamp_y")[k], 1e3) << std::endl;
    }
  std::cout << "every step equals the proportional run at its t (largest relative difference "
               "below 1e-10): "
            << coupling_tests::ok(largest < 1e-10) << std::endl;

  // Negative control: the same file with the proportional history.
  const auto proportional = run_plate("proportional", "  set Load steps = 4\n", 1.);
  double     least        = 1e300;
  for (unsigned int k = 1; k <= 3; ++k)
    least = std::min(least,
                     difference(proportional,
                                k,
                                run_plate("reference_" + std::to_string(k), "", 0.25 * k)));
  std::cout << "negative control, proportional history: steps 1-3 differ from the runs at their t "
               "(smallest relative difference above 0.1): "
            << coupling_tests::ok(least > 0.1) << std::endl;

  bad_case("sequentially linear with a time history",
           "subsection Material\n  set Damage model = critical stretch\n"
           "  subsection critical stretch\n    set Critical stretch = 1e-3\n  end\nend\n"
           "subsection Solver\n  subsection Control\n    set Method = sequentially linear\n"
           "    set Load point = pull\n    set Load component = x\n"
           "    set Load history = time\n  end\nend\n");
  bad_case("time history with End time 0",
           "subsection Solver\n  subsection Control\n    set Load history = time\n  end\nend\n");
}
