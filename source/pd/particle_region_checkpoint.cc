// ---------------------------------------------------------------------
// PeriDeal: the particle region's records in a checkpoint (particles, bond states, histories).
// ---------------------------------------------------------------------
#include <perideal/pd/particle_region.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>

namespace perideal
{
  using namespace dealii;

  namespace
  {
    using BondKey = std::array<std::uint64_t, 2>;

    // The owned particles in the order of their invariant index.
    template <int dim>
    std::vector<unsigned int>
    invariant_order(const ParticleSystem<dim> &ps)
    {
      std::vector<unsigned int> order(ps.n_owned());
      std::iota(order.begin(), order.end(), 0u);
      std::sort(order.begin(), order.end(), [&](const unsigned int a, const unsigned int b) {
        return ps.invariant_index(a) < ps.invariant_index(b);
      });
      return order;
    }

    // The key of bond @p b of particle @p i: its particles' invariant indices, lower first.
    template <int dim>
    BondKey
    bond_key(const ParticleSystem<dim> &ps, const unsigned int i, const unsigned int b)
    {
      const std::uint64_t p = ps.invariant_index(i), q = ps.invariant_index(ps.bonds().neighbor[b]);
      return {{std::min(p, q), std::max(p, q)}};
    }

    // Whether this rank writes bond @p b of particle @p i: a bond to a ghost is listed on two
    // ranks, and the one with the lower invariant index first writes it.
    template <int dim>
    bool
    writes_bond(const ParticleSystem<dim> &ps, const unsigned int i, const unsigned int b)
    {
      return ps.neighbor_is_owned(b) ||
             ps.invariant_index(i) < ps.invariant_index(ps.bonds().neighbor[b]);
    }
  } // namespace

  template <int dim>
  void
  ParticleRegion<dim>::save_particle_records(
    CheckpointWriter                               &writer,
    const std::string                              &name,
    const std::vector<const ParticleVector *>      &vectors,
    const unsigned int                              n_components,
    const std::vector<const std::vector<double> *> &per_particle) const
  {
    const auto                &ps    = particles();
    const std::size_t          width = vectors.size() * n_components + per_particle.size();
    std::vector<unsigned int>  order = invariant_order(ps);
    std::vector<std::uint64_t> indices(order.size());
    std::vector<double>        values(order.size() * width);
    for (std::size_t r = 0; r < order.size(); ++r)
      {
        indices[r]     = ps.invariant_index(order[r]);
        double *record = &values[r * width];
        for (const ParticleVector *vector : vectors)
          for (unsigned int c = 0; c < n_components; ++c)
            *record++ = vector->local_element(order[r] * n_components + c);
        for (const std::vector<double> *array : per_particle)
          *record++ = (*array)[order[r]];
      }
    std::vector<char> data;
    append_bytes(data, values.data(), values.size());
    writer.add_records(name, ps.n_global(), width * sizeof(double), indices, std::move(data));
  }

  template <int dim>
  void
  ParticleRegion<dim>::load_particle_records(
    CheckpointReader                         &reader,
    const std::string                        &name,
    const std::vector<ParticleVector *>      &vectors,
    const unsigned int                        n_components,
    const std::vector<std::vector<double> *> &per_particle) const
  {
    const auto                &ps    = particles();
    const std::size_t          width = vectors.size() * n_components + per_particle.size();
    std::vector<unsigned int>  order = invariant_order(ps);
    std::vector<std::uint64_t> indices(order.size());
    for (std::size_t r = 0; r < order.size(); ++r)
      indices[r] = ps.invariant_index(order[r]);
    const std::vector<char> data     = reader.read_records(name, width * sizeof(double), indices);
    const char             *position = data.data();
    for (std::size_t r = 0; r < order.size(); ++r)
      {
        for (ParticleVector *vector : vectors)
          for (unsigned int c = 0; c < n_components; ++c)
            take_bytes(position, &vector->local_element(order[r] * n_components + c));
        for (std::vector<double> *array : per_particle)
          take_bytes(position, &(*array)[order[r]]);
      }
  }

