// ---------------------------------------------------------------------
// PeriDeal: distributed particles on a lattice and their bonds.
// ---------------------------------------------------------------------
#ifndef perideal_pd_particle_system_h
#define perideal_pd_particle_system_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/distributed/tria.h>

#include <perideal/base/linear_algebra.h>
#include <perideal/pd/lattice.h>
#include <perideal/pd/pre_crack.h>

#include <algorithm>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <vector>

namespace perideal
{
  /**
   * @brief How the volume of a neighbour that the horizon cuts is counted (seed note 000,
   * sec. 4.3; Seleson 2014, Comput. Methods Appl. Mech. Engrg. 282).
   *
   * - none: every neighbour with |xi| <= delta counts fully;
   * - book: neighbours with |xi| <= delta, scaled by beta = (delta + dx/2 - |xi|)/dx beyond
   *   delta - dx/2 (Madenci & Oterkus 2014 codes; beta falls to 1/2 at delta, so a full family
   *   holds 86 % of the horizon volume at delta = 3.015 dx: use with surface correction, which
   *   rescales it);
   * - geometric: the same beta, with the family extended to |xi| < delta + dx/2, the cells that the
   *   horizon cuts; the family volume then matches the horizon to about 1 %.
   */
  enum class PartialVolume
  {
    none,
    book,
    geometric
  };

  /**
   * @brief The partial-volume factor chi of a bond as a function of its length (PartialVolume):
   * 1 inside delta - dx/2 (and everywhere for PartialVolume::none), (delta + dx/2 - r)/dx beyond.
   */
  struct PartialVolumeLaw
  {
    /// The rule.
    PartialVolume rule = PartialVolume::none;
    /// Horizon delta and lattice spacing dx [m].
    ///@{
    double horizon = 0.;
    double spacing = 1.;
    ///@}

    /**
     * @brief The factor of a bond of length @p r.
     */
    double
    operator()(const double r) const
    {
      return (rule == PartialVolume::none || r <= horizon - 0.5 * spacing) ?
               1. :
               (horizon + 0.5 * spacing - r) / spacing;
    }
  };

  /**
   * @brief The bonds of the locally owned particles in compressed-row form (structure of arrays).
   *
   * Row i (a locally owned particle) lists each bond once: to owned particles j > i, and to every
   * ghost particle within the horizon. A loop over rows therefore visits each bond between two
   * owned particles once (apply the force to both ends) and each bond to a ghost once on each of
   * the two ranks (apply the force to the owned end only). Use neighbor_is_owned() to tell.
   */
  struct BondList
  {
    /// Row pointers, size n_owned + 1.
    std::vector<unsigned int> row_start;
    /// Local index of the other end (owned < n_owned <= ghost).
    std::vector<unsigned int> neighbor;
    /// Reference bond length |xi| [m].
    std::vector<double> length;
    /// Surface-correction factor (1 until a model computes it). Set-up data of the models:
    /// one that keeps the factors in its own coefficients frees it after its initialize()
    /// (BondBased: empty then, BondBased::pair_coefficient()).
    std::vector<double> surface_factor;
    /// The partial-volume factor chi of the bonds, a function of their length (not stored).
    PartialVolumeLaw partial_volume;
    /// 1 while the bond carries force, 0 once broken (pre-cracks start at 0), 2 for a bond that
    /// never breaks (it touches a no-fail region). Read it freely; outside the force kernels
    /// (which keep their lane copy in step themselves, BondBlocks::break_lanes()) change it only
    /// through break_bond(), set_states() and set_state_of(), which bump revision().
    std::vector<std::uint8_t> intact;
    /// The bonds the force kernels broke (BondBlocks::break_lanes()) since the list was last
    /// cleared: MaterialModel::released_energy() takes their energy and clears it.
    std::vector<unsigned int> newly_broken;

    /**
     * @brief Partial-volume factor chi of bond @p b (1 inside delta - dx/2, then (delta + dx/2 -
     * |xi|)/dx), computed from its length.
     */
    double
    volume_factor(const std::size_t b) const
    {
      return partial_volume(length[b]);
    }

    /**
     * @brief The row of bond @p b: the owned particle whose row lists it (a binary search).
     */
    unsigned int
    row_of(const std::size_t b) const
    {
      return std::upper_bound(row_start.begin(), row_start.end(), b) - row_start.begin() - 1;
    }

    /// Number of locally stored bonds.
    std::size_t
    size() const
    {
      return neighbor.size();
    }

    /**
     * @brief The number of changes of @p intact made outside the force kernels so far: the
     * kernels' copy of the states (BondBlocks::sync_state()) re-reads them when it changed.
     */
    std::uint64_t
    revision() const
    {
      return n_changes;
    }

    /**
     * @brief Break bond @p b (state 0) outside the force kernels; with @p released, list it in
     * @p newly_broken, so that MaterialModel::released_energy() takes its energy.
     */
    void
    break_bond(const unsigned int b, const bool released = false)
    {
      intact[b] = 0;
      if (released)
        newly_broken.push_back(b);
      ++n_changes;
    }

