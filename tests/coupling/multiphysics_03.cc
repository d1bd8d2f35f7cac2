// ---------------------------------------------------------------------
// Cut load steps with several physics (<Solver/Control/Cut above broken bonds> with <Physics/
// List> = heat; doc/architecture/16_multiphysics.md): the plate of multiphysics_01 (20 mm x
// 10 mm, dx = 1 mm, PMB with a critical stretch of 1e-3) held on its left 3 mm and pulled on
// its right 3 mm by 1.5e-5 m in one static load step (a mean strain of about 1.07e-3 over the
// 14 mm between them), cut above 2 broken bonds, at most 2 cuts in a row: the bonds break one
// by one from a load factor of about 0.8 on, so the step is cut again and again (58 load steps
// kept). Its heat (bond based conduction, k = 50 W/(m K), rho c = 1 J/(m^3 K)) starts at 100 K
// in the left half and 0 in the right one, the left 3 mm held at 200 K and the right 3 mm at
// 0 K (scaled by the load factor for the steady heat); End time = 2 us, so
// the load factor f is the time f x 2 us. A cut try goes back to the last converged step for
// every physics (Checkpoint::restore_kept(): the heat's temperatures and sums, and the bonds
// the try broke), and the heat advances again to the time of the cut load factor. Checked, on
// 1 and 2 ranks, for an explicit heat (sub-cycled), an implicit one (one theta step per load
// step, shortened in a cut one) and a steady one (a static solve at each load factor tried):
//  - the tries that were cut and the kept load factors are those of the mechanics run alone,
//    and its displacements are equal to them, bit for bit;
//  - the temperatures equal those of the heat run alone by its own solver (start_state(),
//    advance()) over the kept steps only: from each kept load factor x End time to the next,
//    in the fewest equal steps of at most the heat's step, with the bonds broken as the heat of
//    the run saw them when it advanced (recorded through CoupledState::advance_other_physics),
//    bit for bit: the tries that were cut left nothing in the heat;
//  - the heat balance closes: the stored heat's change equals the heat in through the held
//    end (heat.heat_error of the last statistics row) to 1e-12 of it (explicit) or to the
//    solver's accuracy (implicit, a direct solve: 1e-10). Not for the steady heat: its
//    quasi-static energy balance does not hold once the mechanics breaks bonds under it (their
//    conductance goes without a dissipation the heat records).
// ---------------------------------------------------------------------

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <perideal/coupling/coupled_problem.h>

#include "coupling_tests.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include <tests.h>

using namespace dealii;

namespace
{
  enum class Fields
  {
    mechanics,
    heat,
    both
  };

  constexpr double end_time = 2e-6;

  // The plate: the mechanics in the top-level sections, the heat (@p heat_solver) in them
  // (alone) or in <Heat> (both).
  std::string
  input(const Fields fields, const std::string &heat_solver)
  {
    const std::string mechanics = coupling_tests::multiphysics_mechanics(true) + R"(
subsection Boundary conditions
  set Names = hold, pull
  subsection hold
    set Region = left
    set Type   = displacement
  end
  subsection pull
    set Region   = right
    set Type     = displacement
    set Function = 1.5e-5; 0
  end
end
subsection Solver
  set Type          = static
  set Load steps    = 1
  set Linear solver = direct
  subsection Control
    set Cut above broken bonds = 2
    set Maximum step cuts      = 2
  end
end
)";
    const std::string heat      = coupling_tests::multiphysics_conduction() + R"(
subsection Initial conditions
  set Displacement = if(x < 0.01, 100, 0)
end
subsection Boundary conditions
  set Names = hot, cold
  subsection hot
    set Region   = left
    set Function = 200
  end
  subsection cold
    set Region   = right
    set Function = 0
  end
end
subsection Solver
  set Type = )" + heat_solver +
                             R"(
end
)";
    const std::string text = coupling_tests::multiphysics_plate() + R"(
subsection Time stepping
  set End time = 2e-6
end
subsection Output
  set Directory  = results
  set Write HDF5 = false
  set Progress   = false
