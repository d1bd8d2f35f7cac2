// ---------------------------------------------------------------------
// PeriDeal: distributed particles on a lattice and their bonds.
// ---------------------------------------------------------------------
#include <deal.II/base/index_set.h>
#include <deal.II/base/utilities.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>

#include <perideal/base/cell_list.h>
#include <perideal/base/setup_times.h>
#include <perideal/base/tie_break.h>
#include <perideal/pd/particle_system.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>
#include <random>

namespace perideal
{
  using namespace dealii;

  namespace
  {
    /**
     * @brief The unit normal of a crack's line (2D: the segment turned by +90 degrees) or plane
     * (3D: e1 x e2 of its edges).
     */
    Tensor<1, 2>
    crack_normal(const std::array<Point<2>, 2> &vertices)
    {
      const Tensor<1, 2> s = vertices[1] - vertices[0];
      const Tensor<1, 2> n({-s[1], s[0]});
      return n / n.norm();
    }

    Tensor<1, 3>
    crack_normal(const std::array<Point<3>, 3> &vertices)
    {
      const Tensor<1, 3> n = cross_product_3d(vertices[1] - vertices[0], vertices[2] - vertices[0]);
      return n / n.norm();
    }

    /**
     * @brief How far the point @p p of a crack's line inside the segment lies from its nearer
     * end [m] (negative outside).
     */
    double
    depth_inside(const std::array<Point<2>, 2> &vertices, const Point<2> &p)
    {
      const Tensor<1, 2> s      = vertices[1] - vertices[0];
      const double       length = s.norm();
      const double       along  = (p - vertices[0]) * s / length;
      return std::min(along, length - along);
    }

    /**
     * @brief How far the point @p p of a crack's plane inside the parallelogram lies from its
     * nearest edge [m] (negative outside): with p - a = α e1 + β e2, the edges α = 0 and 1 lie
     * α |e1 x e2| / |e2| and (1 - α) |e1 x e2| / |e2| away, the edges β = 0 and 1 likewise.
     */
    double
    depth_inside(const std::array<Point<3>, 3> &vertices, const Point<3> &p)
    {
      const Tensor<1, 3> e1 = vertices[1] - vertices[0];
      const Tensor<1, 3> e2 = vertices[2] - vertices[0];
      const Tensor<1, 3> q  = p - vertices[0];
      // Solve q = α e1 + β e2 in the least-squares sense (exact in the plane).
      const double g11 = e1 * e1, g12 = e1 * e2, g22 = e2 * e2;
      const double det   = g11 * g22 - g12 * g12;
      const double alpha = ((q * e1) * g22 - (q * e2) * g12) / det;
      const double beta  = ((q * e2) * g11 - (q * e1) * g12) / det;
      const double area  = cross_product_3d(e1, e2).norm();
      const double h1 = area / std::sqrt(g22), h2 = area / std::sqrt(g11);
      return std::min({alpha * h1, (1. - alpha) * h1, beta * h2, (1. - beta) * h2});
    }

    /// The signed distance of @p x from @p crack's line (2D) or plane (3D) [m], positive on the
    /// side of its normal: the distance PreCrack::cuts() takes the sides of a bond's ends from.
    template <int dim>
    double
    plane_distance(const PreCrack<dim> &crack, const Point<dim> &x)
    {
      return (x - crack.vertices[0]) * crack_normal(crack.vertices);
    }
  } // namespace

