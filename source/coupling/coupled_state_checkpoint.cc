// ---------------------------------------------------------------------
// PeriDeal: a state's records in a checkpoint (its sums and vectors, through its regions), and
// the copy of them a quasi-static run keeps in memory.
// ---------------------------------------------------------------------
#include <perideal/coupling/coupled_state.h>

#include <cstring>
#include <sstream>

namespace perideal
{
  using namespace dealii;

  template <int dim>
  std::string
  CoupledState<dim>::fingerprint(const std::string &prefix) const
  {
    const auto         parts = stored_parts();
    const unsigned int fe_dofs_per_cell =
      fe().n_dofs() > 0 ? fe().get_dof_handler().get_fe_collection()[0].n_dofs_per_cell() : 0;
    std::ostringstream out;
    out << prefix << "unknowns = " << layout().description() << '\n'
        << prefix << "particles = " << pd().particles().n_global() << '\n'
        << prefix << "bonds = " << pd().particles().n_global_bonds() << '\n'
        << prefix << "FE cells with unknowns = " << fe().n_cells_with_unknowns() << '\n'
        << prefix << "FE dofs = " << fe().n_dofs() << '\n'
        << prefix << "FE dofs per cell = " << fe_dofs_per_cell << '\n'
        << prefix << "particle fields = " << parts.particle_vectors.size() << " x "
        << n_components() << " + 1\n"
        << prefix << "FE fields = " << parts.fe_vectors.size() << '\n'
        << prefix << "bond history values = "
        << (pd().has_body() ? pd().material().n_bond_history_values() : 0) << '\n';
    return out.str();
  }

  template <int dim>
  void
  CoupledState<dim>::save(CheckpointWriter &writer, const std::string &prefix) const
  {
    const auto          parts = stored_parts();
    std::vector<double> sums;
    for (const auto *part : {&parts.sums, &parts.totals})
      for (const double *sum : *part)
        sums.push_back(*sum);
    std::vector<char> data;
    append_bytes(data, sums.data(), sums.size());
    writer.add_records(prefix + "sums",
                       Utilities::MPI::n_mpi_processes(comm()),
                       sums.size() * sizeof(double),
                       {Utilities::MPI::this_mpi_process(comm())},
                       std::move(data));
    pd().save_particle_records(writer,
                               prefix + "particles",
                               parts.particle_vectors,
                               n_components(),
                               {parts.energy_density});
    pd().save_bond_histories(writer, prefix + "bond histories");
    fe().save_dof_values(writer, prefix + "FE", parts.fe_vectors);
    // The temperature the next step's work of the temperature change starts from
    // (hold_temperature()): that of the last force evaluation, stored rather than derived at
    // the restart.
    if (has_temperature())
      {
        const bool on_particles = held_temperature_change.size() > 0;
        writer.add_totals(prefix + "held temperature",
                          {on_particles ? 1. : 0., held_thermal_energy});
        if (on_particles)
          pd().save_particle_records(writer,
                                     prefix + "held particle temperature",
                                     {&held_temperature_change},
                                     1,
                                     {});
        if (fe_thermal)
          fe().save_dof_values(writer, prefix + "held thermal load", {&held_thermal_load});
      }
  }

  template <int dim>
  void
  CoupledState<dim>::load(CheckpointReader &reader, const std::string &prefix)
  {
    const auto         parts   = stored_parts();
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm());
    const unsigned int rank    = Utilities::MPI::this_mpi_process(comm());
    const std::size_t  n_sums  = parts.sums.size() + parts.totals.size();
    // This rank's partial sums; on another number of ranks their totals on rank 0 and the
    // totals (the same on every rank) from the first record.
    const std::string          name        = prefix + "sums";
    const std::uint64_t        saved_ranks = reader.n_records(name);
    const bool                 same_ranks  = saved_ranks == n_ranks;
    std::vector<std::uint64_t> indices;
    for (unsigned int r = 0; r < saved_ranks; ++r)
      if (same_ranks ? r == rank : true)
        indices.push_back(r);
    const std::vector<char> data = reader.read_records(name, n_sums * sizeof(double), indices);
    std::vector<double>     records(indices.size() * n_sums);
    std::memcpy(records.data(), data.data(), data.size());
    for (std::size_t k = 0; k < parts.sums.size(); ++k)
      {
        *parts.sums[k] = 0.;
        if (same_ranks || rank == 0)
          for (std::size_t r = 0; r < indices.size(); ++r)
            *parts.sums[k] += records[r * n_sums + k];
      }
    for (std::size_t k = 0; k < parts.totals.size(); ++k)
      *parts.totals[k] = records[parts.sums.size() + k];

