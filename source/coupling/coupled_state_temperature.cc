// ---------------------------------------------------------------------
// PeriDeal: a state's temperature of a thermal strain and the work a changing temperature does
// on the body (doc/architecture/16_multiphysics.md, "The work of a changing temperature").
// ---------------------------------------------------------------------
#include <perideal/coupling/coupled_state.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace perideal
{
  using namespace dealii;

  template <int dim>
  void
  CoupledState<dim>::set_temperature(std::function<void(double)> update)
  {
    temperature_update = std::move(update);
    fe_thermal         = fe().n_dofs() > 0 && fe().has_thermal_strain();
    if (fe_thermal)
      {
        fe().initialize_vector(thermal_load);
        fe().initialize_vector(fe_total_load);
      }
  }

  template <int dim>
  bool
  CoupledState<dim>::has_temperature() const
  {
    return static_cast<bool>(temperature_update);
  }

  template <int dim>
  void
  CoupledState<dim>::update_temperature(const double time)
  {
    if (!temperature_update)
      return;
    temperature_update(time);
    if (fe_thermal)
      thermal_energy = fe().assemble_thermal_load(time, thermal_load);
  }

  template <int dim>
  const FEVector &
  CoupledState<dim>::fe_equation_load() const
  {
    if (!fe_thermal)
      return f_ext;
    fe_total_load = f_ext;
    fe_total_load += thermal_load;
    return fe_total_load;
  }

  template <int dim>
  void
  CoupledState<dim>::hold_temperature()
  {
    if (!has_temperature())
      return;
    if (const ParticleVector *change = pd().material().temperature_change(); change != nullptr)
      {
        if (held_temperature_change.get_partitioner() != change->get_partitioner())
          held_temperature_change.reinit(*change);
        // Every local value, ghosts included: a prescribed temperature writes the ghosts
        // without an exchange, which operator= would not copy.
        const auto &layout = *change->get_partitioner();
        std::copy(change->begin(),
                  change->begin() + layout.locally_owned_size() + layout.n_ghost_indices(),
                  held_temperature_change.begin());
      }
    if (fe_thermal)
      {
        held_thermal_load   = thermal_load;
        held_thermal_energy = thermal_energy;
      }
  }

  template <int dim>
  bool
  CoupledState<dim>::holds_layout() const
  {
    // The same layout, not only the same object: a restart reads the held vectors into a layout
    // of their own.
    const auto same = [](const auto &held, const auto &present) {
      return held.get_partitioner() == present.get_partitioner() ||
             (held.size() == present.size() &&
              held.partitioners_are_compatible(*present.get_partitioner()));
    };
    const ParticleVector *change = pd().material().temperature_change();
    const bool            holds  = (change == nullptr || same(held_temperature_change, *change)) &&
                       (!fe_thermal || same(held_thermal_load, thermal_load));
    // On every rank alike (a conversion may leave one rank's layout as it was).
    return !Utilities::MPI::logical_or(!holds, comm());
  }

  template <int dim>
  bool
  CoupledState<dim>::temperature_changed() const
  {
    if (!has_temperature() || !holds_layout())
      return false;
    bool changed = fe_thermal && (thermal_energy != held_thermal_energy);
    if (const ParticleVector *change = pd().material().temperature_change(); change != nullptr)
      for (unsigned int i = 0; i < pd().particles().n_owned() && !changed; ++i)
        changed = change->local_element(i) != held_temperature_change.local_element(i);
    if (fe_thermal)
      for (unsigned int k = 0; k < thermal_load.locally_owned_size() && !changed; ++k)
        changed = thermal_load.local_element(k) != held_thermal_load.local_element(k);
    return Utilities::MPI::logical_or(changed, comm());
  }

  template <int dim>
  std::array<double, 2>
  CoupledState<dim>::fe_temperature_changes() const
  {
    // The FE energy 1/2 U.K.U - U.f_th(T) + e_th(T) changes by -U.(f_th(T_1) - f_th(T_0)) +
    // e_th(T_1) - e_th(T_0), at U_0 and at U_1.
    if (!fe_thermal)
      return {{0., 0.}};
    FEVector load_change(thermal_load);
    load_change -= held_thermal_load;
    const double energy_change = thermal_energy - held_thermal_energy;
    return {{energy_change - previous_U * load_change, energy_change - U * load_change}};
  }

  template <int dim>
  void
  CoupledState<dim>::add_temperature_work(const std::array<double, 2> &changes)
  {
    if (is_root())
      {
        local_temperature_work += 0.5 * (changes[0] + changes[1]);
        local_temperature_scale += 0.5 * (std::abs(changes[0]) + std::abs(changes[1]));
      }
    hold_temperature();
  }

  template <int dim>
  void
  CoupledState<dim>::accumulate_temperature_work()
  {
    if (!has_temperature())
      return;
    // A conversion of the adaptive region since the hold laid the fields out anew: the
    // equilibrium after it is at the temperature of the step before.
    if (!holds_layout())
      {
        hold_temperature();
        return;
      }
    // E(u, T_1) - E(u, T_0) at the step's start (u_0, U_0) and end (u_1, U_1), averaged; the
    // particles' part in the coupling method's model of equilibrium, the model reading the
    // held temperature change for the second pair.
    std::array<double, 2> changes = fe_temperature_changes();
    if (const ParticleVector *present = pd().material().temperature_change(); present != nullptr)
      {
        previous_u.update_ghost_values();
        const auto now = method().equilibrium_particle_energies(previous_u, u);
        pd().material().set_temperature_change(&held_temperature_change);
        const auto before = method().equilibrium_particle_energies(previous_u, u);
        pd().material().set_temperature_change(present);
        for (const unsigned int k : {0u, 1u})
          changes[k] += now[k] - before[k];
      }
    add_temperature_work(changes);
  }

  template <int dim>
  void
  CoupledState<dim>::accumulate_temperature_jump()
  {
    // The symmetric difference of accumulate_temperature_work() over the step from the state of
    // the work of the loads (u_0, U_0) to the present one (u_1, U_1), which is what the
    // velocity-Verlet step's kinetic energy closes with: E(u_0, T_1) - E(u_0, T_0) follows from
    // the change at u_1 and the change of the forces, E(u_1, T_1) - E(u_1, T_0) - (u_1 - u_0) .
    // (grad E(u_1, T_1) - grad E(u_1, T_0)), exactly for an energy quadratic in u and T. The
    // particles' E(u_1, T_1) from energy_density and their force from internal_force (the
    // step's evaluation at T_1), E and the force at T_0 from one more evaluation of the model.
    std::array<double, 2> changes = fe_temperature_changes();
    if (const ParticleVector *present = pd().material().temperature_change(); present != nullptr)
      {
        auto              &ps     = pd().particles();
        const auto        &volume = ps.volumes();
        const unsigned int nc     = n_components();
        if (held_force.size() != internal_force.size())
          held_force.reinit(internal_force);
        pd().material().set_temperature_change(&held_temperature_change);
        const double before =
          model_strain_energy(pd().material(), ps, u, held_force, held_energy_density);
        pd().material().set_temperature_change(present);
        // grad E = -f V per particle component (f the force density).
        double now = 0., force_change = 0.;
        for (unsigned int i = 0; i < ps.n_owned(); ++i)
          {
            now += energy_density[i] * volume[i];
            for (unsigned int k = i * nc; k < (i + 1) * nc; ++k)
              force_change += volume[i] * (u.local_element(k) - previous_u.local_element(k)) *
                              (internal_force.local_element(k) - held_force.local_element(k));
          }
        const double at_end = Utilities::MPI::sum(now, comm()) - before;
        changes[0] += at_end + Utilities::MPI::sum(force_change, comm());
        changes[1] += at_end;
      }
    add_temperature_work(changes);
  }

  template <int dim>
  double
  CoupledState<dim>::temperature_work() const
  {
    return Utilities::MPI::sum(local_temperature_work, comm());
  }

  template <int dim>
  double
  CoupledState<dim>::temperature_energy_scale() const
  {
    return Utilities::MPI::sum(local_temperature_scale, comm());
  }

#define PERIDEAL_INSTANTIATE(dim)                                                           \
  template void            CoupledState<dim>::set_temperature(std::function<void(double)>); \
  template bool            CoupledState<dim>::has_temperature() const;                      \
  template void            CoupledState<dim>::update_temperature(const double);             \
  template const FEVector &CoupledState<dim>::fe_equation_load() const;                     \
  template void            CoupledState<dim>::hold_temperature();                           \
  template bool            CoupledState<dim>::temperature_changed() const;                  \
  template void            CoupledState<dim>::accumulate_temperature_work();                \
  template void            CoupledState<dim>::accumulate_temperature_jump();                \
  template double          CoupledState<dim>::temperature_work() const;                     \
  template double          CoupledState<dim>::temperature_energy_scale() const;
  PERIDEAL_INSTANTIATE(2)
  PERIDEAL_INSTANTIATE(3)
#undef PERIDEAL_INSTANTIATE
} // namespace perideal