  template <int dim>
  bool
  PreCrack<dim>::cuts(const Point<dim> &x_given, const Point<dim> &y_given) const
  {
    // The ends in lexicographic order, so that cuts(x, y) and cuts(y, x) compute the same.
    bool swap = false;
    for (unsigned int d = 0; d < dim; ++d)
      if (x_given[d] != y_given[d])
        {
          swap = y_given[d] < x_given[d];
          break;
        }
    const Point<dim> &x = swap ? y_given : x_given;
    const Point<dim> &y = swap ? x_given : y_given;

    const double         tolerance = relative_tolerance * x.distance(y);
    const Tensor<1, dim> n         = crack_normal(vertices);
    const double         dx        = plane_distance(*this, x);
    const double         dy        = plane_distance(*this, y);
    // An end within the tolerance of the plane is on the side tie_break_direction() points
    // into (of +n if the plane holds the direction, a case of measure zero).
    const int  on_plane = tie_break_direction<dim>() * n >= 0. ? 1 : -1;
    const auto side     = [&](const double distance) {
      return std::abs(distance) <= tolerance ? on_plane : (distance > 0. ? 1 : -1);
    };
    if (side(dx) == side(dy))
      return false;
    // The crossing point: an end on the plane, projected onto it, or the intersection.
    const Point<dim> p = std::abs(dx) <= tolerance ? x - dx * n :
                         std::abs(dy) <= tolerance ? y - dy * n :
                                                     x + (dx / (dx - dy)) * (y - x);
    return depth_inside(vertices, p) > tolerance;
  }

  template <int dim>
  ParticleSystem<dim>::ParticleSystem(const MPI_Comm comm)
    : communicator(comm)
  {}

  template <int dim>
  void
  ParticleSystem<dim>::set_balance_by_particles(const bool balance)
  {
    balance_by_particles = balance;
  }

