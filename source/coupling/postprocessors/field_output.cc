// ---------------------------------------------------------------------
// PeriDeal: the particle and FE fields of a run, for ParaView.
// ---------------------------------------------------------------------
#include <deal.II/base/data_out_base.h>

#include <perideal/coupling/postprocessors/field_output.h>
#include <perideal/pd/damage_model.h>

#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>

namespace perideal
{
  using namespace dealii;

  template <int dim>
  void
  FieldOutput<dim>::execute(const CoupledState<dim> &state, const StepData &data, StatisticsFile &)
  {
    if (!data.write_fields)
      return;
    const auto &settings = state.settings();
    // The state of a step that did not converge: files of their own, outside the run's series.
    const std::string                    suffix = data.not_converged ? "_not_converged" : "";
    std::unique_ptr<ParticleOutput<dim>> separate;
    if (data.not_converged)
      separate = create_particle_output(state, settings.base_name + suffix);
    else if (!particle_output)
      particle_output = create_particle_output(state, settings.base_name);
    ParticleOutput<dim> *const writer = data.not_converged ? separate.get() : particle_output.get();
    if (writer)
      {
        const auto        &ps      = state.pd().particles();
        const unsigned int n_owned = ps.n_owned(), nc = state.n_components();
        const auto        &x = ps.positions();
        writer->set_points(std::vector<Point<dim>>(x.begin(), x.begin() + n_owned));
        // The fields of each group of components (output_names()): displacement, velocity and
        // force_density of the translations; rotation, angular_velocity, moment_density of the
        // rotations; w, w_rate, w_load of a scalar w; temperature, temperature_rate,
        // heat_source of a temperature.
        struct Group
        {
          std::vector<unsigned int>  components;
          std::array<std::string, 3> names;
        };
        const FieldLayout &layout = state.layout();
        std::vector<Group> groups;
        for (unsigned int c = 0; c < nc; ++c)
          {
            const auto names = output_names(layout[c]);
            const auto group = std::find_if(groups.begin(), groups.end(), [&](const Group &g) {
              return g.names == names;
            });
            if (group == groups.end())
              groups.push_back(Group{{c}, names});
            else
              group->components.push_back(c);
          }
        {
          // The particles slaved to the FE field move with it: show its velocity there (released
          // before the write, whose peak memory it would raise).
          ParticleVector velocity(state.v);
          state.method().interpolate_to_particles(state.V, velocity);
          for (const auto &group : groups)
            if (!group.components.empty())
              {
                const auto values = [&](const ParticleVector &vector) {
                  std::vector<double> result;
                  result.reserve(std::size_t(n_owned) * group.components.size());
                  for (unsigned int i = 0; i < n_owned; ++i)
                    for (const unsigned int c : group.components)
                      result.push_back(vector.local_element(i * nc + c));
                  return result;
                };
                const unsigned int n = group.components.size();
                writer->add_vector_field(group.names[0], n, values(state.u));
                writer->add_vector_field(group.names[1], n, values(velocity));
                writer->add_vector_field(group.names[2], n, values(state.internal_force));
              }
        }
        state.u.update_ghost_values();
        for (const auto &field : state.pd().material().derived_fields(ps, state.u))
          writer->add_vector_field(field.name, field.n_components, field.values);
        writer->add_scalar_field("damage", damage_index(ps));
        // The temperature change of a thermal strain (<Temperature>) as the model read it.
        if (const ParticleVector *delta_T = state.pd().material().temperature_change())
          {
            std::vector<double> values(n_owned);
            for (unsigned int i = 0; i < n_owned; ++i)
              values[i] = delta_T->local_element(i);
            writer->add_scalar_field("temperature_change", values);
            // The free strain of the temperature change in the model's plane
            // (MaterialModel::thermal_expansion() Delta T), named as the FE output's.
            const auto alpha  = state.pd().material().thermal_expansion();
            const char axes[] = {'x', 'y', 'z'};
            for (unsigned int a = 0; a < dim; ++a)
              for (unsigned int b = a; b < dim; ++b)
                {
                  for (unsigned int i = 0; i < n_owned; ++i)
                    values[i] = alpha[a][b] * delta_T->local_element(i);
                  writer->add_scalar_field(std::string("thermal_strain_") + axes[a] + axes[b],
                                           values);
                }
          }
        if (state.energy_density.size() == n_owned)
          writer->add_scalar_field("strain_energy_density", state.energy_density);
        writer->write(data.output_index, data.time);
      }
    state.U.update_ghost_values();
    if (settings.write_hdf5)
      {
        // A file of its own has only its own record: the run's are left as they are.
        std::vector<XDMFEntry> own_record;
        state.fe().write_output(settings.output_directory,
                                settings.solution_name + suffix,
                                data.output_index,
                                data.time,
                                state.U,
                                data.not_converged ? own_record : fe_records);
      }
  }

  template <int dim>
  std::unique_ptr<ParticleOutput<dim>>
  FieldOutput<dim>::create_particle_output(const CoupledState<dim> &state,
                                           const std::string       &base_name)
  {
    const auto &settings = state.settings();
    if (state.pd().has_body() && (settings.write_hdf5 || settings.write_vtu))
      return std::make_unique<ParticleOutput<dim>>(state.comm(),
                                                   settings.output_directory,
                                                   base_name,
                                                   settings.write_hdf5,
                                                   settings.write_vtu);
    return nullptr;
  }

  template <int dim>
  std::string
  FieldOutput<dim>::save_state(const CoupledState<dim> &) const
  {
    const std::vector<char> fe_packed = Utilities::pack(fe_records, false);
    const std::vector<char> packed =
      Utilities::pack(std::make_pair(particle_output ? particle_output->save_records() :
                                                       std::string(),
                                     std::string(fe_packed.begin(), fe_packed.end())),
                      false);
    return std::string(packed.begin(), packed.end());
  }

  template <int dim>
  void
  FieldOutput<dim>::load_state(const CoupledState<dim> &state, const std::string &packed)
  {
    const auto records =
      Utilities::unpack<std::pair<std::string, std::string>>(std::vector<char>(packed.begin(),
                                                                               packed.end()),
                                                             false);
    // Empty: no particle output before the checkpoint (a quasi-static run writes its fields
    // at the last load step only); the writer is then created by the first output.
    if (!records.first.empty())
      {
        particle_output = create_particle_output(state, state.settings().base_name);
        if (particle_output)
          particle_output->load_records(records.first);
      }
    fe_records = Utilities::unpack<std::vector<XDMFEntry>>(std::vector<char>(records.second.begin(),
                                                                             records.second.end()),
                                                           false);
  }

  template class FieldOutput<2>;
  template class FieldOutput<3>;
} // namespace perideal

PERIDEAL_REGISTER_POSTPROCESSOR(
  perideal::FieldOutput,
  "field output",
  "the particle and FE fields every <Output/Output interval> steps and after the last.")
