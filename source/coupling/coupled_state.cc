// ---------------------------------------------------------------------
// PeriDeal: the state of a problem that the solvers advance and the postprocessors read.
// ---------------------------------------------------------------------
#include <perideal/base/parameter_utilities.h>
#include <perideal/coupling/coupled_state.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace perideal
{
  using namespace dealii;

  template <int dim>
  CoupledState<dim>::CoupledState(const MPI_Comm              comm,
                                  std::ostream               &log,
                                  const ProblemSettings<dim> &settings,
                                  const FieldLayout          &layout,
                                  ParticleRegion<dim>        &pd,
                                  FERegion<dim>              &fe,
                                  CouplingMethod<dim>        &method)
    : mpi_communicator(comm)
    , log_stream(log)
    , root(Utilities::MPI::this_mpi_process(comm) == 0)
    , problem_settings(settings)
    , particle_region(pd)
    , fe_region(fe)
    , coupling_method(method)
    , field_layout(layout)
  {}

  template <int dim>
  void
  CoupledState<dim>::setup()
  {
    const unsigned int nc         = n_components();
    const auto        &ps         = pd().particles();
    const unsigned int n_owned    = ps.n_owned();
    const auto        &conditions = pd().boundary_conditions();
    const auto        &slaved     = method().slaved_particles();
    AssertDimension(slaved.size(), n_owned);

    // The method decides which particles are slaved to the FE field; the free ones carry their own
    // mass, and PD boundary conditions may act only on them.
    component_motion.assign(std::size_t(n_owned) * nc, Motion::slaved);
    std::uint64_t n_constrained_slaved = 0;
    for (unsigned int i = 0; i < n_owned; ++i)
      for (unsigned int c = 0; c < nc; ++c)
        {
          const bool prescribed = conditions.is_prescribed(i, c);
          if (slaved[i])
            n_constrained_slaved += prescribed;
          else
            component_motion[i * nc + c] = prescribed ? Motion::prescribed : Motion::moves;
        }
    slaved_anywhere =
      Utilities::MPI::logical_or(std::find(slaved.begin(), slaved.end(), true) != slaved.end(),
                                 comm());
    n_constrained_slaved = Utilities::MPI::sum(n_constrained_slaved, comm());
    AssertThrow(n_constrained_slaved == 0,
                ExcMessage(
                  "A displacement or velocity condition of <Boundary conditions> acts on " +
                  std::to_string(n_constrained_slaved) +
                  " particle components slaved to the FE field (they lie in cells "
                  "with FE unknowns); prescribe it there with <Finite elements/Boundary "
                  "conditions>, or move its region into the PD-only zone (beta = 1)."));

    inertia_ratios = pd().material().inertia_ratios(pd().density());

    const auto &volume = ps.volumes();
    internal_work_factor.assign(component_motion.size(), 0.);
    applied_work_factor.assign(component_motion.size(), 0.);
    for (std::size_t k = 0; k < component_motion.size(); ++k)
      if (component_motion[k] == Motion::prescribed)
        internal_work_factor[k] = -volume[k / nc];
      else
        applied_work_factor[k] = volume[k / nc];
    // A temperature's heat flows in time are no work: its factors move to the heat factors. A
    // steady (quasi-static) temperature keeps them: its balance is that of the work,
    // int Q dT = 1/2 T.K T.
    internal_heat_factor.clear();
    applied_heat_factor.clear();
    const bool in_time = settings().solver_type == SolverType::explicit_dynamics ||
                         settings().solver_type == SolverType::implicit;
    if (layout().has_temperature() && in_time)
      {
        internal_heat_factor.assign(component_motion.size(), 0.);
        applied_heat_factor.assign(component_motion.size(), 0.);
        for (std::size_t k = 0; k < component_motion.size(); ++k)
          if (layout().kind(k % nc) == ComponentKind::temperature)
            {
              std::swap(internal_heat_factor[k], internal_work_factor[k]);
              std::swap(applied_heat_factor[k], applied_work_factor[k]);
            }
      }
    // The components whose load can do work: with internal work factor, and with applied work
    // factor if a load acts (without loads external_force stays +0, so the others' load is
    // 0 f + V 0 = +0 at every step and their trapezoids add exactly nothing).
    const bool loads = conditions.has_loads();
    work_components.clear();
    for (std::size_t k = 0; k < component_motion.size(); ++k)
      if (internal_work_factor[k] != 0. || (loads && applied_work_factor[k] != 0.))
        work_components.push_back(k);

    for (ParticleVector *vec :
         {&u, &v, &a, &internal_force, &external_force, &previous_u, &previous_load})
      pd().particles().reinit_vector(*vec, nc);
    for (FEVector *vec :
         {&U, &V, &A, &f_ext, &residual, &fe_load, &fe_support, &previous_fe_load, &previous_U})
      fe().initialize_vector(*vec);
    energy_density.assign(n_owned, 0.);

    // The FE field of a temperature: the column sums of its stiffness, the conductance of its
    // convection (Robin) faces per dof (the conduction part sums to 0 over a column).
    fe_convection.reinit(0);
    if (layout().has_temperature() && fe().n_dofs() > 0)
      {
        FEVector one;
        fe().initialize_vector(one);
        fe().initialize_vector(fe_convection);
        one = 1.;
        one.update_ghost_values();
        fe().stiffness_matrix().Tvmult(fe_convection, one);
      }
  }

  template <int dim>
  void
  CoupledState<dim>::set_adaptive_region(std::function<bool(unsigned int, double)> adapt,
                                         const unsigned int                        interval)
  {
    Assert(interval > 0, ExcMessage("An adaptive region needs a check every n steps."));
    adaptation     = std::move(adapt);
    check_interval = interval;
  }

  template <int dim>
  bool
  CoupledState<dim>::has_adaptive_region() const
  {
    return static_cast<bool>(adaptation);
  }

  template <int dim>
  const std::function<bool(unsigned int, double)> &
  CoupledState<dim>::adaptive_region() const
  {
    return adaptation;
  }

  template <int dim>
  unsigned int
  CoupledState<dim>::adaptation_interval() const
  {
    return check_interval;
  }

  template <int dim>
  bool
  CoupledState<dim>::adapt_regions(const unsigned int step, const double time)
  {
    Assert(adaptation, ExcMessage("No adaptive region was set."));
    return adaptation(step, time);
  }

  template <int dim>
  void
  CoupledState<dim>::set_other_physics(
    std::function<void(unsigned int, double, double, bool)> advance,
    const bool                                              within_step)
  {
    advance_physics     = std::move(advance);
    physics_within_step = within_step;
  }

  template <int dim>
  bool
  CoupledState<dim>::other_physics_within_step() const
  {
    return physics_within_step;
  }

  template <int dim>
  const std::function<void(unsigned int, double, double, bool)> &
  CoupledState<dim>::other_physics() const
  {
    return advance_physics;
  }

  template <int dim>
  void
  CoupledState<dim>::set_broken_bond_record(std::vector<unsigned int> &broken_bonds)
  {
    broken_bond_record = &broken_bonds;
  }

  template <int dim>
  void
  CoupledState<dim>::advance_other_physics(const unsigned int step,
                                           const double       time,
                                           const double       dt,
                                           const bool         with_energy)
  {
    if (advance_physics)
      advance_physics(step, time, dt, with_energy);
  }

  template <int dim>
  template <typename State>
  typename CoupledState<dim>::template Parts<std::is_const_v<State>>
  CoupledState<dim>::parts_of(State &state)
  {
    return {{&state.u,
             &state.v,
             &state.a,
             &state.internal_force,
             &state.external_force,
             &state.previous_u,
             &state.previous_load},
            &state.energy_density,
            {&state.U,
             &state.V,
             &state.A,
             &state.f_ext,
             &state.residual,
             &state.fe_load,
             &state.fe_support,
             &state.previous_fe_load,
             &state.previous_U},
            {&state.local_work,
             &state.local_dissipated,
             &state.local_heat_in,
             &state.local_temperature_work,
             &state.local_temperature_scale},
            {&state.stored_heat_at_start}};
  }

  template <int dim>
  typename CoupledState<dim>::StoredParts
  CoupledState<dim>::stored_parts()
  {
    return parts_of(*this);
  }

  template <int dim>
  typename CoupledState<dim>::ConstStoredParts
  CoupledState<dim>::stored_parts() const
  {
    return parts_of(*this);
  }

  template <int dim>
  bool
  CoupledState<dim>::is_coupled() const
  {
    return pd().has_body() && fe().has_mesh();
  }

  template <int dim>
  bool
  CoupledState<dim>::has_particles() const
  {
    return pd().particles().n_global() > 0;
  }

  template <int dim>
  void
  CoupledState<dim>::apply_initial_conditions()
  {
    const unsigned int nc = n_components();
    const auto         displacement =
      ParameterUtilities::make_function<dim>(settings().initial_displacement,
                                             nc,
                                             "Initial conditions/Displacement");
    const auto  velocity = ParameterUtilities::make_function<dim>(settings().initial_velocity,
                                                                 nc,
                                                                 "Initial conditions/Velocity");
    const auto &ps       = pd().particles();
    const auto &x        = ps.positions();
    for (unsigned int i = 0; i < ps.n_owned(); ++i)
      for (unsigned int c = 0; c < nc; ++c)
        {
          u.local_element(i * nc + c) = displacement->value(x[i], c);
          v.local_element(i * nc + c) = velocity->value(x[i], c);
        }
    fe().interpolate(*displacement, U);
    fe().interpolate(*velocity, V);
    fe().prescribe(0., U, V);
    pd().boundary_conditions().prescribe_displacement(0., u);
  }

  template <int dim>
  void
  CoupledState<dim>::start_work()
  {
    local_work              = 0.;
    local_dissipated        = 0.;
    local_heat_in           = 0.;
    local_temperature_work  = 0.;
    local_temperature_scale = 0.;
    if (layout().has_temperature())
      stored_heat_at_start = stored_heat();
    pd().particles().bonds().newly_broken.clear();
    carry_work();
    hold_temperature();
  }

  template <int dim>
  void
  CoupledState<dim>::carry_work()
  {
    previous_U             = U;
    previous_fe_load       = fe_load;
    previous_u             = u;
    const double *internal = internal_force.begin(), *applied = external_force.begin();
    double       *load = previous_load.begin();
    for (std::size_t k = 0; k < motion().size(); ++k)
      load[k] = internal_work_factor[k] * internal[k] + applied_work_factor[k] * applied[k];
  }

  template <int dim>
  void
  CoupledState<dim>::accumulate_work()
  {
    // Trapezoidal rule in the loads over the step; one pass per region that also makes the
    // current state the previous one. (Local sums: one in the member could alias the arrays
    // and stay out of a register.)
    double work = local_work;
    {
      double       *load_before = previous_fe_load.begin(), *u_before = previous_U.begin();
      const double *load = fe_load.begin(), *u_now = U.begin();
      for (unsigned int k = 0; k < U.locally_owned_size(); ++k)
        {
          work += 0.5 * (load_before[k] + load[k]) * (u_now[k] - u_before[k]);
          load_before[k] = load[k];
          u_before[k]    = u_now[k];
        }
    }
    {
      // Only the components of work_components: the previous state of the others is not
      // kept, except the displacement if the temperature's work reads it.
      double       *load_before = previous_load.begin(), *u_before = previous_u.begin();
      const double *u_now = u.begin(), *internal = internal_force.begin();
      const double *applied = external_force.begin(), *c_internal = internal_work_factor.data(),
                   *c_applied = applied_work_factor.data();
      for (const std::size_t k : work_components)
        {
          const double load = c_internal[k] * internal[k] + c_applied[k] * applied[k];
          work += 0.5 * (load_before[k] + load) * (u_now[k] - u_before[k]);
          load_before[k] = load;
          u_before[k]    = u_now[k];
        }
      if (pd().material().temperature_change() != nullptr)
        std::copy(u_now, u_now + motion().size(), u_before);
    }
    local_work = work;
  }

  template <int dim>
  double
  CoupledState<dim>::external_work() const
  {
    return Utilities::MPI::sum(local_work, comm());
  }

  template <int dim>
  void
  CoupledState<dim>::accumulate_dissipated_energy()
  {
    if (broken_bond_record != nullptr)
      {
        const auto &broken = pd().particles().bonds().newly_broken;
        broken_bond_record->insert(broken_bond_record->end(), broken.begin(), broken.end());
      }
    local_dissipated += pd().material().released_energy(pd().particles(), u);
  }

  template <int dim>
  double
  CoupledState<dim>::dissipated_energy() const
  {
    return Utilities::MPI::sum(local_dissipated, comm());
  }

  template <int dim>
  void
  CoupledState<dim>::accumulate_heat(const double dt)
  {
    const double *internal = internal_force.begin(), *applied = external_force.begin();
    double        heat = 0.;
    for (std::size_t k = 0; k < internal_heat_factor.size(); ++k)
      heat += internal_heat_factor[k] * internal[k] + applied_heat_factor[k] * applied[k];
    // FE dofs: the loads (sources, fluxes, a convection's h T_inf) and the supports' heat on
    // prescribed dofs, less the h T that leaves through the convection faces.
    for (unsigned int k = 0; k < fe_convection.locally_owned_size(); ++k)
      heat += fe_load.local_element(k) - fe_convection.local_element(k) * U.local_element(k);
    local_heat_in += dt * heat;
  }

  template <int dim>
  void
  CoupledState<dim>::add_heat_in(const double heat)
  {
    local_heat_in += heat;
  }

  template <int dim>
  double
  CoupledState<dim>::heat_in() const
  {
    return Utilities::MPI::sum(local_heat_in, comm());
  }

  template <int dim>
  double
  CoupledState<dim>::stored_heat() const
  {
    const unsigned int nc   = n_components();
    double             heat = 0.;
    // Explicit runs only: quasi-static runs have no masses.
    for (std::size_t k = 0; k < (particle_mass.empty() ? 0 : motion().size()); ++k)
      if (motion()[k] == Motion::moves && layout().kind(k % nc) == ComponentKind::temperature)
        heat += particle_mass[k / nc] * inertia_ratio()[k % nc] * u.local_element(k);
    // The free FE dofs with the capacity the solver uses, the method's lumped mass (which holds
    // the slaved particles' capacity: each part of the body counted once).
    if (fe_convection.size() > 0 && mass.size() > 0)
      {
        const auto &mask = fe().prescribed_mask();
        for (unsigned int k = 0; k < U.locally_owned_size(); ++k)
          if (!mask[k])
            heat += mass.local_element(k) * U.local_element(k);
      }
    return Utilities::MPI::sum(heat, comm());
  }

  template <int dim>
  typename CoupledState<dim>::KineticEnergy
  CoupledState<dim>::kinetic_energy() const
  {
    const auto   &mask = fe().prescribed_mask();
    KineticEnergy energy;
    for (unsigned int k = 0; k < V.locally_owned_size(); ++k)
      {
        const double e = 0.5 * mass.local_element(k) * std::pow(V.local_element(k), 2);
        energy.total += e;
        if (mask[k])
          energy.prescribed += e;
      }
    const unsigned int nc = n_components();
    for (unsigned int i = 0; i < pd().particles().n_owned(); ++i)
      for (unsigned int c = 0; c < nc; ++c)
        {
          const double e =
            0.5 * particle_mass[i] * inertia_ratio()[c] * std::pow(v.local_element(i * nc + c), 2);
          if (motion()[i * nc + c] != Motion::slaved)
            energy.total += e;
          if (motion()[i * nc + c] == Motion::prescribed)
            energy.prescribed += e;
        }
    energy.total      = Utilities::MPI::sum(energy.total, comm());
    energy.prescribed = Utilities::MPI::sum(energy.prescribed, comm());
    return energy;
  }

  template <int dim>
  CoupledEnergy
  CoupledState<dim>::strain_energy() const
  {
    const auto &volume          = pd().particles().volumes();
    double      particle_energy = 0.;
    for (unsigned int i = 0; i < pd().particles().n_owned(); ++i)
      particle_energy += energy_density[i] * volume[i];
    return strain_energy(Utilities::MPI::sum(particle_energy, comm()));
  }

  template <int dim>
  CoupledEnergy
  CoupledState<dim>::strain_energy(const double particle_energy) const
  {
    CoupledEnergy energy = method().strain_energy(U, particle_energy);
    // The FE energy of the mechanical strain: 1/2 U.K.U - U.f_th + the thermal strain's.
    if (fe_thermal)
      energy.fe += thermal_energy - (U * thermal_load);
    return energy;
  }

  template <int dim>
  double
  CoupledState<dim>::max_particle_displacement() const
  {
    const unsigned int nc      = n_components();
    double             largest = 0.;
    for (unsigned int i = 0; i < pd().particles().n_owned(); ++i)
      {
        double u2 = 0.;
        for (unsigned int c = 0; c < nc; ++c)
          if (layout().kind(c) != ComponentKind::rotation)
            u2 += std::pow(u.local_element(i * nc + c), 2);
        largest = std::max(largest, std::sqrt(u2));
      }
    return Utilities::MPI::max(largest, comm());
  }

  template <int dim>
  double
  CoupledState<dim>::fe_force_scale() const
  {
    double scale = 0.;
    for (const double sum : fe().absolute_row_sums(&U))
      scale = std::max(scale, sum);
    return Utilities::MPI::max(scale, comm());
  }

  template <int dim>
  double
  CoupledState<dim>::solution_accuracy() const
  {
    return std::max(settings().solution_accuracy(), method().solution_accuracy());
  }

  template <int dim>
  void
  CoupledState<dim>::log_residual(const std::string &what,
                                  const double       local_largest,
                                  const double       local_scale) const
  {
    const double largest  = Utilities::MPI::max(local_largest, comm());
    const double scale    = Utilities::MPI::max(local_scale, comm());
    const double relative = scale > 0. ? largest / scale : 0.;
    // A residual below 1e-12 of the force scale is round-off: printed as 0 N (the ratio shows
    // it), so that it reads the same on every rank count and build.
    // Without FE unknowns (an empty FE region) there is no scale: the force itself.
    if (is_root() && fe().n_dofs() == 0)
      log() << what << ": " << largest
            << " N (largest unbalanced nodal force at free particles; no FE region)" << std::endl;
    else if (is_root())
      log() << what << ": " << (relative < 1e-12 ? 0. : largest)
            << " N (largest unbalanced nodal force at free dofs and particles), relative to the FE "
               "internal-force scale: "
            << relative << std::endl;
  }

  template class CoupledState<2>;
  template class CoupledState<3>;
} // namespace perideal
