// ---------------------------------------------------------------------
// PeriDeal: implicit theta-scheme time steps of a first-order field (heat conduction).
// ---------------------------------------------------------------------
#include <perideal/base/parameter_utilities.h>
#include <perideal/coupling/solvers/equilibrium_state.h>
#include <perideal/coupling/solvers/run_control.h>
#include <perideal/coupling/solvers/theta_scheme.h>

#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

namespace perideal
{
  using namespace dealii;

  template <int dim>
  void
  ThetaScheme<dim>::check(const CoupledState<dim> &state) const
  {
    AssertThrow(state.layout().n_components(ComponentKind::temperature) == state.n_components(),
                ExcMessage("<Solver/Type> = implicit advances a first-order field (a "
                           "temperature: <Finite elements/Physics> = heat, or a PD conduction "
                           "model), but the problem's field is " +
                           state.layout().description() +
                           ", of second order in time; accepted <Solver/Type> for it: explicit, "
                           "static, adaptive dynamic relaxation."));
    check_convection_on_free_particles(state, "implicit");
  }

  template <int dim>
  void
  ThetaScheme<dim>::setup(CoupledState<dim> &state)
  {
    using Motion = typename CoupledState<dim>::Motion;
    this->check(state);
    const unsigned int nc       = state.n_components();
    const auto        &settings = state.settings();
    auto              &ps       = state.pd().particles();

    // The solve of the method with the prescribed components of free particles.
    ParticleVector prescribed;
    ps.reinit_vector(prescribed, nc);
    for (std::size_t k = 0; k < state.motion().size(); ++k)
      if (state.motion()[k] == Motion::prescribed)
        prescribed.local_element(k) = 1.;
    EquilibriumSettings<dim> equilibrium;
    equilibrium.type                  = SolverType::static_linear;
    equilibrium.linear.linear_solver  = settings.linear_solver;
    equilibrium.linear.tolerance      = settings.tolerance;
    equilibrium.linear.max_iterations = settings.max_iterations;
    state.method().initialize_equilibrium(prescribed, equilibrium, condition_names(state));

    // C, the lumped capacity: the method's lumped masses times the components' inertia ratio
    // (the specific heat of a temperature) on the particles; the FE lumped mass is rho c
    // already (FEPhysics::mass_factor()).
    state.fe().initialize_vector(state.mass);
    state.method().lumped_masses(state.mass, state.particle_mass);
    free_factor.assign(state.motion().size(), 0.);
    for (std::size_t k = 0; k < state.motion().size(); ++k)
      free_factor[k] = state.motion()[k] != Motion::slaved ? 1. : 0.;
    double dt = settings.time_step;
    ParameterUtilities::equal_time_steps(settings.end_time, dt);
    set_step(state, dt);
    state.fe().initialize_vector(fe_rhs);
    ps.reinit_vector(pd_rhs, nc);
    if (state.is_root())
      state.log() << "Implicit theta scheme: theta = " << settings.theta << ", "
                  << state.method().n_unknowns() << " unknowns per step" << std::endl;
  }

  template <int dim>
  void
  ThetaScheme<dim>::set_step(CoupledState<dim> &state, const double dt)
  {
    const unsigned int nc     = state.n_components();
    auto              &ps     = state.pd().particles();
    const double       factor = 1. / (state.settings().theta * dt);
    state.time_step           = dt;
    // D = C / (theta dt). A particle convection h (T_inf - T) / d adds its conductance h V / d
    // to the diagonal (its ambient part h T_inf / d is a load); not to D, which multiplies T_n.
    state.fe().initialize_vector(fe_diagonal);
    fe_diagonal.equ(factor, state.mass);
    ParticleVector diagonal, conductance;
    ps.reinit_vector(diagonal, nc);
    ps.reinit_vector(conductance, nc);
    ps.reinit_vector(particle_diagonal, nc);
    state.pd().boundary_conditions().add_convection_conductance(conductance);
    const auto &volume = ps.volumes();
    for (std::size_t k = 0; k < free_factor.size(); ++k)
      if (free_factor[k] != 0.)
        {
          particle_diagonal.local_element(k) =
            factor * state.particle_mass[k / nc] * state.inertia_ratio()[k % nc] / volume[k / nc];
          diagonal.local_element(k) =
            particle_diagonal.local_element(k) * volume[k / nc] + conductance.local_element(k);
        }
    state.method().set_equilibrium_diagonal(fe_diagonal, diagonal);
  }

  template <int dim>
  void
  ThetaScheme<dim>::forces_at(CoupledState<dim> &state, const double time)
  {
    state.f_ext          = 0.;
    state.external_force = 0.;
    state.fe().assemble_load(time, state.f_ext);
    state.pd().boundary_conditions().add_loads(time, state.external_force);
    state.pd().boundary_conditions().add_convection(time, &state.u, state.external_force);
    equilibrium_state(state);
  }

