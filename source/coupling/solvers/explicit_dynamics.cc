// ---------------------------------------------------------------------
// PeriDeal: explicit dynamics (velocity Verlet) of the coupled system.
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <perideal/base/parameter_utilities.h>
#include <perideal/base/progress_reporter.h>
#include <perideal/base/setup_times.h>
#include <perideal/coupling/communication_volume.h>
#include <perideal/coupling/solvers/explicit_dynamics.h>
#include <perideal/coupling/solvers/run_control.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <iomanip>
#include <limits>
#include <sstream>

namespace perideal
{
  using namespace dealii;

  template <int dim>
  void
  ExplicitDynamics<dim>::setup(CoupledState<dim> &state)
  {
    derive_from_regions(state);
    const auto &ps = state.pd().particles();
    AssertThrow(!state.layout().has_temperature() || state.settings().damping == 0.,
                ExcMessage("The parameter <Time stepping/Damping> is " +
                           ParameterUtilities::format_number(state.settings().damping) +
                           ", but the field of this problem is a temperature (first order in "
                           "time, no velocity to damp): accepted value 0."));
    // A two-way thermoelastic coupling: a step the user fixed above the coupled system's limit is
    // refused naming the coupling number (doc/theory/thermoelasticity.md).
    const double coupling = std::max(state.particle_coupling_number, state.fe_coupling_number);
    state.time_step       = ParameterUtilities::choose_time_step(
      state.settings().time_step,
      state.settings().safety_factor,
      state.stable_dt,
      coupling == 0. ?
              "this discretization" :
              "the two-way thermoelastic coupling (<Temperature/Coupling> = two way, coupling number "
              "T_0 beta : alpha / (rho c) = " +
          ParameterUtilities::format_number(coupling) +
          ": the adiabatic stiffness is 1 + that of the isothermal one)");
    if (state.is_root() && coupling > 0.)
      state.log() << "Two-way thermoelastic coupling: coupling number "
                  << state.particle_coupling_number << " (particles), " << state.fe_coupling_number
                  << " (FE); the mechanics' stable step is 1 / sqrt(1 + coupling number) of "
                     "the isothermal one"
                  << std::endl;
    if (state.is_root())
      {
        state.log() << "Stable time step:";
        if (state.fe().n_dofs() > 0)
          state.log() << " FE " << fe_dt << " s" << (ps.n_global() > 0 ? "," : "");
        if (ps.n_global() > 0)
          state.log() << " PD " << pd_dt << " s";
        state.log() << std::endl;
      }
  }