    /**
     * @brief Replace every bond's state by @p states (a copy of @p intact kept before, or all
     * intact).
     */
    void
    set_states(const std::vector<std::uint8_t> &states)
    {
      intact = states;
      ++n_changes;
    }

    /**
     * @brief Give the bonds @p bond_indices the state @p state.
     */
    void
    set_state_of(const std::vector<unsigned int> &bond_indices, const std::uint8_t state)
    {
      for (const unsigned int b : bond_indices)
        intact[b] = state;
      ++n_changes;
    }

  private:
    /// Incremented by every function above that changes @p intact.
    std::uint64_t n_changes = 0;
  };


  /**
   * @brief Particles on a lattice, distributed over MPI ranks, with ghosts and bonds.
   *
   * Particles sit at the centres of the cells of a lattice of spacing dx covering the bounding
   * box of the body, or, with Settings::perturbation > 0, at a random point of the inner part of
   * their cell (the cell's centre decides whether it belongs to the body; the offset is a hash of
   * the seed and the lattice indices, so it does not depend on the number of ranks). Ownership
   * follows a distributed background mesh (parallel::distributed::Triangulation) whose cells are at
   * least a horizon wide, so that all neighbours of an owned particle lie in owned or ghost cells.
   * Global indices are contiguous per rank; the owners' indices of ghost particles are brought by
   * GridTools::exchange_cell_data_to_ghosts, and field values of ghost particles by the ghost
   * exchange of ParticleVector. The result does not depend on the number of ranks.
   */
  template <int dim>
  class ParticleSystem
  {
  public:
    /// The parameters of the lattice (subsection <Discretization>).
    struct Settings
    {
      /// Lattice spacing dx [m].
      double spacing = 0.;
      /// Horizon delta [m].
      double horizon = 0.;
      /// Thickness of a 2D body [m] (particle volume dx^2 h); ignored in 3D.
      double thickness = 1.;
      /// How neighbours that the horizon cuts count.
      PartialVolume partial_volume = PartialVolume::book;
      /// Random perturbation of the lattice: each particle is moved from its cell centre by an
      /// offset uniform in [-epsilon dx/2, epsilon dx/2] per coordinate (0 <= epsilon <= 1/2).
      double perturbation = 0.;
      /// Seed of the perturbation's offsets (a function of the seed and the lattice indices).
      unsigned int perturbation_seed = 1;
    };

    /**
     * @brief An empty system on communicator @p comm.
     */
    explicit ParticleSystem(const MPI_Comm comm);

    /**
     * @brief Fill the lattice points of @p box that satisfy @p in_body, distribute them, import
     * ghosts and find the bonds; bonds that cross a pre-crack start broken, bonds with an end
     * in @p no_fail (if given) never break. @p counted (if given) is called on every rank with an
     * estimate of the number of particles (from a sample of the box's lattice points) before
     * anything per particle or per background bin takes memory (ParticleRegion warns there when
     * the bonds would not fit).
     */
    void
    generate(const Settings                                        &settings,
             const dealii::BoundingBox<dim>                        &box,
             const std::function<bool(const dealii::Point<dim> &)> &in_body,
             const std::vector<PreCrack<dim>>                      &pre_cracks,
             const std::function<bool(const dealii::Point<dim> &)> &no_fail = {},
             const std::function<void(std::uint64_t)>              &counted = {});

    /**
     * @brief Whether generate() weights the partition of new background bins by the particles
     * each holds (the default: balanced particles where the body fills a small part of its
     * lattice box). Kept bins keep their partition at a regeneration, so a region that grows
     * from a small start (the adaptive PD region) wants false: weights of the first region would
     * crowd the grown ones on the ranks of the empty bins.
     */
    void
    set_balance_by_particles(const bool balance);

