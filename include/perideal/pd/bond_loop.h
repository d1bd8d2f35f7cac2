// ---------------------------------------------------------------------
// PeriDeal: the one loop of the force kernels over the lattice bond blocks.
// ---------------------------------------------------------------------
#ifndef perideal_pd_bond_loop_h
#define perideal_pd_bond_loop_h

#include <perideal/pd/bond_blocks.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <type_traits>
#include <utility>
#include <vector>

namespace perideal
{
  /**
   * @brief Where a block's lanes are: what the loop hands a pair law besides the bond class and
   * the relative values.
   */
  struct BondLanes
  {
    /// Index of lane 0 in the per-lane arrays (block index times the SIMD width).
    std::size_t first_lane;
    /// Kernel index of lane 0's neighbour (the other ends are neighbour + l).
    std::size_t neighbour;
    /// The lanes whose bond carries force (intact, after this block's breaking).
    bond_simd::Mask active;
  };

  /// The type of a reference bond's members: double for a BondBlocks::BondClass,
  /// bond_simd::Vector for a BondBlocks::LaneBond.
  template <typename Bond>
  using BondValue = std::decay_t<decltype(std::declval<Bond>().length)>;

  namespace internal
  {
    /// The bond classes a pair law reads (for_each_bond_block()): the blocks' classes, or the
    /// law's own table if it has one (`law.class_table()`).
    template <typename PairLaw, int dim, typename = void>
    struct ClassTable
    {
      /// BondBlocks::classes() of @p blocks.
      static const typename BondBlocks<dim>::BondClass *
      get(const PairLaw &, const BondBlocks<dim> &blocks)
      {
        return blocks.classes().data();
      }
    };

    /// The law's own class table.
    template <typename PairLaw, int dim>
    struct ClassTable<PairLaw,
                      dim,
                      std::void_t<decltype(std::declval<const PairLaw &>().class_table())>>
    {
      /// `law.class_table()` of @p law.
      static auto
      get(const PairLaw &law, const BondBlocks<dim> &)
      {
        return law.class_table();
      }
    };

    /// Whether the `stretch` of a pair law's strain is the square of the measure that breaks a
    /// bond (`PairLaw::squared_stretch`; false if the law does not say).
    template <typename PairLaw, typename = void>
    inline constexpr bool squared_stretch = false;

    /// The law's `squared_stretch`.
    template <typename PairLaw>
    inline constexpr bool
      squared_stretch<PairLaw, std::void_t<decltype(PairLaw::squared_stretch)>> =
        PairLaw::squared_stretch;

