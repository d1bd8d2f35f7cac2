// ---------------------------------------------------------------------
// PeriDeal: the transfer operator from FE displacements to particle displacements.
// ---------------------------------------------------------------------
#include <deal.II/base/bounding_box.h>
#include <deal.II/base/mpi.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/grid_tools_cache.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <perideal/base/parameter_utilities.h>
#include <perideal/base/setup_times.h>
#include <perideal/coupling/transfer_operator.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace perideal
{
  using namespace dealii;

  namespace
  {
    /**
     * @brief Boxes that cover the locally owned cells: the cells' bounding boxes gathered into
     * at most 4^dim tiles of the rank's bounding box (by cell centre), one box per non-empty
     * tile. The owner guess of the point search tests every particle against every box of
     * every rank; deal.II's boxes of the coarse cells (one per cell of an unrefined gmsh mesh)
     * made it quadratic, and its merging of them is quadratic too.
     */
    template <int dim>
    std::vector<BoundingBox<dim>>
    owned_cell_boxes(const Triangulation<dim> &tria)
    {
      constexpr unsigned int        tiles = 4;
      std::vector<BoundingBox<dim>> cell_boxes;
      for (const auto &cell : tria.active_cell_iterators())
        if (cell->is_locally_owned())
          cell_boxes.push_back(cell->bounding_box());
      if (cell_boxes.empty())
        return {};
      BoundingBox<dim> all = cell_boxes.front();
      for (const auto &box : cell_boxes)
        all.merge_with(box);
      std::vector<std::optional<BoundingBox<dim>>> tile_box(Utilities::fixed_power<dim>(tiles));
      for (const auto &box : cell_boxes)
        {
          const Point<dim> centre = box.center();
          unsigned int     index  = 0;
          for (unsigned int d = dim; d-- > 0;)
            {
              const double extent = all.side_length(d);
              const double t = extent > 0. ? (centre[d] - all.lower_bound(d)) / extent * tiles : 0.;
              index          = index * tiles + std::min(tiles - 1, static_cast<unsigned int>(t));
            }
          if (tile_box[index])
            tile_box[index]->merge_with(box);
          else
            tile_box[index] = box;
        }
      std::vector<BoundingBox<dim>> result;
      for (const auto &box : tile_box)
        if (box)
          result.push_back(*box);
      return result;
    }

    /// The permutation symbol eps_rjk of three axes.
    double
    levi_civita(const unsigned int r, const unsigned int j, const unsigned int k)
    {
      if (r == j || j == k || k == r)
        return 0.;
      return (j == (r + 1) % 3) ? 1. : -1.;
    }
  } // namespace

  template <int dim>
  typename TransferOperator<dim>::ComponentRows
  TransferOperator<dim>::component_rows(const FieldLayout &fe_layout,
                                        const FieldLayout &particle_layout,
                                        const bool         check)
  {
    ComponentRows rows;
    rows.value.assign(fe_layout.n_components(), 0);
    std::vector<bool> fed(fe_layout.n_components(), false);
    const auto        mismatch = [&](const std::string &what) {
      return ExcMessage(what + ": the particles' unknowns (" + particle_layout.description() +
                        ") and the FE field's (" + fe_layout.description() +
                        ") must name the same components; the particles may add rotations, "
                               "which follow half the curl of the FE displacement.");
    };
    bool first = true;
    for (unsigned int c = 0; c < particle_layout.n_components(); ++c)
      {
        unsigned int f = 0;
        while (f < fe_layout.n_components() && !(fe_layout[f] == particle_layout[c]))
          ++f;
        if (f < fe_layout.n_components())
          {
            rows.value[f] = c;
            fed[f]        = true;
            if (first)
              rows.first_value_row = c;
            first = false;
          }
        else if (particle_layout.kind(c) == ComponentKind::rotation &&
                 fe_layout.n_components(ComponentKind::translation) == dim)
          rows.curl.push_back(c);
        else
          AssertThrow(!check,
                      mismatch("The particles' component '" + particle_layout.name(c) +
                               "' has no counterpart in the FE field"));
      }
    for (unsigned int f = 0; f < fe_layout.n_components(); ++f)
      AssertThrow(!check || fed[f],
                  mismatch("The FE field's component '" + fe_layout.name(f) +
                           "' has no counterpart among the particles' unknowns"));
    return rows;
  }

  template <int dim>
  void
  TransferOperator<dim>::reinit(const FERegion<dim>       &fe,
                                const ParticleSystem<dim> &particles,
                                const FieldLayout         &layout,
                                const std::vector<bool>   &located_particles)
  {
    const SetupTimes::Scope time(SetupStage::transfer_operator);
    Assert(located_particles.empty() || located_particles.size() == particles.n_owned(),
           ExcDimensionMismatch(located_particles.size(), particles.n_owned()));
    const MPI_Comm comm        = particles.get_communicator();
    const auto    &tria        = fe.get_triangulation();
    const auto    &dof_handler = fe.get_dof_handler();
    const auto     n_owned     = particles.n_owned();
    const auto    &x           = particles.positions();
    n_components               = layout.n_components();
    const auto row_kinds = component_rows(fe.field_layout(), layout, dof_handler.n_dofs() > 0);

    // Each rank's first particle global index (owned particles are numbered contiguously).
    const types::global_dof_index first_global = n_owned > 0 ? particles.global_index(0) : 0;
    const auto                    offsets      = Utilities::MPI::all_gather(comm, first_global);

    struct Entry
    {
      types::global_dof_index row, column;
      double                  value;
    };
    std::vector<Entry> entries;
    // Without FE unknowns (an empty FE region) every particle is free: no point search, an
    // empty P.
    if (dof_handler.n_dofs() > 0)
      {
        // Locate the owned particles in the locally owned cells of all ranks (one cell each).
        const MappingQ1<dim>        mapping;
        const GridTools::Cache<dim> cache(tria, mapping);
        const auto                  local_boxes  = owned_cell_boxes(tria);
        const auto                  global_boxes = Utilities::MPI::all_gather(comm, local_boxes);
        // A particle not to be located is placed beyond every rank's boxes: the search sends
        // it nowhere, and it stays free.
        std::vector<Point<dim>> points(x.begin(), x.begin() + n_owned);
        Point<dim>              nowhere;
        for (unsigned int d = 0; d < dim; ++d)
          nowhere[d] = std::numeric_limits<double>::max();
        if (!located_particles.empty())
          for (unsigned int i = 0; i < n_owned; ++i)
            if (!located_particles[i])
              points[i] = nowhere;
        const auto located =
          GridTools::internal::distributed_compute_point_locations(cache,
                                                                   points,
                                                                   global_boxes,
                                                                   std::vector<bool>(),
                                                                   1e-10,
                                                                   /*perform_handshake=*/true,
                                                                   /*enforce_unique_mapping=*/true);

        // Every particle must lie in the mesh (checked on all ranks together, so that all throw).
        {
          std::vector<bool> found(n_owned, false);
          for (const auto &component : located.recv_components)
            found[std::get<1>(component)] = true;
          std::vector<Point<dim>> lost;
          for (unsigned int i = 0; i < n_owned; ++i)
            if (!found[i] && (located_particles.empty() || located_particles[i]))
              lost.push_back(x[i]);
          const auto n_lost = Utilities::MPI::sum<types::global_dof_index>(lost.size(), comm);
          if (n_lost > 0)
            {
              Point<dim> first;
              for (const auto &points_of_rank : Utilities::MPI::all_gather(comm, lost))
                if (!points_of_rank.empty())
                  {
                    first = points_of_rank.front();
                    break;
                  }
              std::string where;
              for (unsigned int d = 0; d < dim; ++d)
                where += (d > 0 ? ", " : "") + ParameterUtilities::format_number(first[d]);
              AssertThrow(false,
                          ExcMessage(
                            std::to_string(n_lost) + " particle(s), the first at (" + where +
                            "), lie outside the FE mesh: the PD region (<Discretization/"
                            "Body>, widened by the horizon where beta > 0) must lie inside "
                            "the mesh of <Finite elements>."));
            }
        }

        // The rows this rank computes: for each located point in an FE-carrying cell, the shape
        // functions of that cell (values; for rotations the FE field lacks, gradients).
        const auto                          &fe_element = fe.get_fe_collection()[0];
        const unsigned int                   n_dofs     = fe_element.n_dofs_per_cell();
        std::vector<types::global_dof_index> dofs(n_dofs);
        const FieldLayout                   &fe_layout = fe.field_layout();
        for (const auto &component : located.send_components)
          {
            const auto &[level_index, rank, local, reference, real, permutation] = component;
            (void)permutation;
            const typename DoFHandler<dim>::active_cell_iterator cell(&tria,
                                                                      level_index.first,
                                                                      level_index.second,
                                                                      &dof_handler);
            AssertThrow(GeometryInfo<dim>::is_inside_unit_cell(reference, 1e-8),
                        ExcInternalError("The point search placed a particle outside its cell (" +
                                         std::to_string(reference[0]) + ", " +
                                         std::to_string(reference[1]) + ") at (" +
                                         std::to_string(real[0]) + ", " + std::to_string(real[1]) +
                                         ")."));
            if (cell->active_fe_index() != 0)
              continue; // FE_Nothing: the particle is free
            cell->get_dof_indices(dofs);
            const types::global_dof_index particle = offsets[rank] + local;
            // The inverse transpose of the Jacobian of the (d-linear) mapping at the point, for
            // the shape gradients the rotation rows need.
            Tensor<2, dim> inverse_transpose;
            if (!row_kinds.curl.empty())
              {
                Tensor<2, dim> jacobian;
                for (const unsigned int v : cell->vertex_indices())
                  jacobian +=
                    outer_product(cell->vertex(v),
                                  GeometryInfo<dim>::d_linear_shape_function_gradient(reference,
                                                                                      v));
                inverse_transpose = transpose(invert(jacobian));
              }
            for (unsigned int a = 0; a < n_dofs; ++a)
              {
                const unsigned int fe_component = fe_element.system_to_component_index(a).first;
                const double       value        = fe_element.shape_value(a, reference);
                if (value != 0.)
                  entries.push_back(
                    {particle * n_components + row_kinds.value[fe_component], dofs[a], value});
                if (row_kinds.curl.empty() ||
                    fe_layout.kind(fe_component) != ComponentKind::translation)
                  continue;
                // theta_r = 1/2 eps_rjk du_k/dx_j: shape function a moves translation k.
                const Tensor<1, dim> gradient =
                  inverse_transpose * fe_element.shape_grad(a, reference);
                const unsigned int k = fe_layout[fe_component].axis;
                for (const unsigned int c : row_kinds.curl)
                  {
                    const unsigned int r        = layout[c].axis;
                    double             curl_row = 0.;
                    for (unsigned int j = 0; j < dim; ++j)
                      curl_row += 0.5 * levi_civita(r, j, k) * gradient[j];
                    if (curl_row != 0.)
                      entries.push_back({particle * n_components + c, dofs[a], curl_row});
                  }
              }
          }
      }

    // Sparsity with the rows of other ranks, sent to their owners; then the matrix.
    const auto  row_partitioner = particles.partitioner(n_components);
    const auto &owned_rows      = row_partitioner->locally_owned_range();
    // The rows as one sorted list: IndexSet::add_index() of unsorted rows one by one inserts into
    // the middle of its ranges, quadratic in the particles (5 s of the set-up for 140 000).
    std::vector<types::global_dof_index> rows;
    rows.reserve(entries.size());
    for (const auto &e : entries)
      rows.push_back(e.row);
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    IndexSet touched_rows(owned_rows.size());
    touched_rows.add_indices(rows.begin(), rows.end());
    touched_rows.add_indices(owned_rows);
    touched_rows.compress();
    DynamicSparsityPattern dsp(owned_rows.size(), dof_handler.n_dofs(), touched_rows);
    for (const auto &e : entries)
      dsp.add(e.row, e.column);
    // An empty region (no particles or no FE unknowns) has no entries to send (and deal.II
    // divides by the number of rows there).
    if (owned_rows.size() > 0 && dof_handler.n_dofs() > 0)
      SparsityTools::distribute_sparsity_pattern(dsp, owned_rows, comm, touched_rows);
    P.reinit(owned_rows, dof_handler.locally_owned_dofs(), dsp, comm);
    // Row by row (one call per entry costs more than the point search).
    std::sort(entries.begin(), entries.end(), [](const Entry &a, const Entry &b) {
      return a.row < b.row || (a.row == b.row && a.column < b.column);
    });
    std::vector<types::global_dof_index> columns;
    std::vector<double>                  values;
    for (std::size_t begin = 0, end = 0; begin < entries.size(); begin = end)
      {
        columns.clear();
        values.clear();
        for (end = begin; end < entries.size() && entries[end].row == entries[begin].row; ++end)
          {
            columns.push_back(entries[end].column);
            values.push_back(entries[end].value);
          }
        P.add(entries[begin].row, columns.size(), columns.data(), values.data());
      }
    P.compress(VectorOperation::add);

    // Slaved rows sum to one (partition of unity, one cell per particle); empty rows are free.
    fe.initialize_vector(fe_buffer);
    particles.reinit_vector(particle_buffer, n_components);
    fe_buffer = 1.;
    P.vmult(particle_buffer, fe_buffer);
    slaved.assign(n_owned, false);
    for (unsigned int i = 0; i < n_owned; ++i)
      {
        const double sum =
          particle_buffer.local_element(std::size_t(i) * n_components + row_kinds.first_value_row);
        if (!(sum == 0. || std::abs(sum - 1.) < 1e-10))
          {
            std::string where;
            for (unsigned int d = 0; d < dim; ++d)
              where += (d > 0 ? ", " : "") + ParameterUtilities::format_number(x[i][d]);
            AssertThrow(false,
                        ExcMessage("The row of the transfer operator of the particle at (" + where +
                                   ") sums to " + std::to_string(sum) +
                                   " instead of 0 or 1: it was located in more than "
                                   "one cell, which happens on several ranks to a "
                                   "particle that lies on a slit of the mesh (faces "
                                   "with nodes of their own, as the notches of "
                                   "meshes/kalthoff_winkler_2d.msh); choose "
                                   "<Discretization/Lattice spacing> so that no "
                                   "particle lies on a slit."));
          }
        slaved[i] = (sum != 0.);
      }
    n_slaved =
      Utilities::MPI::sum<types::global_dof_index>(std::count(slaved.begin(), slaved.end(), true),
                                                   comm);
  }

  template <int dim>
  void
  TransferOperator<dim>::interpolate(const FEVector &U, ParticleVector &u_particles) const
  {
    // No slaved particle anywhere (an empty FE region): nothing to interpolate.
    if (n_slaved == 0)
      return;
    P.vmult(particle_buffer, U);
    for (unsigned int i = 0; i < slaved.size(); ++i)
      if (slaved[i])
        for (unsigned int c = 0; c < n_components; ++c)
          u_particles.local_element(i * n_components + c) =
            particle_buffer.local_element(i * n_components + c);
  }

  template <int dim>
  void
  TransferOperator<dim>::add_transpose(const ParticleVector &f, FEVector &F) const
  {
    // P^T f = 0 without slaved particles (the rows of free particles are empty).
    if (n_slaved == 0)
      return;
    P.Tvmult(fe_buffer, f);
    F += fe_buffer;
  }

  template <int dim>
  bool
  TransferOperator<dim>::is_slaved(const unsigned int i) const
  {
    return slaved[i];
  }

  template <int dim>
  const std::vector<bool> &
  TransferOperator<dim>::slaved_particles() const
  {
    return slaved;
  }

  template <int dim>
  types::global_dof_index
  TransferOperator<dim>::n_global_slaved() const
  {
    return n_slaved;
  }

  template <int dim>
  const SparseMatrix &
  TransferOperator<dim>::matrix() const
  {
    return P;
  }

  template <int dim>
  unsigned int
  TransferOperator<dim>::n_point_components() const
  {
    return n_components;
  }

  template class TransferOperator<2>;
  template class TransferOperator<3>;
} // namespace perideal