  template <int dim>
  void
  ParticleSystem<dim>::generate(const Settings                                &settings,
                                const BoundingBox<dim>                        &box,
                                const std::function<bool(const Point<dim> &)> &in_body,
                                const std::vector<PreCrack<dim>>              &pre_cracks,
                                const std::function<bool(const Point<dim> &)> &no_fail,
                                const std::function<void(std::uint64_t)>      &counted)
  {
    std::optional<SetupTimes::Scope> lattice_time(SetupStage::lattice);
    if (resident_before == 0)
      {
        Utilities::System::MemoryStats memory;
        Utilities::System::get_memory_stats(memory);
        resident_before = memory.VmRSS;
      }
    parameters = settings;
    partitioners.clear();
    grid = Lattice<dim>(settings.spacing, settings.perturbation, settings.perturbation_seed);
    grid.cover(box);
    const double dx = settings.spacing;
    // Two perturbed particles are at most 2 a sqrt(dim) closer than their lattice points, a the
    // half-width of the offsets, so the bins widen by that much.
    const double bin_minimum = search_radius() + 2. * grid.offset_bound() * std::sqrt(double(dim));

    // The particle count before anything per particle or per bin takes memory, for @p counted
    // (a memory warning): the share of the box's lattice points in the body, from a sample of
    // 20 000 of them drawn alike on every rank (relative standard error sqrt((1 - f) / (f n)):
    // 0.7 % for a body filling half its box, 2 % for a tenth).
    if (counted)
      {
        double n_box = 1.;
        for (unsigned int d = 0; d < dim; ++d)
          n_box *= grid.n_points(d);
        std::mt19937_64              random(1);
        constexpr unsigned int       n_samples = 20000;
        unsigned int                 n_in_body = 0;
        typename Lattice<dim>::Index index;
        for (unsigned int k = 0; n_box > 0. && k < n_samples; ++k)
          {
            for (unsigned int d = 0; d < dim; ++d)
              index[d] =
                std::uniform_int_distribution<unsigned int>(0, grid.n_points(d) - 1)(random);
            n_in_body += in_body(grid.point(index)) ? 1 : 0;
          }
        counted(static_cast<std::uint64_t>(std::llround(n_box * n_in_body / n_samples)));
      }

    // Background bins, identical on every rank.
    std::array<unsigned int, dim> n_bins;
    const Point<dim>              lower = grid.lower_corner(), upper = grid.upper_corner();
    std::array<double, dim>       bin_width;
    for (unsigned int d = 0; d < dim; ++d)
      {
        n_bins[d] = std::max(1, static_cast<int>(std::floor((upper[d] - lower[d]) / bin_minimum)));
        bin_width[d] = (upper[d] - lower[d]) / n_bins[d];
      }
    // first_point[d][k]: first lattice index in bin k along d (bins are monotone in the index).
    std::array<std::vector<unsigned int>, dim> first_point;
    for (unsigned int d = 0; d < dim; ++d)
      {
        first_point[d].assign(n_bins[d] + 1, grid.n_points(d));
        for (unsigned int i = grid.n_points(d); i-- > 0;)
          {
            const unsigned int bin =
              std::min<unsigned int>(n_bins[d] - 1,
                                     static_cast<unsigned int>(((i + 0.5) * dx) / bin_width[d]));
            first_point[d][bin] = i;
          }
        for (unsigned int k = n_bins[d]; k-- > 0;)
          first_point[d][k] = std::min(first_point[d][k], first_point[d][k + 1]);
      }

    // The bins as a distributed mesh, kept while the lattice box and the bins stay (a PD region
    // that grows during a run is generated again; building p4est's forest costs more than the
    // rest of the set-up).
    std::vector<double> bins_key(lower.begin_raw(), lower.end_raw());
    bins_key.insert(bins_key.end(), upper.begin_raw(), upper.end_raw());
    bins_key.insert(bins_key.end(), n_bins.begin(), n_bins.end());
    const bool new_bins = !background_bins || bins_key != background_key;
    if (new_bins)
      {
        background_bins = std::make_unique<parallel::distributed::Triangulation<dim>>(communicator);
        const std::vector<unsigned int> repetitions(n_bins.begin(), n_bins.end());
        GridGenerator::subdivided_hyper_rectangle(*background_bins, repetitions, lower, upper);
        background_key = bins_key;
      }

    // The particles of the bin of one cell, in a fixed order: the lattice points in the body,
    // moved by their offsets.
    const auto points_of_cell = [&](const typename Triangulation<dim>::active_cell_iterator &cell,
                                    std::vector<Point<dim>> &points) {
      points.clear();
      std::array<unsigned int, dim> bin;
      typename Lattice<dim>::Index  index;
      for (unsigned int d = 0; d < dim; ++d)
        bin[d] = static_cast<unsigned int>((cell->center()[d] - lower[d]) / bin_width[d]);
      const unsigned int k_begin = (dim == 3 ? first_point[dim - 1][bin[dim - 1]] : 0);
      const unsigned int k_end   = (dim == 3 ? first_point[dim - 1][bin[dim - 1] + 1] : 1);
      for (unsigned int k = k_begin; k < k_end; ++k)
        for (unsigned int j = first_point[1][bin[1]]; j < first_point[1][bin[1] + 1]; ++j)
          for (unsigned int i = first_point[0][bin[0]]; i < first_point[0][bin[0] + 1]; ++i)
            {
              const unsigned int ijk[3] = {i, j, k};
              for (unsigned int d = 0; d < dim; ++d)
                index[d] = ijk[d];
              if (in_body(grid.point(index)))
                points.push_back(grid.particle(index));
            }
    };

    // p4est balances bins; weighted by the particles each bin holds it balances the particles:
    // a body that fills a small part of its lattice box (the PD region of a coupled run) leaves
    // most bins empty and, unweighted, one rank with several times the mean. The numbering is
    // rank-invariant, so the partition changes no result. Kept bins keep their partition: a
    // grown PD region finds each particle of the old one on its rank (the conversion's carried
    // state, coupled_problem_conversion.cc), and such a region is not weighted
    // (set_balance_by_particles()).
    std::vector<Point<dim>> owned, ghost_candidates, cell_points;
    if (new_bins && balance_by_particles && Utilities::MPI::n_mpi_processes(communicator) > 1)
      {
        std::vector<unsigned int> particles_of_bin(background_bins->n_active_cells(), 0);
        std::uint64_t             n_particles = 0;
        for (const auto &cell : background_bins->active_cell_iterators())
          if (cell->is_locally_owned())
            {
              points_of_cell(cell, cell_points);
              particles_of_bin[cell->active_cell_index()] = cell_points.size();
              n_particles += cell_points.size();
            }
        // (An empty body keeps the unweighted partition.)
        if (Utilities::MPI::sum(n_particles, communicator) > 0)
          {
            const auto weighting = background_bins->signals.weight.connect(
              [&particles_of_bin](const typename Triangulation<dim>::cell_iterator &cell,
                                  const typename Triangulation<dim>::CellStatus) -> unsigned int {
                return particles_of_bin[cell->active_cell_index()];
              });
            background_bins->repartition();
            weighting.disconnect();
          }
      }
    const auto &background = *background_bins;

    // Owned particles, cell by cell.
    std::vector<types::global_dof_index> first_of_cell(background.n_active_cells(), 0);
    std::vector<std::pair<unsigned int, unsigned int>> ghost_range(background.n_active_cells());
    std::vector<std::uint64_t> particles_in_cell(background.n_active_cells(), 0);
    for (const auto &cell : background.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          points_of_cell(cell, cell_points);
          first_of_cell[cell->active_cell_index()]     = owned.size();
          particles_in_cell[cell->active_cell_index()] = cell_points.size();
          owned.insert(owned.end(), cell_points.begin(), cell_points.end());
        }
      else if (cell->is_ghost())
        {
          points_of_cell(cell, cell_points);
          ghost_range[cell->active_cell_index()] = {ghost_candidates.size(), cell_points.size()};
          ghost_candidates.insert(ghost_candidates.end(), cell_points.begin(), cell_points.end());
        }

    // The rank-invariant index: the particles of all cells before a cell (in the order of the
    // cell index, the same on every rank count), plus the lattice order within the cell.
    std::vector<std::uint64_t> invariant_first(particles_in_cell.size());
    const int                  ierr_cells = MPI_Allreduce(particles_in_cell.data(),
                                         invariant_first.data(),
                                         particles_in_cell.size(),
                                         MPI_UINT64_T,
                                         MPI_SUM,
                                         communicator);
    AssertThrowMPI(ierr_cells);
    std::exclusive_scan(invariant_first.begin(),
                        invariant_first.end(),
                        invariant_first.begin(),
                        std::uint64_t(0));
    invariant_indices.assign(owned.size() + ghost_candidates.size(), 0);
    for (const auto &cell : background.active_cell_iterators())
      if (cell->is_locally_owned() || cell->is_ghost())
        {
          const unsigned int c = cell->active_cell_index();
          const std::size_t  start =
            cell->is_locally_owned() ? first_of_cell[c] : owned.size() + ghost_range[c].first;
          const std::size_t count =
            cell->is_locally_owned() ? particles_in_cell[c] : ghost_range[c].second;
          for (std::size_t k = 0; k < count; ++k)
            invariant_indices[start + k] = invariant_first[c] + k;
        }

    n_owned_particles      = owned.size();
    std::uint64_t n_before = 0, n_mine = n_owned_particles;
    const int     ierr = MPI_Exscan(&n_mine, &n_before, 1, MPI_UINT64_T, MPI_SUM, communicator);
    AssertThrowMPI(ierr);
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      n_before = 0;
    const std::uint64_t n_total = Utilities::MPI::sum(n_mine, communicator);
    AssertThrow(n_total * 4 < std::numeric_limits<types::global_dof_index>::max(),
                ExcMessage("Too many particles (" + std::to_string(n_total) +
                           ") for the index type of this deal.II build; use a deal.II configured "
                           "with DEAL_II_WITH_64BIT_INDICES=ON."));
    n_global_particles = n_total;

    for (auto &first : first_of_cell)
      first += n_before;
    std::vector<types::global_dof_index> ghost_candidate_index(ghost_candidates.size());
    GridTools::exchange_cell_data_to_ghosts<types::global_dof_index,
                                            parallel::distributed::Triangulation<dim>>(
      background,
      [&](const typename Triangulation<dim>::active_cell_iterator &cell) {
        return std::optional<types::global_dof_index>(first_of_cell[cell->active_cell_index()]);
      },
      [&](const typename Triangulation<dim>::active_cell_iterator &cell,
          const types::global_dof_index                           &first) {
        const auto range = ghost_range[cell->active_cell_index()];
        for (unsigned int k = 0; k < range.second; ++k)
          ghost_candidate_index[range.first + k] = first + k;
      });

    reference_positions = owned;
    reference_positions.insert(reference_positions.end(),
                               ghost_candidates.begin(),
                               ghost_candidates.end());
    global_indices.resize(reference_positions.size());
    std::iota(global_indices.begin(), global_indices.begin() + n_owned_particles, n_before);
    std::copy(ghost_candidate_index.begin(),
              ghost_candidate_index.end(),
              global_indices.begin() + n_owned_particles);

    lattice_time.reset();
    find_bonds(pre_cracks, no_fail);

    const double volume = (dim == 2 ? dx * dx * settings.thickness : dx * dx * dx);
    particle_volumes.assign(reference_positions.size(), volume);
    particle_energy_weights.assign(reference_positions.size(), 1.);
    flat_coordinates.resize(reference_positions.size() * dim);
    for (std::size_t i = 0; i < reference_positions.size(); ++i)
      for (unsigned int d = 0; d < dim; ++d)
        flat_coordinates[i * dim + d] = reference_positions[i][d];
  }