  template <int dim>
  void
  ThetaScheme<dim>::first_forces(CoupledState<dim> &state, const double time)
  {
    FEVector       U_start(state.U);
    ParticleVector u_start(state.u);
    state.fe().assemble_load(time, fe_rhs);
    pd_rhs = 0.;
    state.method().solve_equilibrium(fe_rhs, pd_rhs, U_start, u_start);
    forces_at(state, time);
  }

  template <int dim>
  void
  ThetaScheme<dim>::start_state(CoupledState<dim> &state)
  {
    state.apply_initial_conditions();
    state.start_work();
    first_forces(state, 0.);
  }

  template <int dim>
  void
  ThetaScheme<dim>::resume_state(CoupledState<dim> &state, const double time)
  {
    first_forces(state, time);
  }

  template <int dim>
  void
  ThetaScheme<dim>::renew_regions(CoupledState<dim> &state, const double time)
  {
    setup(state);
    first_forces(state, time);
    state.carry_work();
  }

  template <int dim>
  void
  ThetaScheme<dim>::step_to(CoupledState<dim> &state, const double time)
  {
    auto             &fe         = state.fe();
    auto             &conditions = state.pd().boundary_conditions();
    auto             &U = state.U, &u = state.u;
    const double      theta      = state.settings().theta;
    const double      old_weight = (1. - theta) / theta;
    const std::size_t n_particle = free_factor.size();
    // The heat in over the step, theta-weighted as the step: (1 - theta) dt of the heat flows at
    // t_n here, theta dt of those at t_{n+1} after the solve.
    state.accumulate_heat((1. - theta) * state.time_step);
    // D T_n + (1 - theta) / theta (Q_n - K T_n), then the loads at t_{n+1} (of a convection its
    // ambient part: the conductance is in the matrix).
    for (unsigned int k = 0; k < U.locally_owned_size(); ++k)
      fe_rhs.local_element(k) = fe_diagonal.local_element(k) * U.local_element(k) -
                                old_weight * state.residual.local_element(k);
    for (std::size_t k = 0; k < n_particle; ++k)
      pd_rhs.local_element(k) =
        particle_diagonal.local_element(k) * u.local_element(k) +
        old_weight * free_factor[k] *
          (state.internal_force.local_element(k) + state.external_force.local_element(k));
    state.f_ext          = 0.;
    state.external_force = 0.;
    fe.assemble_load(time, state.f_ext);
    conditions.add_loads(time, state.external_force);
    conditions.add_convection(time, nullptr, state.external_force);
    fe_rhs += state.f_ext;
    pd_rhs += state.external_force;
    fe.prescribe(time, U, state.V);
    conditions.prescribe_displacement(time, u);
    iterations = state.method().solve_equilibrium(fe_rhs, pd_rhs, U, u);
    forces_at(state, time);
    state.accumulate_heat(theta * state.time_step);
  }

  template <int dim>
  void
  ThetaScheme<dim>::advance(CoupledState<dim> &state,
                            const double       time,
                            const double       dt,
                            const bool)
  {
    // Another step (a cut load step of the first physics): the diagonal D of its length.
    if (dt != state.time_step)
      set_step(state, dt);
    step_to(state, time + dt);
  }

  template <int dim>
  void
  ThetaScheme<dim>::run(CoupledState<dim>   &state,
                        Postprocessors<dim> &postprocessors,
                        Checkpoint<dim>     &checkpoint)
  {
    const auto        &settings = state.settings();
    double             dt       = settings.time_step;
    const unsigned int n_steps  = ParameterUtilities::equal_time_steps(settings.end_time, dt);
    if (state.is_root())
      state.log() << "Time step: " << dt << " s, steps: " << n_steps << std::endl;
    std::ostringstream run_description;
    run_description << "implicit, theta " << settings.theta << ", " << n_steps << " steps of "
                    << std::setprecision(17) << dt << " s";

    const bool        restarting = checkpoint.restarting();
    RunControl<dim>   run(state, postprocessors, checkpoint, false);
    const RunPosition start =
      run.start(run_description.str(), n_steps, [&]() { start_state(state); });
    if (restarting)
      resume_state(state, start.time);

    for (unsigned int step = start.step + 1; step <= n_steps; ++step)
      {
        const double time = step * dt;
        StepData     data = run.plan(step, time, step == n_steps);
        step_to(state, time);
        data.iterations = iterations;
        run.write(data);
        if (run.checkpoint(data))
          return;
      }
  }

  template class ThetaScheme<2>;
  template class ThetaScheme<3>;
} // namespace perideal