  template <int dim>
  void
  ExplicitDynamics<dim>::derive_from_regions(CoupledState<dim> &state)
  {
    using Motion          = typename CoupledState<dim>::Motion;
    const unsigned int nc = state.n_components();
    auto              &ps = state.pd().particles();
    state.fe().initialize_vector(state.mass);
    ps.reinit_vector(nodal_force, nc);
    state.method().lumped_masses(state.mass, state.particle_mass);
    // The factor from force (moment) density to acceleration: V_i over the inertia of the
    // component (m_i, or m_i times the ratio of a rotational inertia) on the components that
    // move by their acceleration, 0 on the others.
    const auto &volume = ps.volumes();
    acceleration_factor.assign(state.motion().size(), 0.);
    first_order_components.clear();
    for (std::size_t k = 0; k < state.motion().size(); ++k)
      if (state.motion()[k] == Motion::moves)
        {
          acceleration_factor[k] =
            volume[k / nc] / (state.particle_mass[k / nc] * state.inertia_ratio()[k % nc]);
          if (state.layout().kind(k % nc) == ComponentKind::temperature)
            first_order_components.push_back(k);
        }
    // The FE dofs carry the problem's field: a temperature moves by forward Euler.
    fe_first_order = state.layout().has_temperature();

    // The stable step: the smaller of the two regions'.
    fe_dt = state.fe().stable_time_step(&state.mass);
    pd_dt = state.pd().stable_time_step();
    // A two-way thermoelastic coupling stiffens the mechanics within its step to the adiabatic
    // stiffness, at most 1 + delta times the isothermal one: the adiabatic split is stable up to
    // velocity Verlet's limit at the adiabatic frequency (doc/theory/thermoelasticity.md, "The
    // stable time step").
    if (state.particle_coupling_number > 0.)
      pd_dt /= std::sqrt(1. + state.particle_coupling_number);
    if (state.fe_coupling_number > 0.)
      fe_dt /= std::sqrt(1. + state.fe_coupling_number);
    // A convection h (T_inf - T) / d adds h / d to the bound B of its layer's particles:
    // dt <= 2 rho c / (B + h / d) >= 1 / (1 / dt_B + h / (2 rho c d)) (conservative; rho c the
    // smallest of the particles, MaterialModel::inertia_scales()).
    const double convection = state.pd().boundary_conditions().convection_bound();
    if (convection > 0.)
      {
        const auto scales = state.pd().material().inertia_scales(ps, state.pd().density());
        double     smallest =
          scales.empty() && ps.n_owned() > 0 ? 1. : std::numeric_limits<double>::max();
        for (const double scale : scales)
          smallest = std::min(smallest, scale);
        smallest = Utilities::MPI::min(smallest, state.comm());
        for (unsigned int c = 0; c < nc; ++c)
          if (state.layout().kind(c) == ComponentKind::temperature)
            pd_dt = 1. / (1. / pd_dt + convection / (2. * smallest * state.pd().density() *
                                                     state.inertia_ratio()[c]));
      }
    state.stable_dt = std::min(fe_dt, pd_dt);
  }

