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
#include <perideal/base/tie_break.h>
#include <perideal/coupling/transfer_operator.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <tuple>

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

    /**
     * @brief Where the point at @p reference of @p cell lies: -1 strictly inside the cell (no
     * reference coordinate within @p tolerance of 0 or 1), 1 on the cell's boundary and inside
     * the cell once moved by a small step along tie_break_direction() (the direction that
     * PreCrack::cuts() uses for a bond's end on a crack's plane), 0 on the boundary and
     * outside after that step (or moving along the boundary).
     */
    template <int dim>
    int
    face_rule_side(const typename Triangulation<dim>::active_cell_iterator &cell,
                   const Point<dim>                                        &reference,
                   const double                                             tolerance)
    {
      bool on_boundary = false;
      for (unsigned int d = 0; d < dim; ++d)
        on_boundary = on_boundary || reference[d] < tolerance || reference[d] > 1. - tolerance;
      if (!on_boundary)
        return -1;
      // The step in reference coordinates, J^-1 v, with the Jacobian J of the d-linear mapping.
      Tensor<2, dim> jacobian;
      for (const unsigned int v : cell->vertex_indices())
        jacobian +=
          outer_product(cell->vertex(v),
                        GeometryInfo<dim>::d_linear_shape_function_gradient(reference, v));
      const Tensor<1, dim> step = invert(jacobian) * tie_break_direction<dim>();
      for (unsigned int d = 0; d < dim; ++d)
        if ((reference[d] < tolerance && !(step[d] > 0.)) ||
            (reference[d] > 1. - tolerance && !(step[d] < 0.)))
          return 0;
      return 1;
    }

    /**
     * @brief A locally owned cell that holds a particle (within the search's tolerance): the
     * cell, the particle's rank and index there, its reference coordinates in the cell and its
     * position.
     */
    template <int dim>
    struct Candidate
    {
      /// The cell.
      typename Triangulation<dim>::active_cell_iterator cell;
      /// The rank that owns the particle.
      unsigned int rank;
      /// The particle's index among that rank's owned particles.
      unsigned int local;
      /// Its reference coordinates in the cell.
      Point<dim> reference;
      /// Its position.
      Point<dim> real;
    };

    /**
     * @brief Every locally owned cell of every rank that holds one of @p points (this rank's
     * particles; those @p to_locate does not mark are not searched), within @p tolerance in
     * reference coordinates: each point goes to the ranks whose @p global_boxes hold it, and
     * there every owned cell whose bounding box touches it is tried. deal.II's search
     * (GridTools::internal::distributed_compute_point_locations) finds one cell and then the
     * cells that share a vertex with it; across a slit (coincident faces with nodes of their
     * own) the cells share no vertex, so which cells it found for a particle on a slit depended
     * on where the search started, and that on the partition. Returns the candidates held by
     * this rank's cells.
     */
    template <int dim>
    std::vector<Candidate<dim>>
    locate_candidates(const GridTools::Cache<dim>                      &cache,
                      const std::vector<Point<dim>>                    &points,
                      const std::vector<bool>                          &to_locate,
                      const std::vector<std::vector<BoundingBox<dim>>> &global_boxes,
                      const double                                      tolerance,
                      const MPI_Comm                                    comm)
    {
      // To each rank whose boxes hold a point: the point's index and coordinates.
      std::map<unsigned int, std::vector<double>> requests;
      for (unsigned int i = 0; i < points.size(); ++i)
        if (to_locate.empty() || to_locate[i])
          for (unsigned int r = 0; r < global_boxes.size(); ++r)
            for (const auto &box : global_boxes[r])
              if (box.point_inside(points[i], 1e-10))
                {
                  auto &request = requests[r];
                  request.push_back(i);
                  for (unsigned int d = 0; d < dim; ++d)
                    request.push_back(points[i][d]);
                  break;
                }
      const auto                  received = Utilities::MPI::some_to_some(comm, requests);
      const auto                 &tree     = cache.get_locally_owned_cell_bounding_boxes_rtree();
      std::vector<Candidate<dim>> candidates;
      for (const auto &[rank, request] : received)
        for (std::size_t k = 0; k < request.size(); k += dim + 1)
          {
            Point<dim> p, low, high;
            for (unsigned int d = 0; d < dim; ++d)
              p[d] = request[k + 1 + d];
            // The cells' boxes that touch p, widened by a length far below any cell's size and
            // far above the round-off of a coordinate (the reference check below decides).
            const double widen = 1e-10 * (1. + p.norm());
            for (unsigned int d = 0; d < dim; ++d)
              {
                low[d]  = p[d] - widen;
                high[d] = p[d] + widen;
              }
            for (auto hit =
                   tree.qbegin(boost::geometry::index::intersects(BoundingBox<dim>({low, high})));
                 hit != tree.qend();
                 ++hit)
              try
                {
                  const auto      &cell = hit->second;
                  const Point<dim> reference =
                    cache.get_mapping().transform_real_to_unit_cell(cell, p);
                  if (GeometryInfo<dim>::is_inside_unit_cell(reference, tolerance))
                    candidates.push_back(
                      {cell, rank, static_cast<unsigned int>(request[k]), reference, p});
                }
              catch (const typename Mapping<dim>::ExcTransformationFailed &)
                {
                  // p is far outside this cell
                }
          }
      return candidates;
    }

    /**
     * @brief The rule that gives each particle to one cell, the same on every partition: of
     * the cells that hold a particle (@p components, from locate_candidates()), a cell that holds
     * it strictly inside keeps it; of cells that hold it on their boundary (on a face, an edge, a
     * vertex, or a slit's face), the one it moves into along tie_break_direction() keeps it, ties
     * (none or several such cells, e.g. a particle on the mesh's boundary) to the least CellId.
     * Decided on the particle's rank from the candidates the cells' ranks send (two some-to-some
     * messages). Returns whether each component keeps its particle; sets @p found (one entry per
     * owned particle, false on entry) for the particles some cell holds.
     */
    template <int dim>
    std::vector<bool>
    one_cell_per_particle(const std::vector<Candidate<dim>> &components,
                          std::vector<bool>                 &found,
                          const MPI_Comm                     comm)
    {
      // A point this close to a cell's boundary (reference coordinates) is on it, and the
      // direction decides; wider than the search's tolerance (1e-10), so that every cell the
      // search finds a point on the boundary of sees it there.
      constexpr double  tolerance = 1e-8;
      std::vector<bool> keep(components.size(), true);
      // Every candidate, to the particle's rank: its local index, its priority and its cell's
      // CellId, flattened to unsigned ints. (Sending only the candidates on a cell's boundary
      // would miss a cell that holds a point strictly inside while a much smaller neighbour
      // finds it within the search's tolerance.)
      constexpr unsigned int id_size = std::tuple_size<CellId::binary_type>();
      constexpr unsigned int entry   = 2 + id_size;
      std::map<unsigned int, std::vector<unsigned int>> to_owner;
      std::vector<std::array<unsigned int, entry>>      mine(components.size());
      for (std::size_t c = 0; c < components.size(); ++c)
        {
          const auto &[cell, rank, local, reference, real] = components[c];
          // The priority: strictly inside (0) before moving inside (1) before the rest (2).
          const int  side = face_rule_side<dim>(cell, reference, tolerance);
          const auto id   = cell->id().template to_binary<dim>();
          mine[c][0]      = local;
          mine[c][1]      = side < 0 ? 0 : 2 - side;
          std::copy(id.begin(), id.end(), mine[c].begin() + 2);
          auto &message = to_owner[rank];
          message.insert(message.end(), mine[c].begin(), mine[c].end());
        }
      // On each particle's rank: the least candidate (priority, then CellId) of each particle.
      const auto from_cells = Utilities::MPI::some_to_some(comm, to_owner);
      std::map<unsigned int, std::array<unsigned int, entry>> best;
      for (const auto &[sender, message] : from_cells)
        for (std::size_t i = 0; i < message.size(); i += entry)
          {
            std::array<unsigned int, entry> candidate;
            std::copy(message.begin() + i, message.begin() + i + entry, candidate.begin());
            const auto known = best.find(candidate[0]);
            if (known == best.end() || candidate < known->second)
              best[candidate[0]] = candidate;
            found[candidate[0]] = true;
          }
      // Back to every rank that sent a candidate: the winners of its particles.
      std::map<unsigned int, std::vector<unsigned int>> to_cells;
      for (const auto &[sender, message] : from_cells)
        {
          auto &answer = to_cells[sender];
          for (std::size_t i = 0; i < message.size(); i += entry)
            {
              const auto &winner = best[message[i]];
              answer.insert(answer.end(), winner.begin(), winner.end());
            }
        }
      const auto winners = Utilities::MPI::some_to_some(comm, to_cells);
      // The answers come in the order of the candidates sent to that rank.
      std::map<unsigned int, std::size_t> read;
      for (std::size_t c = 0; c < components.size(); ++c)
        {
          const unsigned int rank   = components[c].rank;
          const auto        &answer = winners.at(rank);
          std::size_t       &at     = read[rank];
          keep[c] = std::equal(mine[c].begin(), mine[c].end(), answer.begin() + at);
          at += entry;
        }
      return keep;
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
        // A particle not to be located is not searched: it stays free.
        const std::vector<Point<dim>> points(x.begin(), x.begin() + n_owned);
        const auto                    candidates =
          locate_candidates<dim>(cache, points, located_particles, global_boxes, 1e-10, comm);
        std::vector<bool> found(n_owned, false);
        const auto        keep = one_cell_per_particle<dim>(candidates, found, comm);

        // Every particle must lie in the mesh (checked on all ranks together, so that all throw).
        {
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
        // The shape values at a point by base element (FESystem's shape_value() is its base
        // element's): each computed once, not once per vector component.
        std::vector<std::vector<double>> base_values(fe_element.n_base_elements());
        for (unsigned int b = 0; b < base_values.size(); ++b)
          base_values[b].resize(fe_element.base_element(b).n_dofs_per_cell());
        for (std::size_t c = 0; c < candidates.size(); ++c)
          {
            if (!keep[c])
              continue;
            const auto &[tria_cell, rank, local, reference, real] = candidates[c];
            const typename DoFHandler<dim>::active_cell_iterator cell(&tria,
                                                                      tria_cell->level(),
                                                                      tria_cell->index(),
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
            for (unsigned int b = 0; b < base_values.size(); ++b)
              for (unsigned int k = 0; k < base_values[b].size(); ++k)
                base_values[b][k] = fe_element.base_element(b).shape_value(k, reference);
            for (unsigned int a = 0; a < n_dofs; ++a)
              {
                const unsigned int fe_component = fe_element.system_to_component_index(a).first;
                const auto        &base         = fe_element.system_to_base_index(a);
                const double       value        = base_values[base.first.first][base.second];
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
                        ExcInternalError("The row of the transfer operator of the particle at (" +
                                         where + ") sums to " + std::to_string(sum) +
                                         " instead of 0 or 1: one_cell_per_particle() should "
                                         "have given it to exactly one cell."));
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
