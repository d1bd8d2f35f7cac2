// ---------------------------------------------------------------------
// The stable explicit step of a two-way thermoelastic coupling (doc/theory/thermoelasticity.md,
// "The stable time step"): the coupled two-way plate of restart_multiphysics_01 (20 mm x 10 mm
// plane stress, PMB particles blended into Q1 elasticity, E = 200 GPa, its halves moving apart at
// 20 m/s; a heat of k = 50 W/(m K), rho c = 1 J/(m^3 K), insulated), with alpha = 1e-5 /K and
// T_0 = 300 K: the coupling number delta = T_0 beta : alpha / (rho c) = T_0 2 E alpha^2 /
// ((1 - nu) rho c) = 18000 in plane stress. Before, the step ignored it and the run exploded
// (energies of 1e42). The heat advances inside the mechanics' step (the adiabatic split of
// Armero and Simo, ThermoelasticHeating). Checks:
//  - the automatic step is the isothermal one over sqrt(1 + delta), the run is stable and its
//    energy error (kinetic + strain - work of the temperature - initial) stays at the
//    integration error;
//  - a <Time stepping/Time step> above it (the step of the isothermal limit) is refused before
//    anything is written, naming the entry and the coupling number;
//  - the measured limit: runs at 1, 2 and 2.5 times the computed step are stable (their energy
//    errors second order in the step), at 2.75 times it grows. The rule is safe; the factor
//    left is that of the isothermal Gershgorin step on this plate (its isothermal limit lies
//    between 1.6 and 1.8 times it) and of delta against the stiffening of the highest modes,
//    not of the split (the lagging split before grew above 4.5 times its step, half this one:
//    2.25 times this computed step).
// 1 and 2 ranks alike.
// ---------------------------------------------------------------------

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <perideal/coupling/coupled_problem.h>

#include "coupling_tests.h"

#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <tests.h>

using namespace dealii;

namespace
{
  // The two-way plate with the entries @p time_stepping in <Time stepping>.
  std::string
  input(const std::string &time_stepping)
  {
    const std::string heat = coupling_tests::multiphysics_conduction() + R"(
subsection Initial conditions
  set Displacement = 0
end
subsection Solver
  set Type = explicit
end
)" + coupling_tests::multiphysics_fe(true);
    return coupling_tests::multiphysics_plate() + R"(
subsection Time stepping
  set End time = 2e-6
)" + time_stepping +
           R"(
end
)" + coupling_tests::multiphysics_mechanics(false) +
           R"(
subsection Initial conditions
  set Velocity = if(x < 0.01, -20, 20); 0
end
subsection Material
  subsection bond based
    set Thermal expansion = 1e-5
  end
end
)" + coupling_tests::multiphysics_fe(false) +
           R"(
subsection Finite elements
  subsection Elasticity
    set Thermal expansion = 1e-5
  end
end
subsection Temperature
  set Source                         = heat
  set Reference temperature          = 0
  set Coupling                       = two way
  set Absolute reference temperature = 300
end
subsection Postprocess
  set List = energy statistics