  template <int dim>
  void
  ParticleSystem<dim>::find_bonds(const std::vector<PreCrack<dim>>              &pre_cracks,
                                  const std::function<bool(const Point<dim> &)> &no_fail)
  {
    const SetupTimes::Scope time(SetupStage::neighbor_search);
    const double            reach = bond_reach();
    const auto              n_all = static_cast<unsigned int>(reference_positions.size());

    // Cell list of all local particles (owned and ghost candidates): O(N).
    CellList<dim> cells;
    cells.reinit(make_array_view(reference_positions), reach);

    // Bonds of owned particles; ghosts are referenced by candidate index for now.
    BondList                  found;
    std::vector<unsigned int> row;
    std::vector<std::uint8_t> ghost_used(n_all - n_owned_particles, 0);
    found.row_start.push_back(0);
    for (unsigned int i = 0; i < n_owned_particles; ++i)
      {
        row.clear();
        const Point<dim> &x = reference_positions[i];
        cells.for_each_near(x, [&](const unsigned int j) {
          if ((j >= n_owned_particles || j > i) && x.distance(reference_positions[j]) <= reach)
            row.push_back(j);
        });
        std::sort(row.begin(), row.end());
        for (const unsigned int j : row)
          {
            found.neighbor.push_back(j);
            if (j >= n_owned_particles)
              ghost_used[j - n_owned_particles] = 1;
          }
        found.row_start.push_back(found.neighbor.size());
      }

    // Keep only the ghosts some bond needs, ordered by global index (the order of the ghost
    // entries of a ParticleVector).
    std::vector<unsigned int> kept;
    for (unsigned int g = 0; g < ghost_used.size(); ++g)
      if (ghost_used[g])
        kept.push_back(n_owned_particles + g);
    std::sort(kept.begin(), kept.end(), [&](const unsigned int a, const unsigned int b) {
      return global_indices[a] < global_indices[b];
    });
    std::vector<unsigned int> new_index(n_all, numbers::invalid_unsigned_int);
    for (unsigned int i = 0; i < n_owned_particles; ++i)
      new_index[i] = i;
    std::vector<Point<dim>>              positions(reference_positions.begin(),
                                      reference_positions.begin() + n_owned_particles);
    std::vector<types::global_dof_index> indices(global_indices.begin(),
                                                 global_indices.begin() + n_owned_particles);
    std::vector<std::uint64_t>           invariant(invariant_indices.begin(),
                                         invariant_indices.begin() + n_owned_particles);
    for (const unsigned int old : kept)
      {
        new_index[old] = positions.size();
        positions.push_back(reference_positions[old]);
        indices.push_back(global_indices[old]);
        invariant.push_back(invariant_indices[old]);
      }
    reference_positions.swap(positions);
    global_indices.swap(indices);
    invariant_indices.swap(invariant);
    for (auto &j : found.neighbor)
      j = new_index[j];

    // A bond whose ends lie on one side of a crack's plane, both farther from it than cuts()'s
    // tolerance (relative_tolerance times the bond's length, at most the reach), is not cut:
    // most bonds, rejected by the particles' distances from the plane, each computed once.
    const double                     far = 2. * PreCrack<dim>::relative_tolerance * reach;
    std::vector<std::vector<double>> distances(pre_cracks.size());
    for (unsigned int c = 0; c < pre_cracks.size(); ++c)
      for (const Point<dim> &x : reference_positions)
        distances[c].push_back(plane_distance(pre_cracks[c], x));
    const auto may_cut = [&](const unsigned int c, const unsigned int i, const unsigned int j) {
      const double di = distances[c][i], dj = distances[c][j];
      return !((di > far && dj > far) || (di < -far && dj < -far));
    };

    // Per-bond data (the neighbours grew row by row: no spare capacity kept).
    found.neighbor.shrink_to_fit();
    const std::size_t n_bonds = found.neighbor.size();
    found.length.resize(n_bonds);
    found.surface_factor.assign(n_bonds, 1.);
    found.intact.assign(n_bonds, 1);
    found.partial_volume = {parameters.partial_volume, parameters.horizon, parameters.spacing};
    for (unsigned int i = 0; i < n_owned_particles; ++i)
      for (unsigned int b = found.row_start[i]; b < found.row_start[i + 1]; ++b)
        {
          const Point<dim> &xj = reference_positions[found.neighbor[b]];
          const double      r  = reference_positions[i].distance(xj);
          found.length[b]      = r;
          for (unsigned int c = 0; c < pre_cracks.size(); ++c)
            if (may_cut(c, i, found.neighbor[b]) && pre_cracks[c].cuts(reference_positions[i], xj))
              found.intact[b] = 0;
          if (found.intact[b] && no_fail && (no_fail(reference_positions[i]) || no_fail(xj)))
            found.intact[b] = 2;
        }
    bond_list = std::move(found);
  }

