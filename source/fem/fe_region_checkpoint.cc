// ---------------------------------------------------------------------
// PeriDeal: the FE region's records in a checkpoint (its cells' dof values).
// ---------------------------------------------------------------------
#include <deal.II/grid/cell_id.h>

#include <perideal/fem/fe_region.h>

#include <map>

namespace perideal
{
  using namespace dealii;

  namespace
  {
    using CellKey = CellId::binary_type;

    // Whether an owned cell carries FE unknowns (FE_Q, not FE_Nothing).
    template <int dim>
    bool
    carries_unknowns(const FERegion<dim> &fe, const typename DoFHandler<dim>::cell_iterator &cell)
    {
      return fe.n_dofs() > 0 && cell->is_locally_owned() && cell->active_fe_index() == 0;
    }
  } // namespace

  template <int dim>
  std::uint64_t
  FERegion<dim>::n_cells_with_unknowns() const
  {
    std::uint64_t n_cells = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      n_cells += carries_unknowns(*this, cell);
    return Utilities::MPI::sum(n_cells, comm);
  }

  template <int dim>
  void
  FERegion<dim>::save_dof_values(CheckpointWriter                    &writer,
                                 const std::string                   &name,
                                 const std::vector<const FEVector *> &vectors) const
  {
    // Ghosted copies, so that the dofs other ranks own are current (the vectors are left as
    // they are).
    std::vector<char> data;
    if (n_dofs() > 0)
      {
        std::vector<FEVector> ghosted(vectors.size());
        for (unsigned int k = 0; k < ghosted.size(); ++k)
          {
            initialize_vector(ghosted[k]);
            ghosted[k] = *vectors[k];
            ghosted[k].update_ghost_values();
          }
        std::vector<types::global_dof_index> dofs;
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (carries_unknowns(*this, cell))
            {
              const CellKey key = cell->id().template to_binary<dim>();
              append_bytes(data, key.data(), key.size());
              dofs.resize(cell->get_fe().n_dofs_per_cell());
              cell->get_dof_indices(dofs);
              for (const auto &vector : ghosted)
                for (const auto dof : dofs)
                  {
                    const double value = vector(dof);
                    append_bytes(data, &value);
                  }
            }
      }
    writer.add_bytes(name, std::move(data));
  }

  template <int dim>
  void
  FERegion<dim>::load_dof_values(CheckpointReader              &reader,
                                 const std::string             &name,
                                 const std::vector<FEVector *> &vectors) const
  {
    if (n_dofs() == 0)
      return;
    const std::vector<char> data          = reader.read_all(name);
    const unsigned int      dofs_per_cell = dof_handler.get_fe_collection()[0].n_dofs_per_cell();
    const std::size_t record = sizeof(CellKey) + vectors.size() * dofs_per_cell * sizeof(double);
    std::map<CellKey, const char *> records;
    for (std::size_t offset = 0; offset + record <= data.size(); offset += record)
      {
        CellKey key;
        std::memcpy(key.data(), &data[offset], sizeof(CellKey));
        records[key] = &data[offset + sizeof(CellKey)];
      }
    std::vector<types::global_dof_index> dofs(dofs_per_cell);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (carries_unknowns(*this, cell))
        {
          const auto found = records.find(cell->id().template to_binary<dim>());
          AssertThrow(found != records.end(),
                      ExcMessage(reader.description() +
                                 " is from another problem: it has no values for the FE cell " +
                                 cell->id().to_string() + ". Nothing was written."));
          cell->get_dof_indices(dofs);
          const char *values = found->second;
          for (auto *vector : vectors)
            for (const auto dof : dofs)
              {
                double value;
                take_bytes(values, &value);
                if (vector->in_local_range(dof))
                  (*vector)(dof) = value;
              }
        }
  }

#define PERIDEAL_INSTANTIATE(dim)                                                                     \
  template std::uint64_t FERegion<dim>::n_cells_with_unknowns() const;                                \
  template void          FERegion<dim>::save_dof_values(CheckpointWriter &,                           \
                                               const std::string &,                          \
                                               const std::vector<const FEVector *> &) const; \
  template void          FERegion<dim>::load_dof_values(CheckpointReader &,                           \
                                               const std::string &,                          \
                                               const std::vector<FEVector *> &) const;
  PERIDEAL_INSTANTIATE(2)
  PERIDEAL_INSTANTIATE(3)
#undef PERIDEAL_INSTANTIATE
} // namespace perideal