    /// Communicator.
    MPI_Comm
    get_communicator() const;
    /// Number of locally owned particles.
    unsigned int
    n_owned() const;
    /// Number of owned plus ghost particles.
    unsigned int
    n_local() const;
    /// Number of particles on all ranks.
    dealii::types::global_dof_index
    n_global() const;
    /// Number of bonds on all ranks, each counted once.
    std::uint64_t
    n_global_bonds() const;
    /// Reference positions of owned then ghost particles.
    const std::vector<dealii::Point<dim>> &
    positions() const;
    /// Volumes of owned then ghost particles [m^3].
    const std::vector<double> &
    volumes() const;
    /// Energy weight of the owned then ghost particles: 1, or beta_i in the overlap of a blended
    /// FE-PD coupling (the model's energy is sum_i beta_i W_i V_i).
    const std::vector<double> &
    energy_weights() const;
    /**
     * @brief Weight the particles' energies by @p weight(x) (before the model is initialized):
     * sets energy_weights(); a bond's weight is bond_energy_weight().
     */
    void
    set_energy_weights(const std::function<double(const dealii::Point<dim> &)> &weight);
    /**
     * @brief The energy weight of the bond between local particles @p i and @p j: 1, or
     * (beta_i + beta_j) / 2 in the overlap of a blended FE-PD coupling (bond-based models scale
     * the bond modulus by it).
     */
    double
    bond_energy_weight(const unsigned int i, const unsigned int j) const
    {
      return 0.5 * (particle_energy_weights[i] + particle_energy_weights[j]);
    }
    /// Global index of local particle @p i.
    dealii::types::global_dof_index
    global_index(const unsigned int i) const;
    /**
     * @brief The index of local particle @p i (owned or ghost) in an order that does not depend
     * on the number of ranks: the background cells in the order of their index, the lattice
     * order within a cell. The global indices follow p4est's partition of the cells and differ
     * between rank counts; a checkpoint stores particles by this index.
     */
    std::uint64_t
    invariant_index(const unsigned int i) const;
    /// The bonds.
    const BondList &
    bonds() const;
    /// The bonds, for models that set per-bond factors and for damage.
    BondList &
    bonds();
    /// The lattice of the particles, over the box of generate().
    const Lattice<dim> &
    lattice() const;
    /// The largest bond length: delta, or delta + dx/2 for PartialVolume::geometric.
    double
    search_radius() const;
    /**
     * @brief The partial-volume factor of a bond of length @p r: 1 inside delta - dx/2 (and
     * everywhere for PartialVolume::none), (delta + dx/2 - r)/dx beyond.
     */
    double
    partial_volume_factor(const double r) const;
    /**
     * @brief The family of an interior particle of the lattice, whatever the body: the lattice
     * vectors @p xi of the bonds the search finds and their weights chi V_j (partial-volume
     * factor times dx^dim, times the thickness in 2D). For lattice calibrations.
     */
    void
    lattice_family(std::vector<dealii::Tensor<1, dim>> &xi, std::vector<double> &weight) const;
    /// The settings used by generate().
    const Settings &
    settings() const;

    /**
     * @brief The resident memory of this process [kiB] when generate() was first called: the
     * program without its particles, against which the run summary states the peak memory per
     * bond and per particle.
     */
    std::uint64_t
    resident_memory_before() const;

    /**
     * @brief The partitioner of a field with @p n_components values per particle (cached).
     */
    std::shared_ptr<const Partitioner>
    partitioner(const unsigned int n_components) const;

    /**
     * @brief Reference coordinates of the local particles as one array, x[i * dim + d], for
     * force loops (bond vectors are formed as (x_j - x_i) + (u_j - u_i): adding u to x first
     * would lose the digits of small displacements).
     */
    const std::vector<double> &
    coordinates() const;

    /**
     * @brief Size @p v for @p n_components values per particle, with ghosts, zeroed.
     */
    void
    reinit_vector(ParticleVector &v, const unsigned int n_components) const;

    /**
     * @brief Whether the bond @p b joins two owned particles, i.e. the loop visits it once for
     * both ends.
     */
    bool
    neighbor_is_owned(const std::size_t b) const
    {
      return bond_list.neighbor[b] < n_owned_particles;
    }

    /**
     * @brief Weight of bond @p b in sums over unique bonds: 1 for owned pairs, 1/2 for bonds to
     * ghosts (seen on two ranks).
     */
    double
    bond_share(const std::size_t b) const
    {
      return neighbor_is_owned(b) ? 1.0 : 0.5;
    }

  private:
    MPI_Comm                        communicator;
    Settings                        parameters;
    unsigned int                    n_owned_particles  = 0;
    dealii::types::global_dof_index n_global_particles = 0;
    /// set_balance_by_particles().
    bool balance_by_particles = true;
    /// The background bins (one cell per bin, at least a bond long) and the box and bin counts
    /// they were made for.
    std::unique_ptr<dealii::parallel::distributed::Triangulation<dim>> background_bins;
    std::vector<double>                                                background_key;
    std::vector<dealii::Point<dim>>                                    reference_positions;
    std::vector<double>                                                flat_coordinates;
    std::vector<double>                                                particle_volumes;
    std::vector<double>                                                particle_energy_weights;
    std::vector<dealii::types::global_dof_index>                       global_indices;
    std::vector<std::uint64_t>                                         invariant_indices;
    BondList                                                           bond_list;
    Lattice<dim>                                                       grid;
    mutable std::map<unsigned int, std::shared_ptr<const Partitioner>> partitioners;
    /// resident_memory_before() [kiB].
    std::uint64_t resident_before = 0;

    /// The largest bond length the search accepts (search_radius() with a round-off margin).
    double
    bond_reach() const;

    void
    find_bonds(const std::vector<PreCrack<dim>>                      &pre_cracks,
               const std::function<bool(const dealii::Point<dim> &)> &no_fail);
  };
} // namespace perideal

#endif