  template <int dim>
  MPI_Comm
  ParticleSystem<dim>::get_communicator() const
  {
    return communicator;
  }

  template <int dim>
  unsigned int
  ParticleSystem<dim>::n_owned() const
  {
    return n_owned_particles;
  }

  template <int dim>
  unsigned int
  ParticleSystem<dim>::n_local() const
  {
    return reference_positions.size();
  }

  template <int dim>
  types::global_dof_index
  ParticleSystem<dim>::n_global() const
  {
    return n_global_particles;
  }

  template <int dim>
  std::uint64_t
  ParticleSystem<dim>::n_global_bonds() const
  {
    double local = 0.;
    for (std::size_t b = 0; b < bond_list.size(); ++b)
      local += bond_share(b);
    return static_cast<std::uint64_t>(std::llround(Utilities::MPI::sum(local, communicator)));
  }

  template <int dim>
  const std::vector<Point<dim>> &
  ParticleSystem<dim>::positions() const
  {
    return reference_positions;
  }

  template <int dim>
  const std::vector<double> &
  ParticleSystem<dim>::volumes() const
  {
    return particle_volumes;
  }

  template <int dim>
  const std::vector<double> &
  ParticleSystem<dim>::energy_weights() const
  {
    return particle_energy_weights;
  }

  template <int dim>
  void
  ParticleSystem<dim>::set_energy_weights(const std::function<double(const Point<dim> &)> &weight)
  {
    for (std::size_t i = 0; i < reference_positions.size(); ++i)
      particle_energy_weights[i] = weight(reference_positions[i]);
  }