end
)" + coupling_tests::with_heat(heat);
  }

  struct Result
  {
    std::string log;
    double      stable_dt = 0., largest_error = 0., largest_energy = 0.;
  };

  // Run @p text in @p directory; with @p factor > 0 at that factor of the computed stable step
  // (the safety factor's entry is limited to 1). The largest |energy error| and kinetic plus
  // strain energy of the rows, relative to the initial kinetic energy.
  Result
  run(const std::string &text, const std::string &directory, const double factor)
  {
    std::ostringstream                   log;
    perideal::CoupledProblem<2>          problem(MPI_COMM_WORLD, log);
    ParameterHandler                     prm;
    perideal::Physics<2>::ConditionNames heat;
    perideal::CoupledProblem<2>::declare_parameters(prm,
                                                    {"plate", "left", "right"},
                                                    {},
                                                    {},
                                                    {{"heat", heat}});
    prm.parse_input_from_string(text + "subsection Output\n  set Directory = " + directory +
                                "\n  set Progress = false\n  set Statistics interval = 1\nend\n");
    problem.parse_parameters(prm);
    problem.setup();
    auto &state = problem.get_physics()[0]->state();
    if (factor > 0.)
      state.time_step = factor * state.stable_dt;
    Result result;
    result.stable_dt = state.stable_dt;
    problem.run();
    result.log = log.str();
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      {
        const auto   statistics = perideal_tests::read_statistics(directory + "/statistics.csv");
        const double initial    = statistics.at("kinetic_energy").front();
        for (std::size_t r = 0; r < statistics.at("step").size(); ++r)
          {
            const double error = statistics.at("energy_error")[r];
            const double energy =
              statistics.at("kinetic_energy")[r] + statistics.at("strain_energy")[r];
            result.largest_error = std::isfinite(error) ?
                                     std::max(result.largest_error, std::abs(error) / initial) :
                                     INFINITY;
            result.largest_energy =
              std::isfinite(energy) ? std::max(result.largest_energy, energy / initial) : INFINITY;
          }
      }
    result.largest_error  = Utilities::MPI::broadcast(MPI_COMM_WORLD, result.largest_error, 0);
    result.largest_energy = Utilities::MPI::broadcast(MPI_COMM_WORLD, result.largest_energy, 0);
    return result;
  }

  // The line of @p log that starts with @p start.
  std::string
  line(const std::string &log, const std::string &start)
  {
    std::istringstream in(log);
    for (std::string l; std::getline(in, l);)
      if (l.rfind(start, 0) == 0)
        return l;
    return "(none)";
  }

  // Stable: the energy error of the run (kinetic + strain - work of the temperature - initial
  // energy; the work of the temperature moves up to 3000 KE_0 here) below 0.1 KE_0 at every row.
  void
  report(const std::string &name, const Result &r)
  {
    deallog << name << ": " << (r.largest_error < 0.1 ? "stable" : "unstable")
            << ", largest |energy error| / KE_0 "
            << (r.largest_error < 0.1 ? std::string("below 0.1") :
                r.largest_error < 1e3 ? std::string("above 0.1") :
                                        std::string("above 1e3"))
            << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();

  // The automatic step.
  const Result automatic = run(input(""), "automatic", 0.);
  deallog << line(automatic.log, "Two-way thermoelastic coupling") << std::endl;
  deallog << line(automatic.log, "Stable time step: FE") << std::endl;
  report("automatic step (safety factor 0.8)", automatic);

  // The former step: 0.8 of the isothermal limit, sqrt(1 + delta) times the computed one.
  const double isothermal = automatic.stable_dt * std::sqrt(1. + 18000.);
  deallog << "isothermal limit / computed limit: " << isothermal / automatic.stable_dt << std::endl;
  try
    {
      std::ostringstream step;
      step << std::setprecision(6) << "  set Time step = " << 0.8 * isothermal << "\n";
      run(input(step.str()), "refused", 0.);
      deallog << "fixed former step: not refused" << std::endl;
    }
  catch (const ExceptionBase &exc)
    {
      deallog << "fixed former step: " << perideal_tests::exception_text(exc) << std::endl;
    }
  deallog << "  nothing written: " << (std::filesystem::exists("refused") ? "no" : "yes")
          << std::endl;

  // The measured limit: the error of a stable run is the integration error, second order in
  // the step.
  std::vector<Result> runs;
  for (const double factor : {1., 2., 2.5, 2.75})
    {
      std::ostringstream name;
      name << factor << " x computed step";
      runs.push_back(run(input(""), "factor", factor));
      report(name.str(), runs.back());
    }
  deallog << "energy error at 1 x / at 0.8 x (automatic): " << std::setprecision(3)
          << runs[0].largest_error / automatic.largest_error << " (second order: 1.5625)"
          << "; at 2 x / at 1 x: " << runs[1].largest_error / runs[0].largest_error
          << " (second order: 4)" << std::endl;
}