    /// for_each_bond_block() with the reference bonds of the classes (@p lane_bonds false) or
    /// of the lanes (true: a perturbed lattice).
    template <bool lane_bonds, unsigned int n_components, int dim, typename PairLaw>
    inline void
    bond_block_loop(BondBlocks<dim>                               &blocks,
                    const std::array<const double *, n_components> u,
                    const std::array<double *, PairLaw::n_outputs> outputs,
                    const PairLaw                                  law,
                    BondList                                      &bonds,
                    const double                                   critical_stretch)
    {
      using namespace bond_simd;
      constexpr unsigned int                   n_outputs  = PairLaw::n_outputs;
      const std::size_t                        n_entries  = blocks.groups().size();
      const auto                              *groups     = blocks.groups().data();
      const auto                              *block_list = blocks.blocks().data();
      const auto                              *classes = ClassTable<PairLaw, dim>::get(law, blocks);
      const std::uint8_t                      *state   = blocks.state();
      typename BondBlocks<dim>::LaneBondArrays lane_arrays{};
      if constexpr (lane_bonds)
        lane_arrays = blocks.lane_bond_arrays();
      // A law whose strain holds the squared measure: the blocks where the squared measure
      // exceeds the square of the threshold less a margin are tested with the measure itself
      // (sqrt is monotone and correctly rounded: sqrt(x) > c implies x > c^2 > test).
      constexpr bool squared = squared_stretch<PairLaw>;
      const double   test =
        squared ? critical_stretch * critical_stretch * (1. - 1e-6) : critical_stretch;
      const auto add_to = [](double *target, const Vector &value) {
        Vector sum(target, stdx::element_aligned);
        sum += value;
        sum.copy_to(target, stdx::element_aligned);
      };

      for (std::size_t g = 0; g + 1 < n_entries; ++g)
        {
          const unsigned int a = groups[g].first_particle;
          Vector             u_a[n_components], sum_a[n_outputs];
          for (unsigned int c = 0; c < n_components; ++c)
            u_a[c].copy_from(u[c] + a, stdx::element_aligned);
          // A perturbed lattice: the reference positions of the particle side.
          [[maybe_unused]] Vector x_a[dim];
          if constexpr (lane_bonds)
            for (unsigned int d = 0; d < dim; ++d)
              x_a[d].copy_from(lane_arrays[d] + a, stdx::element_aligned);
          for (unsigned int k = 0; k < n_outputs; ++k)
            sum_a[k] = 0.;
          const auto side = law.side(a);
          for (unsigned int q = groups[g].first_block; q < groups[g + 1].first_block; ++q)
            {
              const auto &block = block_list[q];
              BondLanes   lanes;
              lanes.first_lane = std::size_t(q) * width;
              lanes.neighbour  = std::size_t(std::ptrdiff_t(a) + block.offset);
              Vector u_b[n_components];
              for (unsigned int c = 0; c < n_components; ++c)
                u_b[c].copy_from(u[c] + lanes.neighbour, stdx::element_aligned);
              // The block's reference bonds: its class's lattice vector (the element of the
              // class table itself, not a copy), or the lanes' own.
              const auto &bond = [&]() -> decltype(auto) {
                if constexpr (lane_bonds)
                  return BondBlocks<dim>::lane_bonds(lane_arrays,
                                                     x_a,
                                                     lanes.first_lane,
                                                     lanes.neighbour);
                else
                  return (classes[block.bond_class]);
              }();
              const auto strain = law.strain(bond, lanes.first_lane, u_a, u_b);
              lanes.active      = intact_lanes(state + lanes.first_lane);
              if constexpr (PairLaw::breaks_bonds)
                if (stdx::any_of(lanes.active && (strain.stretch > test)))
                  {
                    Vector stretch = strain.stretch;
                    if constexpr (squared)
                      stretch = stdx::sqrt(stretch);
                    blocks.break_lanes(stretch, critical_stretch, q, bonds);
                    lanes.active = intact_lanes(state + lanes.first_lane);
                  }
              Vector to_a[n_outputs], to_b[n_outputs];
              law.pair(bond, strain, side, lanes, to_a, to_b);
              for (unsigned int k = 0; k < n_outputs; ++k)
                {
                  sum_a[k] += to_a[k];
                  add_to(outputs[k] + lanes.neighbour, to_b[k]);
                }
            }
          for (unsigned int k = 0; k < n_outputs; ++k)
            add_to(outputs[k] + a, sum_a[k]);
        }
    }
  } // namespace internal

  /**
   * @brief The loop over the lattice bond blocks of @p blocks that every force kernel runs;
   * the model supplies only its pair law @p law, inlined (no call per bond through a pointer).
   *
   * For every group (lanes: kernel indices a ... a + width - 1) and every block of the group
   * (neighbours b ... b + width - 1, b = a + offset), the loop loads the @p n_components
   * kernel-order arrays @p u (the components of the unknowns: dim translations, one scalar,
   * translations and rotations) on both sides, u_a[c] once per group and u_b[c] per block, and
   * hands both to the law (a displacement model uses u_b - u_a, a micropolar one also the mean
   * rotation). The law is a type with
   *  - `static constexpr unsigned int n_outputs`: the number of kernel-order arrays
   *    @p outputs it accumulates into (force components, energy, dilatation, ...);
   *  - `static constexpr bool breaks_bonds`;
   *  - `side(a)`: what it reads once per group on the particle side (any type);
   *  - `strain(bond, first_lane, u_a, u_b)`: its per-lane measures of the deformed bond
   *    (any type; per-lane arrays are read at first_lane = lanes.first_lane; with a
   *    bond_simd::Vector member `stretch` if it breaks bonds: intact breakable lanes whose
   *    stretch exceeds @p critical_stretch are broken in the lanes and in @p bonds,
   *    BondBlocks::break_lanes(), before the pair is evaluated; a law with
   *    `static constexpr bool squared_stretch = true` gives the square of the measure instead,
   *    and the loop takes the square root only in the rare blocks where the square comes
   *    near the threshold's: the same bonds break);
   *  - `pair(bond, strain, side, lanes, to_a, to_b)`: the contributions to_a[k] and
   *    to_b[k] of the block's bonds to output k at the particle side and at the neighbour side
   *    (zero in lanes that are not lanes.active); per-lane arrays are read at lanes.first_lane,
   *    per-particle arrays at a and lanes.neighbour.
   *
   * `bond` is the block's reference bond: its BondBlocks::BondClass (scalars: xi, length,
   * inverse_length) on a regular lattice, a BondBlocks::LaneBond (the same members, one value
   * per lane) on a perturbed one, so a law writes strain() and pair() as templates of the bond
   * type (BondValue<Bond> is double or bond_simd::Vector). A law may bring its own class
   * table, `class_table()`: a pointer to one element per class of BondBlocks::classes(), in its
   * order, with at least a BondClass's members (xi, length, inverse_length) and whatever
   * constants the law forms once per class; the loop then hands the law these elements. One
   * branch per call picks the loop.
   *
   * The loop adds to_b to the neighbours' entries at once and keeps the sums of to_a in
   * registers until the group ends. @p bonds and @p critical_stretch are read only if the law
   * breaks bonds. The kernel-order arrays come from BondBlocks::component().
   *
   * The vector stores of the loop may alias any memory (the SIMD types store through
   * memcpy), so whatever the loop reads through a reference or a member would be read again
   * after every store, i.e. several times per block. The loop therefore takes @p u,
   * @p outputs and @p law by value and reads the groups, blocks and classes of @p blocks
   * through local pointers (BondBlocks::break_lanes() changes only the lane states), and it
   * hands BondBlocks::break_lanes() a copy of the stretch: the address of the law's strain
   * would keep the whole strain in memory.
   */
  template <unsigned int n_components, int dim, typename PairLaw>
  inline void
  for_each_bond_block(BondBlocks<dim>                               &blocks,
                      const std::array<const double *, n_components> u,
                      const std::array<double *, PairLaw::n_outputs> outputs,
                      const PairLaw                                  law,
                      BondList                                      &bonds,
                      const double                                   critical_stretch)
  {
    if (blocks.has_lane_bonds())
      internal::bond_block_loop<true, n_components, dim>(blocks,
                                                         u,
                                                         outputs,
                                                         law,
                                                         bonds,
                                                         critical_stretch);
    else
      internal::bond_block_loop<false, n_components, dim>(blocks,
                                                          u,
                                                          outputs,
                                                          law,
                                                          bonds,
                                                          critical_stretch);
  }

