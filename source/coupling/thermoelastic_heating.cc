// ---------------------------------------------------------------------
// PeriDeal: the thermoelastic heating of a two-way coupling.
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>

#include <perideal/coupling/thermoelastic_heating.h>

namespace perideal
{
  using namespace dealii;

  template <int dim>
  void
  ThermoelasticHeating<dim>::connect(ParticleRegion<dim>          &mechanics_pd,
                                     const FERegion<dim>          &mechanics_fe,
                                     const ParticleVector         &mechanics_u,
                                     const FEVector               &mechanics_U,
                                     const TemperatureSource<dim> &source,
                                     CoupledState<dim>            &heat)
  {
    pd                        = &mechanics_pd;
    fe                        = &mechanics_fe;
    u                         = &mechanics_u;
    U                         = &mechanics_U;
    temperature               = &source;
    heat_state                = &heat;
    local_heat                = 0.;
    const FieldLayout &layout = heat.layout();
    for (unsigned int c = layout.n_components(); c-- > 0;)
      if (layout.kind(c) == ComponentKind::temperature)
        component = c;
    if (heat.fe().n_dofs() > 0)
      {
        heat.fe().initialize_vector(previous_fe);
        heat.fe().initialize_vector(present_fe);
        heat.fe().initialize_vector(fe_heating);
        heat.pd().particles().reinit_vector(slaved_heating, layout.n_components());
      }
    if (fe->n_dofs() > 0)
      fe->initialize_vector(displacement);
    if (pd->has_body())
      pd->particles().reinit_vector(particle_displacement, pd->field_layout().n_components());
  }

  template <int dim>
  bool
  ThermoelasticHeating<dim>::active() const
  {
    return heat_state != nullptr;
  }

  template <int dim>
  void
  ThermoelasticHeating<dim>::measure(std::vector<double> &particle_measure, FEVector &fe_measure)
  {
    if (pd->has_body())
      {
        particle_displacement.copy_locally_owned_data_from(*u);
        particle_displacement.update_ghost_values();
        pd->material().thermoelastic_measure(pd->particles(),
                                             particle_displacement,
                                             particle_measure);
      }
    if (fe_measure.size() == 0)
      return;
    fe_measure = 0.;
    if (fe->has_thermal_strain())
      {
        displacement.copy_locally_owned_data_from(*U);
        displacement.update_ghost_values();
        fe->thermoelastic_measure(displacement,
                                  [&](const FEValues<dim>       &fe_values,
                                      const std::vector<double> &m) {
                                    temperature->add_at_heat_points(fe_values, m, fe_measure);
                                  });
      }
    fe_measure.compress(VectorOperation::add);
  }

  template <int dim>
  void
  ThermoelasticHeating<dim>::start()
  {
    measure(previous_particles, previous_fe);
  }

  template <int dim>
  void
  ThermoelasticHeating<dim>::heat_step()
  {
    measure(present_particles, present_fe);
    const double       T0 = temperature->absolute_reference_temperature();
    const unsigned int nc = heat_state->layout().n_components();
    using Motion          = typename CoupledState<dim>::Motion;
    const auto  &motion   = heat_state->motion();
    const auto  &volume   = heat_state->pd().particles().volumes();
    const auto  &capacity = heat_state->particle_mass;
    const double ratio    = heat_state->inertia_ratio()[component];
    auto        &T        = heat_state->u;
    double       heat = 0., stored = 0.;
    // The particles that move by their own rate take their heat; the heat of the step is
    // -T_0 times the measure's change in all (the slaved particles' through their FE dofs, from
    // slaved_heating).
    const bool to_fe = present_fe.size() > 0 && heat_state->any_particle_slaved();
    if (to_fe)
      slaved_heating = 0.;
    for (std::size_t i = 0; i < present_particles.size(); ++i)
      {
        const double heating = -T0 * (present_particles[i] - previous_particles[i]) * volume[i];
        heat += heating;
        if (motion[i * nc + component] == Motion::moves)
          {
            T.local_element(i * nc + component) += heating / (capacity[i] * ratio);
            stored += heating;
          }
        else if (to_fe && motion[i * nc + component] == Motion::slaved)
          slaved_heating.local_element(i * nc + component) = heating;
      }
    T.update_ghost_values();
    if (present_fe.size() > 0)
      {
        // The heat the step brings the FE dofs: their own, and that of the particles slaved to
        // them (P^T, as the explicit step adds their forces), over their capacities.
        fe_heating.equ(-T0, present_fe);
        fe_heating.add(T0, previous_fe);
        for (unsigned int k = 0; k < fe_heating.locally_owned_size(); ++k)
          heat += fe_heating.local_element(k);
        if (to_fe)
          heat_state->method().add_particle_forces(slaved_heating, fe_heating);
        const auto &mask = heat_state->fe().prescribed_mask();
        for (unsigned int k = 0; k < fe_heating.locally_owned_size(); ++k)
          if (!mask[k])
            {
              heat_state->U.local_element(k) +=
                fe_heating.local_element(k) / heat_state->mass.local_element(k);
              stored += fe_heating.local_element(k);
            }
        heat_state->U.update_ghost_values();
      }
    local_heat += heat;
    heat_state->add_heat_in(stored);
    previous_particles = present_particles;
    previous_fe        = present_fe;
  }

  template <int dim>
  void
  ThermoelasticHeating<dim>::save(CheckpointWriter &writer, const std::string &prefix) const
  {
    pd->save_particle_records(writer, prefix + "particle measure", {}, 0, {&previous_particles});
    if (previous_fe.size() > 0)
      heat_state->fe().save_dof_values(writer, prefix + "FE measure", {&previous_fe});
    // The heat so far, once.
    writer.add_totals(prefix + "heat", {heat()});
  }

  template <int dim>
  void
  ThermoelasticHeating<dim>::load(CheckpointReader &reader, const std::string &prefix)
  {
    previous_particles.assign(pd->particles().n_owned(), 0.);
    pd->load_particle_records(reader, prefix + "particle measure", {}, 0, {&previous_particles});
    if (previous_fe.size() > 0)
      heat_state->fe().load_dof_values(reader, prefix + "FE measure", {&previous_fe});
    local_heat = heat_state->is_root() ? reader.read_totals(prefix + "heat", 1)[0] : 0.;
  }

  template <int dim>
  double
  ThermoelasticHeating<dim>::heat() const
  {
    return Utilities::MPI::sum(local_heat, heat_state->comm());
  }

  template class ThermoelasticHeating<2>;
  template class ThermoelasticHeating<3>;
} // namespace perideal