  template <int dim>
  types::global_dof_index
  ParticleSystem<dim>::global_index(const unsigned int i) const
  {
    return global_indices[i];
  }

  template <int dim>
  std::uint64_t
  ParticleSystem<dim>::invariant_index(const unsigned int i) const
  {
    return invariant_indices[i];
  }

  template <int dim>
  const BondList &
  ParticleSystem<dim>::bonds() const
  {
    return bond_list;
  }

  template <int dim>
  BondList &
  ParticleSystem<dim>::bonds()
  {
    return bond_list;
  }

  template <int dim>
  double
  ParticleSystem<dim>::bond_reach() const
  {
    // Bonds of length delta exactly belong to the family; for the geometric partial volume the
    // family ends where the factor reaches zero, at delta + dx/2 (excluded).
    const double delta = parameters.horizon, dx = parameters.spacing;
    return parameters.partial_volume == PartialVolume::geometric ?
             (delta + 0.5 * dx) * (1. - 1e-10) :
             delta * (1. + 1e-10);
  }

  template <int dim>
  double
  ParticleSystem<dim>::partial_volume_factor(const double r) const
  {
    return PartialVolumeLaw{parameters.partial_volume, parameters.horizon, parameters.spacing}(r);
  }

  template <int dim>
  void
  ParticleSystem<dim>::lattice_family(std::vector<Tensor<1, dim>> &xi,
                                      std::vector<double>         &weight) const
  {
    const double dx     = parameters.spacing;
    const double volume = std::pow(dx, dim) * (dim == 2 ? parameters.thickness : 1.);
    xi                  = grid.vectors(bond_reach());
    weight.clear();
    for (const auto &v : xi)
      weight.push_back(partial_volume_factor(v.norm()) * volume);
  }