  /**
   * @brief One force evaluation of a bond-block kernel, the frame the models share around
   * their loop: the kernel's copy of the bond states follows the bonds of @p particles, the
   * @p n_components components of @p u are gathered into @p u_field, @p f_field (and, if
   * @p energy_density is given, @p w_field) is zeroed, @p loop runs (called with
   * std::true_type if the energy density is wanted, std::false_type otherwise) and the force
   * (and energy) densities of the owned particles are scattered into @p force
   * (@p energy_density), divided by the volumes.
   */
  template <int dim, typename Loop>
  inline void
  evaluate_bond_kernel(BondBlocks<dim>                 &blocks,
                       const ParticleSystem<dim>       &particles,
                       const ParticleVector            &u,
                       const unsigned int               n_components,
                       typename BondBlocks<dim>::Array &u_field,
                       typename BondBlocks<dim>::Array &f_field,
                       typename BondBlocks<dim>::Array &w_field,
                       ParticleVector                  &force,
                       std::vector<double>             *energy_density,
                       const Loop                      &loop)
  {
    blocks.sync_state(particles.bonds());
    blocks.gather(u.begin(), n_components, u_field);
    std::fill(f_field.begin(), f_field.end(), 0.);
    const double *volume = particles.volumes().data();
    if (energy_density != nullptr)
      {
        std::fill(w_field.begin(), w_field.end(), 0.);
        loop(std::true_type());
        energy_density->resize(particles.n_owned());
        blocks.scatter_owned(w_field, 1, volume, energy_density->data());
      }
    else
      loop(std::false_type());
    blocks.scatter_owned(f_field, n_components, volume, force.begin());
  }

  /**
   * @brief A value per owned particle from a pair law with one output that breaks nothing
   * (MaterialModel::thermoelastic_measure() of the bond-based models): the kernel's copy of the
   * bond states follows the bonds of @p particles, the @p n_components unknowns @p u are
   * gathered into @p u_field, @p law's values at the two ends of every intact bond are summed
   * in @p w_field and scattered into @p measure (owned particles), divided by the volumes.
   */
  template <int dim, unsigned int n_components = dim, typename PairLaw>
  inline void
  evaluate_bond_measure(BondBlocks<dim>                 &blocks,
                        ParticleSystem<dim>             &particles,
                        const ParticleVector            &u,
                        typename BondBlocks<dim>::Array &u_field,
                        typename BondBlocks<dim>::Array &w_field,
                        const PairLaw                   &law,
                        std::vector<double>             &measure)
  {
    static_assert(PairLaw::n_outputs == 1 && !PairLaw::breaks_bonds);
    blocks.sync_state(particles.bonds());
    blocks.gather(u.begin(), n_components, u_field);
    std::fill(w_field.begin(), w_field.end(), 0.);
    std::array<const double *, n_components> unknowns;
    for (unsigned int c = 0; c < n_components; ++c)
      unknowns[c] = blocks.component(u_field, c);
    for_each_bond_block<n_components>(blocks,
                                      unknowns,
                                      std::array<double *, 1>{{blocks.component(w_field, 0)}},
                                      law,
                                      particles.bonds(),
                                      0.);
    measure.resize(particles.n_owned());
    blocks.scatter_owned(w_field, 1, particles.volumes().data(), measure.data());
  }

