// ---------------------------------------------------------------------
// PeriDeal: the particle and FE fields of a run, for ParaView.
// ---------------------------------------------------------------------
#include <perideal/coupling/postprocessors/field_output.h>
#include <perideal/pd/damage_model.h>

namespace perideal
{
  using namespace dealii;

  template <int dim>
  void
  FieldOutput<dim>::execute(const CoupledState<dim> &state, const StepData &data, StatisticsFile &)
  {
    if (!data.write_fields)
      return;
    const auto &settings = state.settings;
    if (!particle_output && state.pd.has_body() && (settings.write_hdf5 || settings.write_vtu))
      particle_output = std::make_unique<ParticleOutput<dim>>(state.comm,
                                                              settings.output_directory,
                                                              settings.base_name,
                                                              settings.write_hdf5,
                                                              settings.write_vtu);
    if (particle_output)
      {
        const auto        &ps      = state.pd.particles();
        const unsigned int n_owned = ps.n_owned(), nc = state.n_components();
        const auto        &x            = ps.positions();
        const auto         owned_values = [&](const ParticleVector &vector) {
          return std::vector<double>(vector.begin(), vector.begin() + std::size_t(n_owned) * nc);
        };
        // The slaved particles move with the FE field: show its velocity there.
        ParticleVector velocity(state.v);
        state.transfer.interpolate(state.V, velocity);
        particle_output->clear_fields();
        particle_output->set_points(std::vector<Point<dim>>(x.begin(), x.begin() + n_owned));
        particle_output->add_vector_field("displacement", nc, owned_values(state.u));
        particle_output->add_vector_field("velocity", nc, owned_values(velocity));
        particle_output->add_vector_field("force_density", nc, owned_values(state.internal_force));
        particle_output->add_scalar_field("damage", damage_index(ps));
        if (state.energy_density.size() == n_owned)
          particle_output->add_scalar_field("strain_energy_density", state.energy_density);
        particle_output->write(data.output_index, data.time);
      }
    state.U.update_ghost_values();
    if (settings.write_hdf5)
      state.fe.write_output(state.settings.output_directory,
                            "solution",
                            data.output_index,
                            data.time,
                            state.U);
  }

  template class FieldOutput<2>;
  template class FieldOutput<3>;
} // namespace perideal