end
)";
    if (fields == Fields::mechanics)
      return text + mechanics;
    // Alone, the heat has the problem's solver entries (an implicit one: one step to the end).
    if (fields == Fields::heat)
      return text + heat + "subsection Solver\n  set Linear solver = direct\nend\n" +
             (heat_solver == "implicit" ?
                "subsection Time stepping\n  set Time step = 2e-6\nend\n" :
                "");
    return text + mechanics + coupling_tests::with_heat(heat);
  }

  // A step the heat took in the run: its start and length [s], the bond states it saw.
  struct HeatStep
  {
    double                    time = 0., dt = 0.;
    std::vector<std::uint8_t> intact;
  };

  struct Result
  {
    // Owned entries: the displacement, the temperature.
    std::vector<double> u, T;
    // The load factors of the kept load steps and the number of tries cut (from the log on rank
    // 0).
    std::vector<double> factors;
    unsigned int        cuts = 0;
    // The heat's steps (every try's, the cut ones too) and its step [s].
    std::vector<HeatStep> heat_steps;
    double                heat_step = 0.;
    // heat.heat_in and heat.heat_error of the last statistics row (rank 0; not of a steady
    // heat).
    double heat_in = 0., heat_error = 0.;
  };

  // The problem of @p fields, parsed from input() and set up.
  void
  set_up(perideal::CoupledProblem<2> &problem, const Fields fields, const std::string &heat_solver)
  {
    ParameterHandler                     prm;
    perideal::Physics<2>::ConditionNames heat;
    heat.particles = {"hot", "cold"};
    perideal::CoupledProblem<2>::declare_parameters(prm,
                                                    {"plate", "left", "right"},
                                                    fields == Fields::heat ?
                                                      std::vector<std::string>{"hot", "cold"} :
                                                      std::vector<std::string>{"hold", "pull"},
                                                    {},
                                                    {{"heat", heat}});
    prm.parse_input_from_string(input(fields, heat_solver));
    problem.parse_parameters(prm);
    deallog.push("run");
    problem.setup();
    deallog.pop();
  }

  Result
  run(const Fields fields, const std::string &heat_solver)
  {
    // The load factors in full in the log.
    std::ostringstream log;
    log << std::setprecision(17);
    perideal::CoupledProblem<2> problem(MPI_COMM_WORLD, log);
    set_up(problem, fields, heat_solver);
    Result      result;
    const auto &physics = problem.get_physics();
    auto       &state   = physics[0]->state();
    if (fields == Fields::both)
      {
        // Each step of the heat with the bond states it sees (one bond list for both physics).
        const auto advance = state.other_physics();
        state.set_other_physics(
          [&, advance](const unsigned int step, const double time, const double dt, const bool e) {
            if (step > 0)
              result.heat_steps.push_back({time, dt, state.pd().particles().bonds().intact});
            advance(step, time, dt, e);
          },
          state.other_physics_within_step());
      }
    deallog.push("run");
    problem.run();
    deallog.pop();
    const auto owned = [](const perideal::ParticleVector &v) {
      return std::vector<double>(v.begin(), v.begin() + v.locally_owned_size());
    };
    result.u = owned(state.u);
    if (fields == Fields::both)
      {
        result.T         = owned(physics[1]->state().u);
        result.heat_step = physics[1]->state().time_step;
      }
    std::istringstream lines(log.str());
    for (std::string line; std::getline(lines, line);)
      if (line.rfind("Load step ", 0) == 0 && line.find("cut to") != std::string::npos)
        ++result.cuts;
      else if (line.rfind("Load step ", 0) == 0 && line.find("solve(s)") != std::string::npos)
        result.factors.push_back(
          std::stod(line.substr(line.find("load factor ") + std::string("load factor ").size())));
    if (fields == Fields::both && Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      {
        const auto statistics = perideal_tests::read_statistics("results/statistics.csv");
        if (heat_solver != "static")
          {
            result.heat_in    = statistics.at("heat.heat_in").back();
            result.heat_error = statistics.at("heat.heat_error").back();
          }
      }
    return result;
  }

  // The heat run alone by its own solver over the kept steps of @p steps (a step is cut if the
  // next one starts at the same time), each in the fewest equal steps of at most @p step (as
  // CoupledProblem advances a physics of <Physics/List>), with the bond states of the step:
  // its temperatures.
  std::vector<double>
  heat_alone(const std::string &heat_solver, const std::vector<HeatStep> &steps, const double step)
  {
    std::ostringstream          log;
    perideal::CoupledProblem<2> problem(MPI_COMM_WORLD, log);
    set_up(problem, Fields::heat, heat_solver);
    auto &field = *problem.get_physics()[0];
    deallog.push("run");
    field.solver().start_state(field.state());
    for (std::size_t k = 0; k < steps.size(); ++k)
      {
        if (k + 1 < steps.size() && steps[k + 1].time == steps[k].time)
          continue;
        field.pd.particles().bonds().set_states(steps[k].intact);
        const double       time = steps[k].time, dt = steps[k].dt;
        const unsigned int n = std::max(1., std::ceil(dt / step * (1. - 1e-12)));
        for (unsigned int s = 0; s < n; ++s)
          field.solver().advance(field.state(), time + s * (dt / n), dt / n, s + 1 == n);
      }
    deallog.pop();
    const auto &T = field.state().u;
    return std::vector<double>(T.begin(), T.begin() + T.locally_owned_size());
  }

  // Whether @p a and @p b are equal bit for bit on every rank.
  bool
  equal(const std::vector<double> &a, const std::vector<double> &b)
  {
    return Utilities::MPI::min(static_cast<int>(a == b), MPI_COMM_WORLD) == 1;
  }

  void
  verdict(const std::string &what, const bool ok)
  {
    deallog << what << ": " << (ok ? "ok" : "FAILED") << std::endl;
  }

  void
  check(const std::string &heat_solver, const double balance_tolerance, const std::string &name)
  {
    const Result both      = run(Fields::both, heat_solver);
    const Result mechanics = run(Fields::mechanics, heat_solver);
    // The heat's step: its sub-step (explicit), the load step (implicit: one theta step;
    // steady: one solve).
    const double step = heat_solver == "explicit" ? both.heat_step : end_time;
    const auto   heat = heat_alone(heat_solver, both.heat_steps, step);
    deallog << heat_solver << " heat: " << both.cuts << " tries cut, " << both.factors.size()
            << " load steps kept, the first at the load factors";
    for (std::size_t k = 0; k < 3 && k < both.factors.size(); ++k)
      deallog << ' ' << both.factors[k];
    deallog << ", the last at " << (both.factors.empty() ? 0. : both.factors.back()) << std::endl;
    verdict("  tries cut and load factors kept as by the mechanics alone",
            both.cuts > 0 && both.cuts == mechanics.cuts && both.factors == mechanics.factors);
    verdict("  mechanics equal to the mechanics alone, bit for bit", equal(both.u, mechanics.u));
    verdict("  temperature equal to the heat alone over the same times, bit for bit",
            equal(both.T, heat));
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0 && heat_solver != "static")
      verdict("  heat in > 0, the balance closing to " + name + " of it",
              both.heat_in > 0. &&
                std::abs(both.heat_error) <= balance_tolerance * std::abs(both.heat_in));
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();
  deallog.depth_file(1);

  check("explicit", 1e-12, "1e-12");
  check("implicit", 1e-10, "1e-10");
  check("static", 0., "");
}