  template <int dim>
  void
  ExplicitDynamics<dim>::adapt_regions(CoupledState<dim> &state,
                                       const unsigned int step,
                                       const double       time)
  {
    // The energies before (the energy density is current: a check step computes it).
    const auto   kinetic_before = state.kinetic_energy();
    const auto   strain_before  = state.strain_energy();
    const double before         = kinetic_before.total + strain_before.fe + strain_before.particles;
    // The cost of the check and of the conversion (the energies above belong to the check step).
    const auto          start_wall = std::chrono::steady_clock::now();
    const std::clock_t  start_cpu  = std::clock();
    const std::uint64_t n_before   = state.pd().particles().n_global();
    const auto          elapsed    = [&]() {
      return std::make_pair(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_wall).count(),
        double(std::clock() - start_cpu) / CLOCKS_PER_SEC);
    };
    if (!state.adapt_regions(step, time))
      {
        const auto [wall, cpu] = elapsed();
        ++adaptive_cost.checks;
        adaptive_cost.check_wall += wall;
        adaptive_cost.check_cpu += cpu;
        return;
      }
    derive_from_regions(state);
    AssertThrow(state.time_step <= state.stable_dt,
                ExcMessage("The conversion at t = " + ParameterUtilities::format_number(time) +
                           " s lowered the stable time step to " +
                           ParameterUtilities::format_number(state.stable_dt) +
                           " s, below the step of the run, " +
                           ParameterUtilities::format_number(state.time_step) +
                           " s: lower <Time stepping/Safety factor> (or <Time step>)."));
    renew_forces(state, time);
    {
      const auto [wall, cpu] = elapsed();
      ++adaptive_cost.conversions;
      adaptive_cost.conversion_wall += wall;
      adaptive_cost.conversion_cpu += cpu;
      adaptive_cost.added += state.pd().particles().n_global() - n_before;
    }
    const auto   kinetic = state.kinetic_energy();
    const auto   strain  = state.strain_energy();
    const double after   = kinetic.total + strain.fe + strain.particles;
    state.conversion_energy += after - before;
    if (state.is_root())
      state.log() << "  energy before " << before << " J (kinetic " << kinetic_before.total
                  << ", strain " << strain_before.fe + strain_before.particles << "), after "
                  << after << " J (kinetic " << kinetic.total << ", strain "
                  << strain.fe + strain.particles << "), change " << after - before
                  << " J, relative " << (before != 0. ? (after - before) / before : 0.)
                  << std::endl;
  }

  template <int dim>
  std::string
  ExplicitDynamics<dim>::adaptive_cost_summary(const CoupledState<dim> &state,
                                               const double             loop_seconds) const
  {
    const AdaptiveCost &c              = adaptive_cost;
    const double        conversion_cpu = Utilities::MPI::max(c.conversion_cpu, state.comm());
    const double        check_cpu      = Utilities::MPI::max(c.check_cpu, state.comm());
    // A step per particle: the loop without the checks and conversions over the particles
    // summed over the steps.
    const double step_wall =
      c.particle_steps > 0. ? (loop_seconds - c.conversion_wall - c.check_wall) / c.particle_steps :
                              0.;
    std::ostringstream out;
    out << "Adaptive region: " << c.conversions << " conversion" << (c.conversions == 1 ? "" : "s")
        << " (+" << c.added << " particles), wall " << c.conversion_wall << " s (CPU "
        << conversion_cpu << "), " << 100. * c.conversion_wall / loop_seconds
        << " % of the time loop";
    if (c.added > 0)
      {
        const double per_particle = c.conversion_wall / c.added;
        out << "; per converted particle " << 1e6 * per_particle << " us against "
            << 1e6 * step_wall << " us per step and particle ("
            << (step_wall > 0. ? per_particle / step_wall : 0.) << " steps' worth)";
      }
    out << "; " << c.checks << " checks without conversion, wall " << c.check_wall << " s (CPU "
        << check_cpu << ")";
    return out.str();
  }

  template <int dim>
  void
  ExplicitDynamics<dim>::renew_forces(CoupledState<dim> &state, const double time)
  {
    slave_particles(state);
    compute_acceleration(state, time, true);
    if (state.settings().damping > 0.)
      add_damping(state);
    state.carry_work();
  }

  template <int dim>
  void
  ExplicitDynamics<dim>::renew_regions(CoupledState<dim> &state, const double time)
  {
    setup(state);
    renew_forces(state, time);
  }

  template <int dim>
  void
  ExplicitDynamics<dim>::renew_rates(CoupledState<dim> &state, const double time)
  {
    // A temperature (the only field another physics changes) has no damping.
    slave_particles(state);
    compute_acceleration(state, time, false);
  }

  template <int dim>
  void
  ExplicitDynamics<dim>::slave_particles(CoupledState<dim> &state) const
  {
    state.method().interpolate_to_particles(state.U, state.u);
    state.u.update_ghost_values();
  }

  template <int dim>
  void
  ExplicitDynamics<dim>::compute_acceleration(CoupledState<dim> &state,
                                              const double       time,
                                              const bool         with_energy,
                                              const double       kick)
  {
    auto &pd = state.pd();
    state.update_temperature(time);
    // A changed temperature does work at the present displacements: the energy at it against
    // the energy at the temperature before, both with the bonds left after this evaluation.
    const bool heated = state.temperature_changed();
    pd.material().compute_forces(pd.particles(),
                                 state.u,
                                 state.internal_force,
                                 with_energy || heated ? &state.energy_density : nullptr,
                                 pd.critical_stretch());
    state.accumulate_dissipated_energy();
    if (heated)
      state.accumulate_temperature_jump();
    // The applied forces (zero since the set-up if there are none).
    const bool loads = pd.boundary_conditions().has_loads();
    if (loads)
      {
        state.external_force = 0.;
        pd.boundary_conditions().add_loads(time, state.external_force);
        if (pd.boundary_conditions().has_convection())
          pd.boundary_conditions().add_convection(time, &state.u, state.external_force);
      }
    // Particles: a = f V / m on the components that move by it, and v += kick a if asked (one
    // pass, no branches); the nodal forces f V only if some particle is slaved to the FE field
    // (zero otherwise).
    const std::size_t n        = state.motion().size();
    const double     *internal = state.internal_force.begin();
    const double     *applied  = state.external_force.begin();
    const double     *factor   = acceleration_factor.data();
    double           *a = state.a.begin(), *v = state.v.begin();
    const auto        accelerate = [&](const auto &force) {
      if (kick > 0.)
        for (std::size_t k = 0; k < n; ++k)
          {
            a[k] = force(k) * factor[k];
            v[k] += kick * a[k];
          }
      else
        for (std::size_t k = 0; k < n; ++k)
          a[k] = force(k) * factor[k];
    };
    if (loads)
      accelerate([&](const std::size_t k) { return internal[k] + applied[k]; });
    else
      accelerate([&](const std::size_t k) { return internal[k]; });
    auto &fe = state.fe();
    if (fe.n_dofs() == 0)
      return;
    if (state.any_particle_slaved())
      {
        const unsigned int nc     = state.n_components();
        const auto        &volume = pd.particles().volumes();
        double            *nodal  = nodal_force.begin();
        for (std::size_t k = 0; k < n; ++k)
          nodal[k] = (internal[k] + applied[k]) * volume[k / nc];
      }

    // FE: R = f_ext + f_th - K U + P^T f (the method's P^T; f_th the thermal load); prescribed
    // dofs do not move by it, and the work their supports do is that of K U - f_th - P^T f (the
    // part of R they balance).
    fe.assemble_load(time, state.f_ext);
    fe.stiffness_matrix().vmult(state.residual, state.U);
    state.residual.sadd(-1., 1., state.fe_equation_load());
    state.method().add_particle_forces(nodal_force, state.residual);
    const auto &mask = fe.prescribed_mask();
    for (unsigned int k = 0; k < state.U.locally_owned_size(); ++k)
      if (mask[k])
        {
          state.fe_load.local_element(k) =
            state.f_ext.local_element(k) - state.residual.local_element(k);
          state.A.local_element(k) = 0.;
        }
      else
        {
          state.fe_load.local_element(k) = state.f_ext.local_element(k);
          state.A.local_element(k) = state.residual.local_element(k) / state.mass.local_element(k);
        }
  }

  template <int dim>
  void
  ExplicitDynamics<dim>::set_first_order_rates(CoupledState<dim> &state) const
  {
    for (const std::size_t k : first_order_components)
      state.v.local_element(k) = state.a.local_element(k);
    if (fe_first_order)
      {
        const auto &mask = state.fe().prescribed_mask();
        for (unsigned int k = 0; k < state.U.locally_owned_size(); ++k)
          if (!mask[k])
            state.V.local_element(k) = state.A.local_element(k);
      }
  }

  template <int dim>
  void
  ExplicitDynamics<dim>::add_damping(CoupledState<dim> &state) const
  {
    // a -= c v with the half-step velocity on the dofs and particle components that move by
    // their acceleration.
    using Motion      = typename CoupledState<dim>::Motion;
    const double c    = state.settings().damping;
    const auto  &mask = state.fe().prescribed_mask();
    for (unsigned int k = 0; k < state.U.locally_owned_size(); ++k)
      if (!mask[k])
        state.A.local_element(k) -= c * state.V.local_element(k);
    for (std::size_t k = 0; k < state.motion().size(); ++k)
      if (state.motion()[k] == Motion::moves)
        state.a.local_element(k) -= c * state.v.local_element(k);
  }

  template <int dim>
  void
  ExplicitDynamics<dim>::report_initial_residual(const CoupledState<dim> &state) const
  {
    // The largest force that is not balanced at t = 0, over the free FE dofs and the free
    // particle components, against the internal-force scale max_i sum_j |K_ij U_j| of the FE
    // rows (the nodal force without the cancellation between neighbours). For a deformation the
    // coupled model reproduces exactly (rigid motion; uniform strain away from free surfaces)
    // the residual is the ghost force of the coupling.
    using Motion               = typename CoupledState<dim>::Motion;
    const unsigned int nc      = state.n_components();
    const auto        &mask    = state.fe().prescribed_mask();
    double             largest = 0.;
    state.U.update_ghost_values();
    for (unsigned int k = 0; k < state.U.locally_owned_size(); ++k)
      if (!mask[k])
        largest = std::max(largest, std::abs(state.residual.local_element(k)));
    const auto &volume = state.pd().particles().volumes();
    for (std::size_t k = 0; k < state.motion().size(); ++k)
      if (state.motion()[k] == Motion::moves)
        largest = std::max(largest,
                           std::abs(state.internal_force.local_element(k) +
                                    state.external_force.local_element(k)) *
                             volume[k / nc]);
    state.log_residual("Force residual at t = 0", largest, state.fe_force_scale());
  }

  template <int dim>
  void
  ExplicitDynamics<dim>::start_state(CoupledState<dim> &state)
  {
    // The initial state, the slaved particles' from the FE field; then the other physics start,
    // before the first forces: a thermal strain reads the initial temperature, and a two-way
    // coupling takes the initial deformation's measure.
    state.apply_initial_conditions();
    state.U.update_ghost_values();
    slave_particles(state);
    state.advance_other_physics(0, 0., 0., true);
    compute_acceleration(state, 0., true);
    set_first_order_rates(state);
    if (state.is_coupled())
      report_initial_residual(state);
    state.start_work();
    state.fe_support.equ(-1., state.residual);
  }

  template <int dim>
  void
  ExplicitDynamics<dim>::advance(CoupledState<dim> &state,
                                 const double       time,
                                 const double       dt,
                                 const bool         with_energy)
  {
    using Motion     = typename CoupledState<dim>::Motion;
    auto &fe         = state.fe();
    auto &conditions = state.pd().boundary_conditions();
    auto &U = state.U, &V = state.V, &A = state.A;
    auto &u = state.u, &v = state.v, &a = state.a;
    // The heat in over the step from the heat flows at its start (forward Euler).
    state.accumulate_heat(dt);

    // Half step of the velocities (first-order unknowns: their rate at the start of the
    // step), prescribed velocities over the step, positions.
    V.add(0.5 * dt, A);
    v.add(0.5 * dt, a);
    set_first_order_rates(state);
    fe.prescribe(time + 0.5 * dt, U, V);
    conditions.prescribe_step_velocity(time, dt, v);
    // U and u hold ghost values from the last step; deal.II's add() on a vector with ghost
    // values exchanges them again at once, an exchange per step the update after the
    // prescribed values repeats (measured: the FE ghost update twice per step, 15 % of the
    // bytes of the coupled 3D plate on 4 ranks, doc/benchmarks/performance/README.md).
    U.zero_out_ghost_values();
    u.zero_out_ghost_values();
    U.add(dt, V);
    if (!state.any_particle_slaved())
      u.add(dt, v);
    else
      for (std::size_t k = 0; k < state.motion().size(); ++k)
        if (state.motion()[k] != Motion::slaved)
          u.local_element(k) += dt * v.local_element(k);
    fe.prescribe(time + dt, U, V);
    conditions.prescribe_displacement(time + dt, u);
    U.update_ghost_values();
    slave_particles(state);
    // The adiabatic split of a two-way thermoelastic coupling: the other physics advance at the
    // step's end configuration, and the forces there read their temperature of the step's end.
    if (state.other_physics_within_step())
      state.advance_other_physics(static_cast<unsigned int>(std::lround(time / dt)) + 1,
                                  time,
                                  dt,
                                  with_energy);

    // The closing half step of the particles' velocities in the pass of the acceleration if
    // no damping changes the acceleration first.
    const bool damped = state.settings().damping > 0.;
    compute_acceleration(state, time + dt, with_energy, damped ? 0. : 0.5 * dt);
    if (damped)
      {
        add_damping(state);
        v.add(0.5 * dt, a);
      }
    V.add(0.5 * dt, A);
    set_first_order_rates(state);
    fe.prescribe(time + dt, U, V);

    state.accumulate_work();
  }

  template <int dim>
  void
  ExplicitDynamics<dim>::run(CoupledState<dim>   &state,
                             Postprocessors<dim> &postprocessors,
                             Checkpoint<dim>     &checkpoint)
  {
    const auto        &settings = state.settings();
    const unsigned int n_steps =
      ParameterUtilities::equal_time_steps(settings.end_time, state.time_step);
    const double dt = state.time_step;
    if (state.is_root())
      state.log() << "Time step: " << dt << " s, steps: " << n_steps << std::endl;
    std::ostringstream run_description;
    run_description << "explicit dynamics, " << n_steps << " steps of " << std::setprecision(17)
                    << dt << " s";

    RunControl<dim>   run(state, postprocessors, checkpoint, false);
    const RunPosition start =
      run.start(run_description.str(), n_steps, [&]() { start_state(state); });
    // A restart takes the temperature of the time reached (the checkpoint held the one the work
    // of the temperature in the next step starts from).
    if (checkpoint.restarting())
      state.update_temperature(start.time);

    ProgressReporter progress(state.comm(),
                              state.log(),
                              n_steps,
                              settings.end_time,
                              settings.show_progress && state.is_root());
    const auto       start_time = std::chrono::steady_clock::now();
    for (unsigned int step = start.step + 1; step <= n_steps; ++step)
      {
        StepData   data = run.plan(step, step * dt, step == n_steps);
        const bool check_regions =
          state.has_adaptive_region() && !data.final_row && step % state.adaptation_interval() == 0;
        advance(state,
                (step - 1) * dt,
                dt,
                data.write_statistics || data.write_fields || check_regions);
        if (!state.other_physics_within_step())
          state.advance_other_physics(step,
                                      (step - 1) * dt,
                                      dt,
                                      data.write_statistics || data.write_fields);

        if (data.write_statistics)
          state.fe_support.equ(-1., state.residual);
        run.write(data);
        adaptive_cost.particle_steps += state.pd().particles().n_global();
        if (check_regions)
          adapt_regions(state, step, data.time);
        progress.update(step, data.time);
        if (run.checkpoint(data))
          return;
      }
    const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_time).count();
    const std::uint64_t n_bonds = state.pd().particles().n_global_bonds();
    if (!settings.show_progress)
      return;
    if (state.is_root())
      {
        state.log() << "Wall time of the time loop: " << seconds << " s" << std::endl;
        if (n_bonds > 0)
          state.log() << "bond updates per second: "
                      << double(n_bonds) * (n_steps - start.step) / seconds << std::endl;
      }
    if (state.has_adaptive_region())
      {
        const std::string line = adaptive_cost_summary(state, seconds);
        // The stages of the set-up and of every conversion together: less the set-up's line,
        // where the conversions' time goes.
        const std::string stages =
          SetupTimes::summary(state.comm(), "Set-up stages with the conversions");
        if (state.is_root())
          state.log() << line << "\n" << stages << std::endl;
      }
    // What a step exchanges between the ranks (read from the patterns, after the loop): the
    // particles' ghost update in slave_particles(), the FE ghost update in advance(), the
    // stiffness product and the method's transfer.
    if (Utilities::MPI::n_mpi_processes(state.comm()) > 1)
      {
        const unsigned int          nc = state.n_components();
        std::vector<ExchangeVolume> exchanges;
        exchanges.push_back(
          ghost_exchange("particle ghosts (u)", *state.pd().particles().partitioner(nc)));
        auto &fe = state.fe();
        if (fe.n_dofs() > 0)
          {
            exchanges.push_back(ghost_exchange("FE ghost dofs (U)", *state.U.get_partitioner()));
            exchanges.push_back(matrix_exchange("K U", fe.stiffness_matrix(), false));
            for (const auto &e : state.method().transfer_exchanges())
              exchanges.push_back(e);
          }
        const std::string line =
          communication_summary(state.comm(), exchanges, nc, state.pd().particles().n_owned());
        if (state.is_root())
          state.log() << line << std::endl;
      }
  }

  template class ExplicitDynamics<2>;
  template class ExplicitDynamics<3>;
} // namespace perideal