  /**
   * @brief The temperature change of the lanes' bonds, the mean (Delta T_a + Delta T_b) / 2 of
   * their two ends (doc/theory/thermal_strain.md, "Choices"), for a pair law with a thermal
   * strain: the loop hands it the kernel-order temperature change as the extra input component
   * @p c after the unknowns (gather_temperature_change()).
   */
  inline bond_simd::Vector
  bond_temperature_change(const bond_simd::Vector *u_a,
                          const bond_simd::Vector *u_b,
                          const unsigned int       c)
  {
    return 0.5 * (u_a[c] + u_b[c]);
  }

  /**
   * @brief The temperature change @p delta_T (one value per local particle,
   * MaterialModel::set_temperature_change()) in kernel order into @p field (sized here on first
   * use), and its one component: the extra input of a thermal pair law (bond_temperature_change()).
   */
  template <int dim>
  inline const double *
  gather_temperature_change(const BondBlocks<dim>           &blocks,
                            const ParticleVector            &delta_T,
                            typename BondBlocks<dim>::Array &field)
  {
    if (field.empty())
      blocks.reinit_field(field, 1);
    blocks.gather(delta_T.begin(), 1, field);
    return blocks.component(field, 0);
  }

  /**
   * @brief The deformed bond of a displacement model, per lane: r = xi + eta (eta = u_b - u_a
   * the relative displacement), rho = |xi| / |r| and the stretch s = |r| / |xi| - 1.
   */
  template <int dim>
  struct DeformedBond
  {
    /// r, rho and s per lane.
    ///@{
    bond_simd::Vector r[dim];
    bond_simd::Vector rho;
    bond_simd::Vector stretch;
    ///@}
  };

  /**
   * @brief The DeformedBond of the lanes of a block of reference bond @p bond_class (its
   * class or the lanes' own, see for_each_bond_block()) with displacements
   * @p u_a at the particle side and @p u_b at the neighbours (dim components each);
   * multiplications only (bond_simd::inverse_sqrt()).
   */
  template <int dim, typename Bond>
  inline DeformedBond<dim>
  deformed_bond(const Bond &bond_class, const bond_simd::Vector *u_a, const bond_simd::Vector *u_b)
  {
    using bond_simd::Vector;
    DeformedBond<dim> y;
    Vector            length2 = 0.;
    for (unsigned int d = 0; d < dim; ++d)
      {
        y.r[d] = bond_class.xi[d] + (u_b[d] - u_a[d]);
        length2 += y.r[d] * y.r[d];
      }
    const Vector ratio2 = length2 * (bond_class.inverse_length * bond_class.inverse_length);
    y.rho               = bond_simd::inverse_sqrt(ratio2);
    y.stretch           = ratio2 * y.rho - 1.;
    return y;
  }

  /**
   * @brief What the pair laws of the displacement field's bond stretch share: the deformed bond
   * (deformed_bond()) as their strain, and by default nothing read per group on the particle
   * side. A law derives from it and adds its outputs and pair(); one that reads per-particle
   * data declares its own Side and side().
   */
  template <int dim>
  struct StretchPairLaw
  {
    /// Nothing read per group on the particle side.
    struct Side
    {};

    /// Nothing to read for the group of particle @p a.
    Side
    side(const unsigned int) const
    {
      return {};
    }

    /// The deformed bond of the lanes (relative position, rho, stretch).
    template <typename Bond>
    DeformedBond<dim>
    strain(const Bond &bond,
           const std::size_t /*first_lane*/,
           const bond_simd::Vector *u_a,
           const bond_simd::Vector *u_b) const
    {
      return deformed_bond<dim>(bond, u_a, u_b);
    }
  };

  /**
   * @brief The bond slope of a scalar field per lane: r = (w_b - w_a)/|xi| and its magnitude
   * |r|, the `stretch` that breaks a bond.
   */
  struct BondSlope
  {
    /// r and |r| per lane.
    ///@{
    bond_simd::Vector value, stretch;
    ///@}
  };

