// ---------------------------------------------------------------------
// PeriDeal: lattice bond blocks and SIMD building blocks of the force kernels.
// ---------------------------------------------------------------------
#ifndef perideal_pd_bond_blocks_h
#define perideal_pd_bond_blocks_h

#include <deal.II/base/aligned_vector.h>

#include <perideal/pd/particle_system.h>

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include <experimental/simd>

namespace perideal
{
  /**
   * @brief SIMD vectors of the force kernels (std::experimental::simd of the width the kernels
   * are compiled for: 8 doubles with AVX-512, 4 with AVX2, 2 with SSE2).
   */
  namespace bond_simd
  {
    namespace stdx = std::experimental;

    /// A SIMD vector of doubles.
    using Vector = stdx::native_simd<double>;
    /// A lane mask.
    using Mask = Vector::mask_type;
    /// Number of lanes.
    constexpr unsigned int width = Vector::size();

    /**
     * @brief 1/sqrt(@p a) for @p a of order one (a squared bond length over the squared
     * reference length): a single-precision seed refined by two Newton steps, accurate to about
     * one unit in the last place of a double. Square roots and divisions of doubles are the slow
     * operations of the vector units; this uses multiplications only (after the seed). Valid for
     * 1e-30 < @p a < 1e30, i.e. bonds not stretched or shortened by 15 orders of magnitude.
     */
    inline Vector
    inverse_sqrt(const Vector &a)
    {
      // The floats in the same lanes with a native ABI (a fixed_size_simd<float, width> is
      // kept on the stack: two stores per call).
      using Single        = stdx::rebind_simd_t<float, Vector>;
      const Single single = stdx::static_simd_cast<Single>(a);
      Vector       r      = stdx::static_simd_cast<Vector>(Single(1.f) / stdx::sqrt(single));
      const Vector half_a = 0.5 * a;
      r                   = r * (1.5 - half_a * r * r);
      r                   = r * (1.5 - half_a * r * r);
      return r;
    }

    /**
     * @brief The lanes of a block whose bond carries force (state != 0).
     */
    inline Mask
    intact_lanes(const std::uint8_t *state)
    {
      return stdx::static_simd_cast<Vector>(
               stdx::fixed_size_simd<std::uint8_t, width>(state, stdx::element_aligned)) != 0.;
    }
  } // namespace bond_simd

  /**
   * @brief The bonds of a ParticleSystem rearranged for vectorized force loops: SIMD-wide
   * blocks of bonds along the lattice.
   *
   * The particles live on a lattice. The kernels number the local particles (owned and ghost)
   * lexicographically by their lattice coordinates ("kernel order"), so that lattice lines are
   * runs of consecutive indices, and keep per-particle fields component-wise in that order
   * (gather(), scatter_owned()). A *group* is a run of width particles a0 ... a0 + width
   * - 1 (a0 a multiple of width); a *block* of the group holds, in lane l, the bond of particle
   * a0 + l along one lattice vector (its *bond class*), with the other ends at a0 + offset + l,
   * offset > 0: a bond sits at its end of lower kernel index, owned or ghost, so a lattice
   * vector and its reverse are one class and the lanes fill (97 % on the 41^3 benchmark lattice,
   * 84 % when bonds sat at their owned end).
   * So every load and store of a block is a contiguous vector: the particle's side once per
   * group, the neighbours' side once per block, and the per-lane arrays of the block. Lanes
   * without a bond (line ends, ghosts, other offsets) have state 0 and coefficient 0: they
   * produce zero forces and need no masks. The reference bond vector is the class's lattice
   * vector, shared by the block; it is not stored per bond. On a perturbed lattice
   * (ParticleSystem::Settings::perturbation > 0) the particles keep the kernel order and the
   * classes of their lattice points, but every bond has its own reference vector: the blocks
   * then hold the particles' reference positions in kernel order (a vector of the bond is
   * the difference of two contiguous loads, like the displacements) and the inverse length per
   * lane (lane_bonds(); has_lane_bonds()), and for_each_bond_block() hands the pair laws a
   * LaneBond instead of the class.
   *
   * The class depends on the SIMD width: it is compiled, like the kernels that use it, with
   * the kernel options of source/pd/CMakeLists.txt.
   *
   * Each bond of the BondList is in exactly one lane (to_lanes() copies per-bond values). The
   * lane states are the kernels' copy of BondList::intact: a kernel that breaks a bond writes
   * both (break_lanes()), and sync_state() re-reads BondList::intact when its revision has
   * changed.
   */
  template <int dim>
  class BondBlocks
  {
  public:
    /// The lanes of a block: the SIMD width of the kernels.
    static constexpr unsigned int width = bond_simd::width;

