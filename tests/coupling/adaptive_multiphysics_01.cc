// ---------------------------------------------------------------------
// The adaptive PD region with several physics (<Physics/List> = heat; doc/architecture/
// 13_adaptive_region.md, 16_multiphysics.md): the strip of adaptive_region_01 (a velocity pulse
// in a free plane-strain strip, FE cells of 2 mm, a PD disk at x = 60 mm, the criterion
// 'principal strain', 120 explicit steps) with its heat: bond based conduction and FE heat,
// k = 18 W/(m K), rho c = 1 J/(m^3 K) (diffusivity 18 m^2/s: the heat moves 15 mm in the
// 12 us), an initial temperature 20 + 100 exp(-((x - 40 mm)/10 mm)^2) K and a source 1e6 exp(-((x -
// 60 mm)/10 mm)^2) W/m^3, insulated. Every conversion is inspected through the first physics'
// CoupledState::adapt_regions, wrapped around the problem's. Checked, on 1 and 2 ranks:
//  (a) the mechanics equal the same adaptive run without heat bit for bit (the same conversions:
//      the heat does not act on the mechanics), with the heat explicit (sub-cycled) and
//      implicit (one theta step per step);
//  (b) right after each conversion, the temperature of every particle that had no value of its
//      own (new, or slaved before) equals the old FE field at its lattice point (to 1e-12 of
//      the largest temperature; the test evaluates the Q1 field itself), free particles keep
//      theirs and the FE field keeps its values on the cells that keep unknowns, bit for bit;
//  (c) the heat balance closes over the conversions: the conversions' change of the stored
//      heat, summed in heat.conversion_heat, equals the change of the stored heat at each
//      conversion and heat.heat_error = stored - heat in - conversion heat stays at round-off
//      at every row (1e-12 of the heat exchanged explicit, 1e-9 implicit: the solver's
//      tolerance), while the conversion heat is 3.5 % of the heat in;
//  (d) a uniform temperature (20 K, no source) stays uniform across the conversions: every
//      particle and FE value equals 20 K to 1e-13 before and after each (the stored heat
//      changes by 20 K times the change of the lumped capacity, which the blended lumping does
//      not keep exactly; heat.conversion_heat takes it);
//  - a crack carried over once: the bonds across x = 60 mm near the initial disk's centre,
//    broken before the first conversion, are broken after it, and the heat's model sees them
//    broken (its flows of a unit temperature step across them are 0);
//  - checkpoints of the adaptive run with its heat are refused, as without heat.
// The explicit heat takes 3 sub-steps per step at the start and 4 after the first conversion,
// which lowers its stable step.
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>

#include "coupling_tests.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using namespace dealii;

namespace
{
  using Key = std::array<long, 2>;

  Key
  key_of(const Point<2> &x)
  {
    return {{std::lround(x[0] / 5e-4), std::lround(x[1] / 5e-4)}};
  }