  /**
   * @brief The pair law of the bond-based energy of a scalar field (the antiplane models):
   * slope r (BondSlope) as its strain, pair force k r on the particle side (-k r on the
   * neighbour) and, if @p with_energy, the pair energy k r^2 |xi| / 4 at both ends, with k the
   * per-lane coefficient (c G chi V_i V_j); a bond breaks where |r| exceeds the critical slope.
   * The law does not depend on the bond's orientation. A scalar law that breaks bonds by their
   * slope derives from it and adds its own outputs and pair().
   */
  template <int dim, bool with_energy>
  struct SlopePairLaw
  {
    /// The outputs: the force density and, if with_energy, the energy density.
    static constexpr unsigned int n_outputs = 1 + (with_energy ? 1 : 0);
    /// A bond breaks where its slope exceeds the critical slope.
    static constexpr bool breaks_bonds = true;
    /// k per lane.
    const double *coefficient;

    /// Nothing read per group on the particle side.
    struct Side
    {};

    /// Nothing to read for the group of particle @p a.
    Side
    side(const unsigned int) const
    {
      return {};
    }

    /// The slope of the lanes and its magnitude (what breaks a bond).
    template <typename Bond>
    BondSlope
    strain(const Bond &bond,
           const std::size_t /*first_lane*/,
           const bond_simd::Vector *w_a,
           const bond_simd::Vector *w_b) const
    {
      const bond_simd::Vector r = (w_b[0] - w_a[0]) * bond.inverse_length;
      return {r, std::experimental::abs(r)};
    }

    /// The pair force k r (and energy) of the active lanes.
    template <typename Bond>
    void
    pair(const Bond      &bond,
         const BondSlope &r,
         const Side &,
         const BondLanes   &lanes,
         bond_simd::Vector *to_a,
         bond_simd::Vector *to_b) const
    {
      using namespace bond_simd;
      const Vector k(coefficient + lanes.first_lane, stdx::element_aligned);
      Vector       t               = 0.;
      stdx::where(lanes.active, t) = k * r.value;
      to_a[0]                      = t;
      to_b[0]                      = -t;
      if constexpr (with_energy)
        {
          Vector e                     = 0.;
          stdx::where(lanes.active, e) = (0.25 * bond.length) * k * r.value * r.value;
          to_a[1]                      = e;
          to_b[1]                      = e;
        }
    }
  };

  /**
   * @brief The pair law of bond-based heat conduction (BondBasedConduction): SlopePairLaw on
   * the temperature, whose pair "force" k (T_b - T_a)/|xi| is the heat flow of the bond into
   * the particle side (k = kappa G chi V_i V_j) and whose energy is the functional of the
   * calibration; bonds do not break by the temperature (only a broken bond, a pre-crack,
   * stops conducting: the loop's inactive lanes).
   */
  template <int dim, bool with_energy>
  struct ConductionPairLaw : SlopePairLaw<dim, with_energy>
  {
    /// No bond breaks by its temperature slope.
    static constexpr bool breaks_bonds = false;
  };

  /**
   * @brief The bond-based pair law of the warping w of Saint-Venant torsion (seed note 000,
   * sec. 4.5): SlopePairLaw with the twisted slope
   *   r = (w_b - w_a + p_a xi_y - q_a xi_x) / |xi|,  p = psi (x - x0), q = psi (y - y0),
   * i.e. the bond projection of the shear strain grad w + psi (-(y - y0), x - x0) at the bond's
   * midpoint (Torsion). The unknowns are three kernel-order components (w, p, q); p and q are
   * fixed fields. Since p_b xi_y - q_b xi_x = p_a xi_y - q_a xi_x, the slope changes sign with
   * the bond's orientation like (w_b - w_a)/|xi|, so the law does not depend on which end is
   * which; a bond breaks by |r|, the full shear of the bond.
   */
  template <int dim, bool with_energy>
  struct TwistedSlopePairLaw : SlopePairLaw<dim, with_energy>
  {
    /// The twisted slope of the lanes and its magnitude.
    template <typename Bond>
    BondSlope
    strain(const Bond &bond,
           const std::size_t /*first_lane*/,
           const bond_simd::Vector *u_a,
           const bond_simd::Vector *u_b) const
    {
      const bond_simd::Vector r =
        (u_b[0] - u_a[0] + u_a[1] * bond.xi[1] - u_a[2] * bond.xi[0]) * bond.inverse_length;
      return {r, std::experimental::abs(r)};
    }
  };
} // namespace perideal

#endif