    /// A kernel-order field or per-lane array (64-byte aligned, so that the particle side of a
    /// block and the lane arrays are aligned vector loads).
    using Array = dealii::AlignedVector<double>;

    /// A lattice vector of the family: its components, length and inverse length.
    struct BondClass
    {
      /// The lattice vector [m], its length [m] and inverse length [1/m].
      ///@{
      std::array<double, dim> xi;
      double                  length;
      double                  inverse_length;
      ///@}
    };

    /// The reference bonds of a block's lanes on a perturbed lattice: the bond vector from the
    /// lane's particle to its neighbour, its length and inverse length, per lane (empty lanes
    /// hold the class's).
    struct LaneBond
    {
      /// The bond vector [m], its length [m] and inverse length [1/m] per lane.
      ///@{
      bond_simd::Vector xi[dim];
      bond_simd::Vector length;
      bond_simd::Vector inverse_length;
      ///@}
    };

    /// The reference bonds on a perturbed lattice, read by lane_bonds(): the dim components of
    /// the particles' reference positions in kernel order (xi of a lane = position of its
    /// neighbour - position of its particle) and the per-lane inverse lengths; the length is
    /// |xi|^2 / |xi|.
    using LaneBondArrays = std::array<const double *, dim + 1>;

    /// The blocks of one group of width consecutive particles (kernel order).
    struct Group
    {
      /// Kernel index of lane 0.
      unsigned int first_particle;
      /// Blocks [first_block, next group's first_block).
      unsigned int first_block;
    };

    /// One SIMD-wide block of bonds along one lattice vector.
    struct Block
    {
      /// Kernel index of the neighbour in lane l: first_particle + offset + l.
      int offset;
      /// Index into classes().
      unsigned int bond_class;
    };

    /**
     * @brief Build the blocks of the bonds of @p particles (reference configuration); copies
     * the bond states.
     */
    void
    reinit(const ParticleSystem<dim> &particles);

    /// The groups; the last entry is a sentinel (its first_block is n_blocks()).
    const std::vector<Group> &
    groups() const
    {
      return group_list;
    }

    /// The blocks, grouped.
    const std::vector<Block> &
    blocks() const
    {
      return block_list;
    }

    /// The bond classes.
    const std::vector<BondClass> &
    classes() const
    {
      return class_list;
    }

    /// Whether the bonds have their own reference vectors (a perturbed lattice).
    bool
    has_lane_bonds() const
    {
      return !lane_inverse_length.empty();
    }

    /// The kernel-order reference positions and the per-lane inverse lengths of the reference
    /// bonds (has_lane_bonds() only).
    LaneBondArrays
    lane_bond_arrays() const
    {
      LaneBondArrays arrays;
      for (unsigned int d = 0; d < dim; ++d)
        arrays[d] = reference_position.data() + std::size_t(d) * field_stride + width;
      arrays[dim] = lane_inverse_length.data();
      return arrays;
    }

    /// The reference bonds of the lanes from @p first_lane on, whose particles are at
    /// @p x_a (their reference positions, dim components, loaded once per group from
    /// @p arrays, lane_bond_arrays()) and whose neighbours start at kernel index
    /// @p neighbour.
    static LaneBond
    lane_bonds(const LaneBondArrays    &arrays,
               const bond_simd::Vector *x_a,
               const std::size_t        first_lane,
               const std::size_t        neighbour)
    {
      namespace stdx = std::experimental;
      LaneBond bond;
      bond.length = 0.;
      for (unsigned int d = 0; d < dim; ++d)
        {
          const bond_simd::Vector x_b(arrays[d] + neighbour, stdx::element_aligned);
          bond.xi[d] = x_b - x_a[d];
          bond.length += bond.xi[d] * bond.xi[d];
        }
      bond.inverse_length.copy_from(arrays[dim] + first_lane, stdx::element_aligned);
      bond.length *= bond.inverse_length;
      return bond;
    }