  template <int dim>
  const Lattice<dim> &
  ParticleSystem<dim>::lattice() const
  {
    return grid;
  }

  template <int dim>
  double
  ParticleSystem<dim>::search_radius() const
  {
    return parameters.partial_volume == PartialVolume::geometric ?
             parameters.horizon + 0.5 * parameters.spacing :
             parameters.horizon;
  }

  template <int dim>
  const typename ParticleSystem<dim>::Settings &
  ParticleSystem<dim>::settings() const
  {
    return parameters;
  }

  template <int dim>
  std::uint64_t
  ParticleSystem<dim>::resident_memory_before() const
  {
    return resident_before;
  }

  template <int dim>
  std::shared_ptr<const Partitioner>
  ParticleSystem<dim>::partitioner(const unsigned int n_components) const
  {
    auto &cached = partitioners[n_components];
    if (!cached)
      {
        IndexSet owned(n_global_particles * n_components),
          ghosts(n_global_particles * n_components);
        if (n_owned_particles > 0)
          owned.add_range(global_indices[0] * n_components,
                          (global_indices[0] + n_owned_particles) * n_components);
        std::vector<types::global_dof_index> ghost_list;
        ghost_list.reserve((n_local() - n_owned_particles) * n_components);
        for (unsigned int i = n_owned_particles; i < n_local(); ++i)
          for (unsigned int c = 0; c < n_components; ++c)
            ghost_list.push_back(global_indices[i] * n_components + c);
        ghosts.add_indices(ghost_list.begin(), ghost_list.end());
        owned.compress();
        ghosts.compress();
        // No particles at all (the empty PD region of a coupled problem): no ghosts either
        // (deal.II's owner lookup divides by the size).
        cached = n_global_particles == 0 ?
                   std::make_shared<const Partitioner>(owned, communicator) :
                   std::make_shared<const Partitioner>(owned, ghosts, communicator);
      }
    return cached;
  }

  template <int dim>
  const std::vector<double> &
  ParticleSystem<dim>::coordinates() const
  {
    return flat_coordinates;
  }

  template <int dim>
  void
  ParticleSystem<dim>::reinit_vector(ParticleVector &v, const unsigned int n_components) const
  {
    v.reinit(partitioner(n_components));
  }

  template struct PreCrack<2>;
  template struct PreCrack<3>;
  template class ParticleSystem<2>;
  template class ParticleSystem<3>;
} // namespace perideal