    pd().load_particle_records(reader,
                               prefix + "particles",
                               parts.particle_vectors,
                               n_components(),
                               {parts.energy_density});
    pd().load_bond_histories(reader, prefix + "bond histories");
    fe().load_dof_values(reader, prefix + "FE", parts.fe_vectors);
    u.update_ghost_values();
    U.update_ghost_values();
    if (has_temperature())
      {
        const std::vector<double> values = reader.read_totals(prefix + "held temperature", 2);
        held_thermal_energy              = values[1];
        if (values[0] != 0.)
          {
            pd().particles().reinit_vector(held_temperature_change, 1);
            pd().load_particle_records(reader,
                                       prefix + "held particle temperature",
                                       {&held_temperature_change},
                                       1,
                                       {});
            held_temperature_change.update_ghost_values();
          }
        if (fe_thermal)
          {
            fe().initialize_vector(held_thermal_load);
            fe().load_dof_values(reader, prefix + "held thermal load", {&held_thermal_load});
          }
      }
  }

  namespace
  {
    /**
     * @p to = @p from, with @p from's layout. A plain assignment between vectors of different
     * partitioners compares them collectively, but only on the ranks whose partitioner objects
     * differ: after a conversion of the adaptive PD region (a new layout on some ranks only)
     * the ranks would call different collectives. Taking @p from's partitioner first (not
     * collective) makes every rank assign between equal partitioners.
     */
    void
    copy_with_layout(LinearAlgebra::distributed::Vector<double>       &to,
                     const LinearAlgebra::distributed::Vector<double> &from)
    {
      if (to.get_partitioner() != from.get_partitioner())
        to.reinit(from, true);
      to = from;
    }

    /**
     * @p to = @p from, owned and ghost entries as they are (the held temperature's ghosts are
     * set without the vector's ghost state), in @p from's layout.
     */
    void
    copy_local_entries(LinearAlgebra::distributed::Vector<double>       &to,
                       const LinearAlgebra::distributed::Vector<double> &from)
    {
      to.reinit(from.get_partitioner());
      if (from.size() > 0)
        std::copy(from.begin(),
                  from.begin() + from.get_partitioner()->locally_owned_size() +
                    from.get_partitioner()->n_ghost_indices(),
                  to.begin());
    }
  } // namespace

  template <int dim>
  void
  CoupledState<dim>::keep()
  {
    const auto parts = stored_parts();
    kept.particle_vectors.resize(parts.particle_vectors.size());
    for (unsigned int k = 0; k < parts.particle_vectors.size(); ++k)
      copy_with_layout(kept.particle_vectors[k], *parts.particle_vectors[k]);
    kept.energy_density = *parts.energy_density;
    kept.fe_vectors.resize(parts.fe_vectors.size());
    for (unsigned int k = 0; k < parts.fe_vectors.size(); ++k)
      copy_with_layout(kept.fe_vectors[k], *parts.fe_vectors[k]);
    kept.sums.clear();
    for (const auto *part : {&parts.sums, &parts.totals})
      for (const double *sum : *part)
        kept.sums.push_back(*sum);
    kept.history.clear();
    if (pd().has_body() && pd().material().n_bond_history_values() > 0)
      kept.history = pd().material().bond_history(pd().particles());
    // The temperature the work of the next step starts from (what save() writes of it).
    if (has_temperature())
      {
        copy_local_entries(kept.held_temperature_change, held_temperature_change);
        copy_with_layout(kept.held_thermal_load, held_thermal_load);
        kept.held_thermal_energy = held_thermal_energy;
      }
  }

  template <int dim>
  void
  CoupledState<dim>::restore_kept()
  {
    const auto parts = stored_parts();
    for (unsigned int k = 0; k < parts.particle_vectors.size(); ++k)
      *parts.particle_vectors[k] = kept.particle_vectors[k];
    *parts.energy_density = kept.energy_density;
    for (unsigned int k = 0; k < parts.fe_vectors.size(); ++k)
      *parts.fe_vectors[k] = kept.fe_vectors[k];
    auto sum = kept.sums.begin();
    for (const auto *part : {&parts.sums, &parts.totals})
      for (double *value : *part)
        *value = *sum++;
    if (!kept.history.empty())
      pd().material().set_bond_history(pd().particles(), kept.history);
    if (has_temperature())
      {
        copy_local_entries(held_temperature_change, kept.held_temperature_change);
        copy_with_layout(held_thermal_load, kept.held_thermal_load);
        held_thermal_energy = kept.held_thermal_energy;
      }
    // The bonds broken since keep() are intact again: not broken for the other physics either.
    if (broken_bond_record != nullptr)
      broken_bond_record->clear();
  }

#define PERIDEAL_INSTANTIATE(dim)                                                              \
  template std::string CoupledState<dim>::fingerprint(const std::string &) const;              \
  template void        CoupledState<dim>::save(CheckpointWriter &, const std::string &) const; \
  template void        CoupledState<dim>::load(CheckpointReader &, const std::string &);       \
  template void        CoupledState<dim>::keep();                                              \
  template void        CoupledState<dim>::restore_kept();
  PERIDEAL_INSTANTIATE(2)
  PERIDEAL_INSTANTIATE(3)
#undef PERIDEAL_INSTANTIATE
} // namespace perideal