  template <int dim>
  void
  ParticleRegion<dim>::save_bond_states(CheckpointWriter &writer, const std::string &name) const
  {
    const auto       &ps    = particles();
    const BondList   &bonds = ps.bonds();
    std::vector<char> data;
    for (unsigned int i = 0; i < ps.n_owned(); ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        if (bonds.intact[b] == 0 && writes_bond(ps, i, b))
          {
            const BondKey key = bond_key(ps, i, b);
            append_bytes(data, key.data(), key.size());
          }
    writer.add_bytes(name, std::move(data));
  }

  template <int dim>
  void
  ParticleRegion<dim>::load_bond_states(CheckpointReader &reader, const std::string &name)
  {
    auto                   &ps   = particles();
    const std::vector<char> data = reader.read_all(name);
    std::vector<BondKey>    broken(data.size() / sizeof(BondKey));
    std::memcpy(broken.data(), data.data(), broken.size() * sizeof(BondKey));
    std::sort(broken.begin(), broken.end());
    BondList &bonds   = ps.bonds();
    double    matched = 0.;
    for (unsigned int i = 0; i < ps.n_owned(); ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        if (std::binary_search(broken.begin(), broken.end(), bond_key(ps, i, b)))
          {
            bonds.break_bond(b);
            matched += ps.bond_share(b);
          }
    const std::int64_t found = std::llround(Utilities::MPI::sum(matched, ps.get_communicator()));
    AssertThrow(found == std::int64_t(broken.size()),
                ExcMessage(reader.description() +
                           " is from another problem: " + std::to_string(broken.size()) +
                           " broken bonds, of which " + std::to_string(found) +
                           " join particles of this run. Nothing was " + "written."));
  }

  template <int dim>
  void
  ParticleRegion<dim>::save_bond_histories(CheckpointWriter &writer, const std::string &name) const
  {
    const unsigned int n_values = has_body() ? material().n_bond_history_values() : 0;
    if (n_values == 0)
      return;
    const auto               &ps     = particles();
    const BondList           &bonds  = ps.bonds();
    const std::vector<double> values = material().bond_history(ps);
    std::vector<char>         data;
    for (unsigned int i = 0; i < ps.n_owned(); ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        {
          const double *begin = &values[std::size_t(b) * n_values];
          if (writes_bond(ps, i, b) &&
              std::any_of(begin, begin + n_values, [](const double v) { return v != 0.; }))
            {
              const BondKey key = bond_key(ps, i, b);
              append_bytes(data, key.data(), key.size());
              append_bytes(data, begin, n_values);
            }
        }
    writer.add_bytes(name, std::move(data));
  }

  template <int dim>
  void
  ParticleRegion<dim>::load_bond_histories(CheckpointReader &reader, const std::string &name)
  {
    const unsigned int n_values = has_body() ? material().n_bond_history_values() : 0;
    if (n_values == 0)
      return;
    auto                   &ps     = particles();
    const BondList         &bonds  = ps.bonds();
    const std::size_t       record = sizeof(BondKey) + n_values * sizeof(double);
    const std::vector<char> data   = reader.read_all(name);
    AssertThrow(data.size() % record == 0,
                ExcMessage(reader.description() +
                           " is from another problem: its bond histories "
                           "are not of " +
                           std::to_string(n_values) +
                           " values. Nothing was "
                           "written."));
    std::map<BondKey, const char *> records;
    for (std::size_t offset = 0; offset < data.size(); offset += record)
      {
        BondKey key;
        std::memcpy(key.data(), &data[offset], sizeof(key));
        records[key] = &data[offset + sizeof(key)];
      }
    std::vector<double> values(std::size_t(bonds.size()) * n_values, 0.);
    double              matched = 0.;
    for (unsigned int i = 0; i < ps.n_owned(); ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        {
          const auto found = records.find(bond_key(ps, i, b));
          if (found != records.end())
            {
              std::memcpy(&values[std::size_t(b) * n_values],
                          found->second,
                          n_values * sizeof(double));
              matched += ps.bond_share(b);
            }
        }
    const std::int64_t found = std::llround(Utilities::MPI::sum(matched, ps.get_communicator()));
    AssertThrow(found == std::int64_t(records.size()),
                ExcMessage(reader.description() +
                           " is from another problem: " + std::to_string(records.size()) +
                           " bond histories, of which " + std::to_string(found) +
                           " belong to bonds of this run. Nothing was " + "written."));
    material().set_bond_history(ps, values);
  }

#define PERIDEAL_INSTANTIATE(dim)                                                                 \
  template void ParticleRegion<dim>::save_particle_records(                                       \
    CheckpointWriter &,                                                                           \
    const std::string &,                                                                          \
    const std::vector<const ParticleVector *> &,                                                  \
    const unsigned int,                                                                           \
    const std::vector<const std::vector<double> *> &) const;                                      \
  template void ParticleRegion<dim>::load_particle_records(                                       \
    CheckpointReader &,                                                                           \
    const std::string &,                                                                          \
    const std::vector<ParticleVector *> &,                                                        \
    const unsigned int,                                                                           \
    const std::vector<std::vector<double> *> &) const;                                            \
  template void ParticleRegion<dim>::save_bond_states(CheckpointWriter &, const std::string &)    \
    const;                                                                                        \
  template void ParticleRegion<dim>::load_bond_states(CheckpointReader &, const std::string &);   \
  template void ParticleRegion<dim>::save_bond_histories(CheckpointWriter &, const std::string &) \
    const;                                                                                        \
  template void ParticleRegion<dim>::load_bond_histories(CheckpointReader &, const std::string &);
  PERIDEAL_INSTANTIATE(2)
  PERIDEAL_INSTANTIATE(3)
#undef PERIDEAL_INSTANTIATE
} // namespace perideal