  /// The strip of adaptive_region_01 (coarse FE cells), with its heat if @p solver is not empty.
  std::string
  input(const std::string &solver, const std::string &initial, const std::string &source)
  {
    const std::string strip =
      coupling_tests::adaptive_strip("50, 10", "0", "principal strain", "0.06, 0.01");
    if (solver.empty())
      return strip;
    return strip + coupling_tests::substitute(R"(
subsection Physics
  set List = heat
end
subsection Heat
  subsection Material
    set Model   = bond based conduction
    set Density = 1
    subsection bond based conduction
      set Conductivity  = 18
      set Specific heat = 1
    end
  end
  subsection Finite elements
    set Physics = heat
    set Density = 1
    subsection heat
      set Conductivity  = 18
      set Specific heat = 1
    end
  end
  subsection Initial conditions
    set Displacement = INITIAL
  end
  subsection Body force
    set Function = SOURCE
  end
  subsection Solver
    set Type = SOLVER
  end
end
)",
                                              {{"SOLVER", solver},
                                               {"INITIAL", initial},
                                               {"SOURCE", source}});
  }

  /// The heat's temperatures at a moment: the owned particles' by lattice point (and whether
  /// they were free), and the FE field at the lattice points of the cells with unknowns (every
  /// rank: all of them).
  struct Snapshot
  {
    std::map<Key, std::pair<double, bool>> particles;
    std::map<Key, double>                  fe;
    /// The largest |T - @p uniform| over the owned particles and FE dofs (all ranks).
    double deviation = 0.;
  };

  Snapshot
  snapshot(const perideal::Physics<2> &heat, const double uniform)
  {
    Snapshot    result;
    const auto &state  = heat.state();
    const auto &ps     = heat.pd.particles();
    const auto &slaved = heat.method().slaved_particles();
    double      local  = 0.;
    for (unsigned int i = 0; i < ps.n_owned(); ++i)
      {
        const double T                              = state.u.local_element(i);
        result.particles[key_of(ps.positions()[i])] = {T, !slaved[i]};
        local                                       = std::max(local, std::abs(T - uniform));
      }
    for (unsigned int k = 0; k < state.U.locally_owned_size(); ++k)
      local = std::max(local, std::abs(state.U.local_element(k) - uniform));
    result.deviation = Utilities::MPI::max(local, MPI_COMM_WORLD);

    // The Q1 field at the lattice points (the centres of the 1 mm lattice cells) inside each
    // owned cell with unknowns (the cells are rectangles of 2 mm).
    const double        dx = 1e-3;
    std::vector<double> values; // kx, ky, T per point
    state.U.update_ghost_values();
    Vector<double> dof_values;
    for (const auto &cell : heat.fe.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned() && cell->active_fe_index() == 0)
        {
          const auto &fe    = cell->get_fe();
          const auto  lower = cell->vertex(0), upper = cell->vertex(3);
          dof_values.reinit(fe.n_dofs_per_cell());
          cell->get_dof_values(state.U, dof_values);
          for (long i = std::lround(lower[0] / dx); (i + 0.5) * dx < upper[0]; ++i)
            for (long j = std::lround(lower[1] / dx); (j + 0.5) * dx < upper[1]; ++j)
              {
                const Point<2> x((i + 0.5) * dx, (j + 0.5) * dx);
                Point<2>       unit;
                for (unsigned int d = 0; d < 2; ++d)
                  unit[d] = (x[d] - lower[d]) / (upper[d] - lower[d]);
                double T = 0.;
                for (unsigned int k = 0; k < fe.n_dofs_per_cell(); ++k)
                  T += dof_values[k] * fe.shape_value(k, unit);
                const Key key = key_of(x);
                values.insert(values.end(), {double(key[0]), double(key[1]), T});
              }
        }
    for (const auto &part : Utilities::MPI::all_gather(MPI_COMM_WORLD, values))
      for (std::size_t k = 0; k + 3 <= part.size(); k += 3)
        result.fe[{{long(part[k]), long(part[k + 1])}}] = part[k + 2];
    return result;
  }

  /// What the inspection of the conversions found (the largest over them; counts summed).
  struct Inspection
  {
    unsigned int conversions = 0;
    // (b)
    double        interpolation_error = 0.;
    bool          free_kept = true, fe_kept = true;
    std::uint64_t interpolated = 0, kept = 0;
    // (c): the largest |change of the stored heat - change of conversion_heat| at a conversion,
    // and the largest |conversion change| itself [J].
    double heat_jump_error = 0., heat_jump = 0.;
    // (d)
    double deviation = 0.;
  };

  void
  compare(const Snapshot &before, const Snapshot &after, const double scale, Inspection &found)
  {
    double        error     = 0.;
    bool          free_kept = true, fe_kept = true;
    std::uint64_t interpolated = 0, kept = 0;
    for (const auto &[key, value] : after.particles)
      {
        const auto old = before.particles.find(key);
        if (old != before.particles.end() && old->second.second)
          {
            free_kept = free_kept && value.first == old->second.first;
            ++kept;
          }
        else
          {
            error = std::max(error, std::abs(value.first - before.fe.at(key)));
            ++interpolated;
          }
      }
    for (const auto &[key, T] : after.fe)
      fe_kept = fe_kept && T == before.fe.at(key);
    found.interpolation_error =
      std::max(found.interpolation_error, Utilities::MPI::max(error, MPI_COMM_WORLD) / scale);
    found.free_kept =
      found.free_kept && Utilities::MPI::min(free_kept ? 1 : 0, MPI_COMM_WORLD) == 1;
    found.fe_kept = found.fe_kept && fe_kept;
    found.interpolated += Utilities::MPI::sum(interpolated, MPI_COMM_WORLD);
    found.kept += Utilities::MPI::sum(kept, MPI_COMM_WORLD);
    found.deviation = std::max({found.deviation, before.deviation, after.deviation});
  }

  // The cut: the bonds across x = 60 mm with both ends within 7.5 mm of the initial disk's
  // centre (free particles of its PD-only zone before and after every conversion).
  const Point<2> centre(0.06, 0.01);

  bool
  crosses_cut(const Point<2> &a, const Point<2> &b)
  {
    return (a[0] - 0.06) * (b[0] - 0.06) < 0. && a.distance(centre) < 7.5e-3 &&
           b.distance(centre) < 7.5e-3;
  }

  /// Break the cut's bonds (as a crack would), returning how many (all ranks).
  std::uint64_t
  break_cut(perideal::ParticleSystem<2> &ps)
  {
    const auto   &x      = ps.positions();
    auto         &bonds  = ps.bonds();
    std::uint64_t broken = 0;
    for (unsigned int i = 0; i < ps.n_owned(); ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        if (crosses_cut(x[i], x[bonds.neighbor[b]]))
          {
            bonds.break_bond(b);
            ++broken;
          }
    return Utilities::MPI::sum(broken, MPI_COMM_WORLD);
  }

  /// After a conversion: the cut's bonds intact and broken, and the heat model's flows (its
  /// force kernel) with T = 1 beyond the cut and 0 before it at the particles within 4 mm of
  /// the centre (all their bonds across x = 60 mm are the cut's: the largest is 0 if the heat
  /// sees them broken), and how many of these lie within a horizon of the cut.
  struct CutCheck
  {
    std::uint64_t broken = 0, intact = 0, near = 0;
    double        largest_flow = 0.;
  };

  CutCheck
  check_cut(perideal::Physics<2> &heat)
  {
    CutCheck    found;
    auto       &ps    = heat.pd.particles();
    const auto &x     = ps.positions();
    const auto &bonds = ps.bonds();
    for (unsigned int i = 0; i < ps.n_owned(); ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        if (crosses_cut(x[i], x[bonds.neighbor[b]]))
          ++(bonds.intact[b] == 0 ? found.broken : found.intact);
    perideal::ParticleVector T, flow;
    ps.reinit_vector(T, 1);
    ps.reinit_vector(flow, 1);
    for (unsigned int i = 0; i < ps.n_owned(); ++i)
      T.local_element(i) = x[i][0] > 0.06 ? 1. : 0.;
    T.update_ghost_values();
    heat.pd.material().compute_forces(ps, T, flow, nullptr, heat.pd.critical_stretch());
    for (unsigned int i = 0; i < ps.n_owned(); ++i)
      if (x[i].distance(centre) < 4e-3)
        {
          found.largest_flow = std::max(found.largest_flow, std::abs(flow.local_element(i)));
          found.near += std::abs(x[i][0] - 0.06) < 3.015e-3;
        }
    found.broken       = Utilities::MPI::sum(found.broken, MPI_COMM_WORLD);
    found.intact       = Utilities::MPI::sum(found.intact, MPI_COMM_WORLD);
    found.near         = Utilities::MPI::sum(found.near, MPI_COMM_WORLD);
    found.largest_flow = Utilities::MPI::max(found.largest_flow, MPI_COMM_WORLD);
    return found;
  }

  struct Run
  {
    std::string                                log;
    std::map<Key, Tensor<1, 2>>                displacement; // rank 0: every particle
    std::map<std::string, std::vector<double>> statistics;
    Inspection                                 inspection;
    // With the cut: the bonds it broke before the first conversion, what it is after it.
    std::uint64_t cut_bonds = 0;
    CutCheck      cut;
  };

  /// The strip with the heat of @p solver (empty: without heat); @p uniform: the temperature
  /// against which the snapshots measure their deviation; @p cut: break the cut's bonds before
  /// the first conversion and check them after it.
  Run
  run(const std::string &solver,
      const std::string &initial,
      const std::string &source,
      const double       uniform = 0.,
      const bool         cut     = false)
  {
    coupling_tests::write_file("adaptive.prm", input(solver, initial, source));
    std::ostringstream          log;
    perideal::CoupledProblem<2> problem(MPI_COMM_WORLD, log);
    coupling_tests::parse(problem, "adaptive.prm");
    problem.setup();
    Run        result;
    const auto physics = problem.get_physics().size();
    if (physics > 1)
      {
        auto      &mechanics = problem.get_physics()[0]->state();
        const auto convert   = mechanics.adaptive_region();
        mechanics.set_adaptive_region(
          [&problem, &result, convert, uniform, cut](const unsigned int step, const double time) {
            perideal::Physics<2> &heat   = *problem.get_physics()[1];
            const Snapshot        before = snapshot(heat, uniform);
            const double          stored = heat.state().stored_heat(),
                         summed          = heat.state().conversion_energy;
            const bool first             = result.inspection.conversions == 0;
            if (cut && first && result.cut_bonds == 0)
              result.cut_bonds = break_cut(heat.pd.particles());
            if (!convert(step, time))
              return false;
            if (cut && first)
              result.cut = check_cut(heat);
            const Snapshot after = snapshot(heat, uniform);
            double         scale = 0.;
            for (const auto &[key, T] : before.fe)
              scale = std::max(scale, std::abs(T));
            compare(before, after, scale, result.inspection);
            const double jump = heat.state().stored_heat() - stored;
            result.inspection.heat_jump_error =
              std::max(result.inspection.heat_jump_error,
                       std::abs(jump - (heat.state().conversion_energy - summed)));
            result.inspection.heat_jump = std::max(result.inspection.heat_jump, std::abs(jump));
            ++result.inspection.conversions;
            return true;
          },
          mechanics.adaptation_interval());
      }
    problem.run();
    result.log             = log.str();
    const auto         &ps = problem.particles();
    const auto         &u  = problem.particle_displacement();
    std::vector<double> local;
    for (unsigned int i = 0; i < ps.n_owned(); ++i)
      local.insert(local.end(),
                   {ps.positions()[i][0],
                    ps.positions()[i][1],
                    u.local_element(2 * i),
                    u.local_element(2 * i + 1)});
    for (const auto &part : Utilities::MPI::gather(MPI_COMM_WORLD, local))
      for (std::size_t k = 0; k + 4 <= part.size(); k += 4)
        result.displacement[key_of(Point<2>(part[k], part[k + 1]))] =
          Tensor<1, 2>({part[k + 2], part[k + 3]});
    MPI_Barrier(MPI_COMM_WORLD);
    result.statistics = perideal_tests::read_statistics("results/statistics.csv");
    return result;
  }

  /// The largest |heat.heat_error| over the rows relative to the largest of the heat columns.
  double
  balance_error(const Run &run)
  {
    double error = 0., scale = 0.;
    for (const std::string column : {"heat.stored_heat", "heat.heat_in", "heat.conversion_heat"})
      for (const double value : run.statistics.at(column))
        scale = std::max(scale, std::abs(value));
    for (const double value : run.statistics.at("heat.heat_error"))
      error = std::max(error, std::abs(value));
    return error / scale;
  }

  /// The heat's sub-steps per mechanical step at the set-up and after each conversion, as the
  /// log of @p run gives them ("  n steps of ... per step of the first physics").
  std::string
  sub_steps(const Run &run)
  {
    std::istringstream lines(run.log);
    std::string        counts;
    for (std::string line; std::getline(lines, line);)
      if (line.find(" per step of the first physics") != std::string::npos)
        counts += (counts.empty() ? "" : " ") + std::to_string(std::stoi(line));
    return counts;
  }

  /// The inspection of @p run against @p mechanics, the run without heat; @p balance: the
  /// bound of the heat error relative to the heat exchanged.
  void
  report(const std::string &what, const Run &run, const Run &mechanics, const double balance)
  {
    const Inspection &found = run.inspection;
    std::cout << what << ": " << found.conversions << " conversions ("
              << coupling_tests::count_lines(run.log, "the PD region grew") << " logged, "
              << coupling_tests::count_lines(mechanics.log, "the PD region grew")
              << " without heat), " << run.displacement.size()
              << " particles at the end; the heat's sub-steps: " << sub_steps(run) << std::endl;
    std::cout << "  (a) mechanics equal to the run without heat, bit for bit: "
              << coupling_tests::ok(
                   run.displacement == mechanics.displacement &&
                   found.conversions ==
                     coupling_tests::count_lines(mechanics.log, "the PD region grew"))
              << std::endl;
    std::cout << "  (b) " << found.interpolated << " particle values from the old FE field, "
              << found.kept << " kept; equal to the old field to 1e-12 of the largest "
              << "temperature: " << coupling_tests::ok(found.interpolation_error <= 1e-12)
              << "; free particles keep theirs: " << coupling_tests::ok(found.free_kept)
              << "; FE values kept: " << coupling_tests::ok(found.fe_kept) << std::endl;
    const double conversion_heat = run.statistics.at("heat.conversion_heat").back();
    std::cout << "  (c) conversion heat " << conversion_heat << " J, heat in "
              << run.statistics.at("heat.heat_in").back() << " J; the change at each conversion "
              << "summed: " << coupling_tests::ok(found.heat_jump_error <= 1e-14 * found.heat_jump)
              << "; heat error within " << balance << " of the heat exchanged at every row: "
              << coupling_tests::ok(balance_error(run) <= balance) << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
    std::cout.setstate(std::ios::failbit);
  std::cout << std::setprecision(2);

  const std::string initial       = "20 + 100 * exp(-((x - 0.04) / 0.01)^2)";
  const std::string source        = "1e6 * exp(-((x - 0.06) / 0.01)^2)";
  const Run         mechanics     = run("", "", "");
  const Run         explicit_heat = run("explicit", initial, source);
  report("explicit heat", explicit_heat, mechanics, 1e-12);
  const Run implicit_heat = run("implicit", initial, source);
  report("implicit heat", implicit_heat, mechanics, 1e-9);

  // Checkpoints of an adaptive run are refused with the heat as without it (a restart does not
  // rebuild a grown region), when the file is read.
  {
    coupling_tests::write_file("adaptive.prm",
                               input("explicit", initial, source) +
                                 "subsection Output\n  set Checkpoint interval = 10\nend\n");
    std::ostringstream          log;
    perideal::CoupledProblem<2> problem(MPI_COMM_WORLD, log);
    std::string                 message = "accepted";
    try
      {
        coupling_tests::parse(problem, "adaptive.prm");
      }
    catch (const ExceptionBase &exc)
      {
        std::ostringstream info;
        exc.print_info(info);
        message = info.str();
      }
    std::cout << "checkpoints with heat refused as without: "
              << coupling_tests::ok(message.find("cannot be checkpointed yet") != std::string::npos)
              << std::endl;
  }

  // A crack across the PD-only zone (the cut's bonds broken before the first conversion) is
  // carried over once and insulates for the heat after it.
  const Run cut = run("explicit", initial, source, 0., true);
  std::cout << "cut: " << cut.cut_bonds << " bonds broken before the first conversion; after "
            << "it " << cut.cut.broken << " broken, " << cut.cut.intact << " intact: "
            << coupling_tests::ok(cut.cut_bonds > 0 && cut.cut.broken == cut.cut_bonds &&
                                  cut.cut.intact == 0)
            << "; the heat's flows of a unit step across it at the " << cut.cut.near
            << " particles within a horizon of it near the centre are 0: "
            << coupling_tests::ok(cut.cut.near > 0 && cut.cut.largest_flow == 0.) << std::endl;

  const Run uniform = run("explicit", "20", "0", 20.);
  std::cout << "uniform 20 K: " << uniform.inspection.conversions
            << " conversions; every value within 1e-13 of 20 K before and after them: "
            << coupling_tests::ok(uniform.inspection.deviation <= 20. * 1e-13)
            << "; the conversions' change of the stored heat (the lumped capacity's) "
            << uniform.statistics.at("heat.conversion_heat").back() << " J" << std::endl;
}