    /**
     * @brief @p per_lane[q * width + l] = @p per_bond[bond_index(q, l)], 0 for empty lanes.
     */
    void
    to_lanes(const std::vector<double> &per_bond, Array &per_lane) const;

    /**
     * @brief @p per_lane[q * width + l] = @p value(i, b) for the lane's bond b, of row i of
     * @p bonds (the bond list of reinit()), 0 for empty lanes: per-lane values of a model that
     * keeps none per bond.
     */
    void
    to_lanes(const BondList                                                     &bonds,
             const std::function<double(const unsigned int, const std::size_t)> &value,
             Array                                                              &per_lane) const;

    /**
     * @brief The lane of bond @p b of row @p i of @p bonds (the bond list of reinit()): a
     * search among the blocks of the group of its end of lower kernel index.
     */
    std::size_t
    lane_of(const BondList &bonds, const unsigned int i, const std::size_t b) const;

    /**
     * @brief The lanes of all bonds at once: @p lane[b] = lane_of() of bond b (the lanes store
     * their bond: one pass over them), for the @p n_bonds bonds of the bond list of reinit()
     * (4 B per bond, less than a copy of a per-lane value of doubles).
     */
    void
    lanes_of_bonds(const std::size_t n_bonds, std::vector<unsigned int> &lane) const;

    /**
     * @brief The inverse of to_lanes(): @p per_bond[bond_index(q, l)] = @p per_lane[q * width +
     * l] (per-lane histories back in bond order, for the linearization and checkpoints);
     * @p per_bond is sized like the bond list.
     */
    void
    from_lanes(const Array &per_lane, std::vector<double> &per_bond) const;

    /**
     * @brief Copy BondList::intact into the lane states if it changed since the last copy.
     */
    void
    sync_state(const BondList &bonds);

    /// The lane states, width per block.
    std::uint8_t *
    state()
    {
      return lane_state.data();
    }

    /**
     * @brief Break the bonds of block @p q whose @p stretch exceeds @p critical_stretch and that
     * are breakable (state 1), in the lanes and in @p bonds, and list them in
     * BondList::newly_broken. Bonds that never break (state 2) are left alone. The rare path of
     * the kernels: they re-read the lane states afterwards.
     */
    void
    break_lanes(const bond_simd::Vector &stretch,
                const double             critical_stretch,
                const unsigned int       q,
                BondList                &bonds);

    /**
     * @brief Size the @p n_components kernel-order arrays of @p field (with the padding the
     * blocks read and write), zeroed.
     */
    void
    reinit_field(Array &field, const unsigned int n_components) const;

    /// Component @p d of a kernel-order field sized by reinit_field(): index by kernel index.
    double *
    component(Array &field, const unsigned int d) const;

    /**
     * @brief The @p n_components values per local particle of @p values (particle order,
     * values[i * n_components + d], owned then ghost) into the kernel-order @p field.
     */
    void
    gather(const double *values, const unsigned int n_components, Array &field) const;

    /**
     * @brief The owned particles' entries of the kernel-order @p field, each divided by the
     * particle's entry of @p divisor, into @p values (particle order).
     */
    void
    scatter_owned(Array             &field,
                  const unsigned int n_components,
                  const double      *divisor,
                  double            *values) const;

  private:
    unsigned int n_owned = 0, n_local = 0;
    std::size_t  field_stride = 0;
    /// Kernel slots: the largest kernel index plus one (the windows leave empty slots).
    std::size_t               n_slots = 0;
    std::vector<unsigned int> kernel_index;
    std::vector<Group>        group_list;
    std::vector<Block>        block_list;
    std::vector<BondClass>    class_list;
    std::vector<unsigned int> lane_bond;
    std::vector<std::uint8_t> lane_state;
    /// On a perturbed lattice: the local particles' reference positions, a kernel-order field
    /// of dim components (padding entries beyond the body, one spacing apart, so that no lane's
    /// vector is zero), and the inverse lengths of the lanes' reference bonds (empty lanes: the
    /// class's); both empty on a regular lattice.
    Array         reference_position, lane_inverse_length;
    std::uint64_t synced_revision = 0;
  };
} // namespace perideal

#endif
