// ---------------------------------------------------------------------
// Bad input of the adaptive PD region (<Coupling/Adaptive region>), on the strip of
// adaptive_region_01: a valid file is accepted; each bad case stops with a message naming the
// entry and the accepted values, when the file is read or at the set-up (before any output): a
// check interval of zero, thresholds outside their ranges, a strain region that does not parse,
// a ramp narrower than a horizon, a damage distance not inside the core, a lead distance beyond
// the core less the damage distance, initial seeds outside the body or without a criterion, the
// event-by-event control and implicit time steps (explicit steps and quasi-static load steps
// convert), checkpoints, no damage model, no FE mesh, an initial disk that reaches an FE boundary
// condition. A PD zone that would reach an FE boundary condition during the run
// stops the run at that check, before anything is converted: the statistics end with the row of
// the step before the check's conversion, the log with the message.
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>

#include "coupling_tests.h"

#include <iostream>
#include <string>

using namespace dealii;

namespace
{
  // An FE velocity condition on the left end (boundary id 0), x held at rest.
  const std::string left_condition = R"(
subsection Finite elements
  subsection Boundary conditions
    set Names = left
    subsection left
      set Boundary ids = 0
      set Type         = velocity
      set Components   = x
      set Function     = 0
    end
  end
end
)";

  void
  run_case(const std::string &name,
           const std::string &overrides,
           const std::string &seeds = "0.06, 0.01",
           const bool         run   = false)
  {
    const std::string file = "bad_input.prm";
    coupling_tests::write_file(
      file,
      coupling_tests::adaptive_strip("50, 10", "0", "principal strain", seeds) + overrides);
    try
      {
        std::ostringstream          log;
        perideal::CoupledProblem<2> problem(MPI_COMM_WORLD, log);
        coupling_tests::parse(problem, file);
        problem.setup();
        if (run)
          problem.run();
        std::cout << name << ": accepted" << std::endl;
      }
    catch (const ExceptionBase &exc)
      {
        std::cout << name << ": " << perideal_tests::exception_text(exc) << std::endl;
      }
    MPI_Barrier(MPI_COMM_WORLD);
  }

  std::string
  adaptive(const std::string &entries)
  {
    return "subsection Coupling\n  subsection Adaptive region\n" + entries + "  end\nend\n";
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
    std::cout.setstate(std::ios::failbit);
  run_case("valid input", "");
  run_case("check interval 0", adaptive("    set Check interval = 0\n"));
  run_case("strain fraction 0", adaptive("    set Strain fraction = 0\n"));
  run_case("strain region that does not parse", adaptive("    set Strain region = x +\n"));
  run_case("damage threshold 1", adaptive("    set Damage threshold = 1\n"));
  run_case("ramp narrower than a horizon", adaptive("    set Ramp width = 0.002\n"));
  run_case("damage distance outside the core",
           adaptive("    set Criterion = damage\n    set Damage distance = 0.009\n"));
  run_case("lead distance beyond the core less the damage distance",
           adaptive("    set Criterion = damage\n    set Damage distance = 0.0045\n"
                    "    set Lead distance = 0.005\n"));
  run_case("initial seed outside the body", "", "0.06, 0.01; 0.2, 0.01");
  run_case("initial seeds without a criterion", adaptive("    set Criterion = none\n"));
  run_case("event-by-event control",
           R"(
subsection Finite elements
  subsection Boundary conditions
    set Names = left
    subsection left
      set Boundary ids = 0
      set Components   = x
      set Function     = 1e-5
    end
  end
end
subsection Solver
  set Type = static
  subsection Control
    set Method     = sequentially linear
    set Load point = left
  end
end
)");
  run_case("implicit solver", "subsection Solver\n  set Type = implicit\nend\n");
  run_case("checkpoints", "subsection Output\n  set Checkpoint interval = 10\nend\n");
  run_case("no damage model", "subsection Material\n  set Damage model = none\nend\n");
  run_case("no FE mesh",
           "subsection Finite elements\n  set Generator =\nend\nsubsection Coupling\n  set "
           "Blending function = 0\nend\n");
  run_case("initial disk on an FE condition", left_condition, "0.005, 0.01");
  // The pulse at x = 20 mm flags cells whose disks reach the left end at the first check.
  run_case("PD zone reaching an FE condition during the run", left_condition, "0.06, 0.01", true);
  const auto stats = perideal_tests::read_statistics("results/statistics.csv");
  std::cout << "  last statistics row: step " << stats.at("step").back() << std::endl;
  // The pulse, reversed so that its half running right stretches (strain 2e-3), breaks bonds
  // in the ramp (beta < 1) of the disk at x = 60 mm on its way in, and the damage criterion's
  // first check that sees them stops the run: the zone did not lead the crack.
  run_case("crack outside the PD-only zone at a check",
           adaptive("    set Criterion = damage\n") +
             "subsection Material\n  subsection critical stretch\n    set Critical stretch = "
             "1e-3\n  end\nend\nsubsection Initial conditions\n  set Velocity = -20 * "
             "exp(-((x - 0.02) / 0.006)^2); 0\nend\n",
           "0.06, 0.01",
           true);
  const auto cracked = perideal_tests::read_statistics("results/statistics.csv");
  std::cout << "  last statistics row: step " << cracked.at("step").back() << std::endl;
}
