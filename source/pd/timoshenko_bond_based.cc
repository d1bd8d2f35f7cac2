// ---------------------------------------------------------------------
// PeriDeal: bond-based peridynamics with Timoshenko-beam bonds and particle rotations (seed 003):
// the pair law, its softening histories and the force evaluation.
// ---------------------------------------------------------------------
#include <perideal/base/parameter_utilities.h>
#include <perideal/pd/timoshenko_bond_based.h>
#include <perideal/pd/timoshenko_kernel.h>

#include <cmath>
#include <limits>
#include <type_traits>
#include <vector>

namespace perideal
{
  using namespace dealii;

  namespace
  {
    using namespace bond_simd;
    constexpr unsigned int
    n_rotations(const int dim)
    {
      return dim == 2 ? 1 : 3;
    }

    /**
     * @brief The measures of a Timoshenko bond per lane: stretch s, shear strain gamma
     * (dim components in 3D, one along t = e_z x n in 2D), bending rotation kappa (the
     * rotations' components), and the largest of |s|/s_0, |gamma|/gamma_0, |kappa|/kappa_0 as
     * the `stretch` that breaks a bond (failure relative to the limits).
     */
    template <int dim>
    struct BondStrain
    {
      Vector s;
      Vector gamma[dim == 2 ? 1 : 3];
      Vector kappa[n_rotations(dim)];
      Vector stretch;
    };

    /**
     * @brief What the pair law reads of a bond's reference direction besides |xi| and 1/|xi|:
     * n = xi/|xi|, n/2 (the mean rotation's factor ½ taken into the direction: exact) and the
     * coefficients of the shear force 12 C_theta/|xi|^2, of the moment arm 6 C_theta/|xi| and of
     * the bending moment C_B/|xi| per unit pair coefficient k, each rounded as the law has
     * always formed it; Value double (a bond class) or bond_simd::Vector (the lanes of a
     * perturbed lattice).
     */
    template <int dim, typename Value>
    struct TimoshenkoFrame
    {
      /// n = xi/|xi| and n/2.
      ///@{
      Value n[dim], half_n[dim];
      ///@}
      /// 12 C_theta/|xi|^2, 6 C_theta/|xi| and C_B/|xi|.
      ///@{
      Value shear, arm, bend;
      ///@}
    };

    /// The TimoshenkoFrame of the reference bond @p xi, @p inverse_length with the bond
    /// stiffnesses @p C_theta, @p C_B.
    template <int dim, typename Value, typename Xi>
    DEAL_II_ALWAYS_INLINE inline TimoshenkoFrame<dim, Value>
    make_frame(const Xi &xi, const Value &inverse_length, const double C_theta, const double C_B)
    {
      TimoshenkoFrame<dim, Value> f;
      for (unsigned int d = 0; d < dim; ++d)
        {
          f.n[d]      = xi[d] * inverse_length;
          f.half_n[d] = 0.5 * f.n[d];
        }
      f.shear = 12. * C_theta * inverse_length * inverse_length;
      f.arm   = 6. * C_theta * inverse_length;
      f.bend  = C_B * inverse_length;
      return f;
    }

    /**
     * @brief A bond class of the law's own class table (for_each_bond_block()): the members of
     * the BondBlocks::BondClass and its TimoshenkoFrame, formed once per force evaluation
     * instead of once per block.
     */
    template <int dim>
    struct TimoshenkoClass : TimoshenkoFrame<dim, double>
    {
      /// The lattice vector [m], its length [m] and inverse length [1/m] (BondClass).
      ///@{
      std::array<double, dim> xi;
      double                  length, inverse_length;
      ///@}
    };

    /// The TimoshenkoClass of every bond class of @p blocks, in the order of its classes().
    template <int dim>
    std::vector<TimoshenkoClass<dim>>
    class_table(const BondBlocks<dim> &blocks, const double C_theta, const double C_B)
    {
      std::vector<TimoshenkoClass<dim>> table(blocks.classes().size());
      for (unsigned int i = 0; i < table.size(); ++i)
        {
          const auto &c = blocks.classes()[i];
          static_cast<TimoshenkoFrame<dim, double> &>(table[i]) =
            make_frame<dim, double>(c.xi, c.inverse_length, C_theta, C_B);
          table[i].xi             = c.xi;
          table[i].length         = c.length;
          table[i].inverse_length = c.inverse_length;
        }
      return table;
    }

    /**
     * @brief The constants and per-lane arrays a TimoshenkoPairLaw reads.
     */
    struct TimoshenkoLawData
    {
      /// k = G chi V_i V_j per lane.
      const double *coefficient = nullptr;
      /// The lane states (BondBlocks::state()), read only to prefetch them.
      const std::uint8_t *state = nullptr;
      /// The class table (class_table(): TimoshenkoClass of the law's dimension).
      const void *classes = nullptr;
      double      C_N = 0., C_theta = 0., C_B = 0.;
      /// 1/s_0, 1/gamma_0, 1/kappa_0 (0: that mode does not fail).
      double inverse_limit[3] = {0., 0., 0.};
      /// 1/s_0 of compression (s < 0): inverse_limit[0] but with a <Compressive strength>.
      double inverse_compression = 0.;
      /// Softening: histories x (largest value / limit) and factors mu per mode and lane, the
      /// dissipated energy per lane, k, and whether this evaluation raises the histories.
      double *history[3] = {nullptr, nullptr, nullptr};
      double *factor[3]  = {nullptr, nullptr, nullptr};
      double *dissipated = nullptr;
      /// The largest growth of a history in this evaluation (written by commits).
      double *largest_growth      = nullptr;
      double  softening_parameter = 1.;
      bool    commit              = false;
      /// The thermal expansion alpha of the bonds' stretch (thermal laws only).
      double expansion = 0.;
    };

    /**
     * @brief The pair law of the Timoshenko bond (TimoshenkoBondBased): force k f on the
     * particle side, -k f on the neighbour, moments k m_i and k m_j, and, if @p with_energy,
     * the pair energy k w / 2 at both ends (k per lane = G chi V_i V_j). With @p softening,
     * each mode is scaled by its factor per lane (secant stiffness at the largest value
     * reached); if `commit`, the pair first raises the lanes' histories to the present values
     * and updates their factors and dissipated energies. With @p thermal, the stretch s is the
     * mechanical one, less alpha Delta T_b (Delta T_b the bond's mean temperature change, the
     * loop's input after the unknowns: bond_temperature_change()); shear and bending take no
     * thermal strain.
     */
    template <int dim, bool with_energy, bool softening, bool thermal>
    struct TimoshenkoPairLaw
    {
      static constexpr unsigned int n_rot   = n_rotations(dim);
      static constexpr unsigned int n_shear = (dim == 2 ? 1 : 3);
      /// The loop's inputs: the unknowns and, if thermal, the temperature change.
      static constexpr unsigned int n_inputs     = dim + n_rot + (thermal ? 1 : 0);
      static constexpr unsigned int n_outputs    = dim + n_rot + (with_energy ? 1 : 0);
      static constexpr bool         breaks_bonds = true;
      /// How far ahead strain() prefetches the pair coefficients: 16 blocks.
      static constexpr std::size_t prefetch_lanes = 16 * bond_simd::width;
      /// The strain's `stretch` is the square of the failure measure (for_each_bond_block()).
      static constexpr bool squared_stretch = true;
      static constexpr bool softens         = softening;
      TimoshenkoLawData     p;

      /// The class table of the loop (p.classes).
      const TimoshenkoClass<dim> *
      class_table() const
      {
        return static_cast<const TimoshenkoClass<dim> *>(p.classes);
      }

      struct Side
      {};
      Side
      side(const unsigned int) const
      {
        return {};
      }

      /// The frame of the reference bond @p bond: its class's (formed once per evaluation) on
      /// a regular lattice, the lanes' own on a perturbed one.
      template <typename Bond>
      DEAL_II_ALWAYS_INLINE inline decltype(auto)
      frame(const Bond &bond) const
      {
        if constexpr (std::is_same_v<Bond, TimoshenkoClass<dim>>)
          return static_cast<const TimoshenkoFrame<dim, double> &>(bond);
        else
          return make_frame<dim, Vector>(bond.xi, bond.inverse_length, p.C_theta, p.C_B);
      }

      // strain() and pair() inlined into the loop whatever their size (GCC 12 outlined the
      // strain of the regular lattice once it had the class table: a call per block, its
      // arguments through memory).
      template <typename Bond>
      DEAL_II_ALWAYS_INLINE inline BondStrain<dim>
      strain(const Bond       &bond,
             const std::size_t first_lane,
             const Vector     *u_a,
             const Vector     *u_b) const
      {
        // The pair coefficients stream from memory (8 B per lane, larger than the caches on
        // the benchmark lattices); without a prefetch each block waited for its line.
        __builtin_prefetch(p.coefficient + first_lane + prefetch_lanes);
        if (first_lane % (8 * bond_simd::width) == 0)
          __builtin_prefetch(p.state + first_lane + prefetch_lanes);
        const auto     &f  = frame(bond);
        const auto     &il = bond.inverse_length;
        const auto     &n  = f.n;
        BondStrain<dim> y;
        Vector          eta[dim];
        y.s = 0.;
        for (unsigned int d = 0; d < dim; ++d)
          {
            eta[d] = u_b[d] - u_a[d];
            y.s += n[d] * eta[d];
          }
        Vector gamma2 = 0., kappa2 = 0.;
        if constexpr (dim == 2)
          {
            y.gamma[0] = (n[0] * eta[1] - n[1] * eta[0]) * il - 0.5 * (u_a[2] + u_b[2]);
            y.kappa[0] = u_b[2] - u_a[2];
            gamma2     = y.gamma[0] * y.gamma[0];
            kappa2     = y.kappa[0] * y.kappa[0];
          }
        else
          {
            // gamma = (eta - (n . eta) n)/|xi| - (theta_a + theta_b) x n / 2, the ½ in n/2.
            const auto &h = f.half_n;
            Vector      t[3], k[3];
            for (unsigned int d = 0; d < 3; ++d)
              {
                t[d] = u_a[3 + d] + u_b[3 + d];
                k[d] = u_b[3 + d] - u_a[3 + d];
              }
            const Vector tn[3] = {t[1] * h[2] - t[2] * h[1],
                                  t[2] * h[0] - t[0] * h[2],
                                  t[0] * h[1] - t[1] * h[0]};
            const Vector kn    = k[0] * n[0] + k[1] * n[1] + k[2] * n[2];
            for (unsigned int d = 0; d < 3; ++d)
              {
                y.gamma[d] = (eta[d] - y.s * n[d]) * il - tn[d];
                y.kappa[d] = k[d] - kn * n[d];
                gamma2 += y.gamma[d] * y.gamma[d];
                kappa2 += y.kappa[d] * y.kappa[d];
              }
          }
        y.s *= il;
        if constexpr (thermal)
          y.s -= p.expansion * bond_temperature_change(u_a, u_b, dim + n_rot);
        // (1/s_0)^2 of the sign of s.
        Vector a2                 = p.inverse_limit[0] * p.inverse_limit[0];
        stdx::where(y.s < 0., a2) = p.inverse_compression * p.inverse_compression;
        const Vector x2           = stdx::max(y.s * y.s * a2,
                                    stdx::max(gamma2 * (p.inverse_limit[1] * p.inverse_limit[1]),
                                              kappa2 * (p.inverse_limit[2] * p.inverse_limit[2])));
        // The square of the failure measure: the loop takes the root where it may break.
        y.stretch = x2;
        return y;
      }

      /// Per lane 1/s_0 of the sign of the stretch @p s (tension or compression).
      Vector
      axial_inverse_limit(const Vector &s) const
      {
        Vector a               = p.inverse_limit[0];
        stdx::where(s < 0., a) = p.inverse_compression;
        return a;
      }

      template <typename Bond>
      DEAL_II_ALWAYS_INLINE inline void
      pair(const Bond            &bond,
           const BondStrain<dim> &y,
           const Side &,
           const BondLanes &lanes,
           Vector          *to_a,
           Vector          *to_b) const
      {
        const auto &f = frame(bond);
        const auto &n = f.n;
        Vector      k = 0.;
        stdx::where(lanes.active, k) =
          Vector(p.coefficient + lanes.first_lane, stdx::element_aligned);
        Vector k_s = k, k_g = k, k_b = k;
        if constexpr (softening)
          {
            const std::size_t q = lanes.first_lane;
            if (p.commit)
              update_history(bond, y, q, k);
            k_s *= Vector(p.factor[0] + q, stdx::element_aligned);
            k_g *= Vector(p.factor[1] + q, stdx::element_aligned);
            k_b *= Vector(p.factor[2] + q, stdx::element_aligned);
          }
        // f = p.C_N s n + 12 p.C_theta gamma / |xi|^2; m = 6 p.C_theta n x gamma / |xi| +- p.C_B
        // kappa / |xi|.
        const Vector axial = (p.C_N * k_s) * y.s;
        const Vector shear = f.shear * k_g;
        const Vector arm   = f.arm * k_g;
        const Vector bend  = f.bend * k_b;
        if constexpr (dim == 2)
          {
            const Vector fg = shear * y.gamma[0];
            to_a[0]         = axial * n[0] - fg * n[1];
            to_a[1]         = axial * n[1] + fg * n[0];
            const Vector mg = arm * y.gamma[0], mb = bend * y.kappa[0];
            to_a[2] = mg + mb;
            to_b[2] = mg - mb;
          }
        else
          {
            for (unsigned int d = 0; d < 3; ++d)
              to_a[d] = axial * n[d] + shear * y.gamma[d];
            const Vector ng[3] = {n[1] * y.gamma[2] - n[2] * y.gamma[1],
                                  n[2] * y.gamma[0] - n[0] * y.gamma[2],
                                  n[0] * y.gamma[1] - n[1] * y.gamma[0]};
            for (unsigned int d = 0; d < 3; ++d)
              {
                const Vector mg = arm * ng[d], mb = bend * y.kappa[d];
                to_a[3 + d] = mg + mb;
                to_b[3 + d] = mg - mb;
              }
          }
        for (unsigned int d = 0; d < dim; ++d)
          to_b[d] = -to_a[d];
        if constexpr (with_energy)
          {
            Vector g2 = 0., b2 = 0.;
            for (unsigned int d = 0; d < n_shear; ++d)
              g2 += y.gamma[d] * y.gamma[d];
            for (unsigned int d = 0; d < n_rot; ++d)
              b2 += y.kappa[d] * y.kappa[d];
            // w = p.C_N |xi| s^2 / 2 + 6 p.C_theta gamma^2 / |xi| + p.C_B kappa^2 / (2 |xi|), k w /
            // 2 per end.
            const Vector e =
              0.25 * (axial * y.s * bond.length + shear * g2 * bond.length + bend * b2);
            to_a[n_outputs - 1] = e;
            to_b[n_outputs - 1] = e;
          }
      }

      /**
       * @brief Raise the histories of the active lanes of block @p q to the present measures,
       * and update their factors and the energy they have p.dissipated (seed eq. 15, secant
       * unloading: D(x) = U_0 [1/2 + (1 - e^(-k(x-1)))/k - x e^(-k(x-1))/2] for x > 1, U_0 the
       * mode's bond energy at its limit times 2), with @p k the lanes' pair coefficients (0 in
       * lanes without force: a bond broken in this evaluation keeps its history, and
       * released_energy() takes its energy).
       */
      template <typename Bond>
      void
      update_history(const Bond            &bond,
                     const BondStrain<dim> &y,
                     const std::size_t      q,
                     const Vector          &k) const
      {
        Vector g2 = 0., b2 = 0.;
        for (unsigned int d = 0; d < n_shear; ++d)
          g2 += y.gamma[d] * y.gamma[d];
        for (unsigned int d = 0; d < n_rot; ++d)
          b2 += y.kappa[d] * y.kappa[d];
        // Lanes without force (empty, broken) keep their histories: a checkpoint restores those
        // of bonds only, and damage_changed() reports the growth of bonds only.
        const Vector a          = axial_inverse_limit(y.s);
        Vector       present[3] = {stdx::abs(y.s) * a,
                                   stdx::sqrt(g2) * p.inverse_limit[1],
                                   stdx::sqrt(b2) * p.inverse_limit[2]};
        for (auto &x : present)
          stdx::where(k == 0., x) = 0.;
        // U_0 per mode: p.C_N |xi| s_0^2 (s_0 of the present sign), 12 p.C_theta gamma_0^2 /
        // |xi|, p.C_B kappa_0^2 / |xi|.
        const Vector U0[3] = {
          p.inverse_limit[0] > 0. ? Vector(p.C_N * bond.length) / (a * a) : Vector(0.),
          p.inverse_limit[1] > 0. ? Vector(12. * p.C_theta * bond.inverse_length /
                                           (p.inverse_limit[1] * p.inverse_limit[1])) :
                                    Vector(0.),
          p.inverse_limit[2] > 0. ?
            Vector(p.C_B * bond.inverse_length / (p.inverse_limit[2] * p.inverse_limit[2])) :
            Vector(0.)};
        const double kk = p.softening_parameter;
        const auto   D  = [kk](const Vector &x) {
          Vector d = 0.;
          for (unsigned int l = 0; l < bond_simd::width; ++l)
            if (x[l] > 1.)
              {
                const double e = std::exp(-kk * (x[l] - 1.));
                d[l]           = 0.5 + (1. - e) / kk - 0.5 * x[l] * e;
              }
          return d;
        };
        Vector released = 0.;
        for (unsigned int m = 0; m < 3; ++m)
          {
            const Vector old(p.history[m] + q, stdx::element_aligned);
            if (stdx::none_of(present[m] > old))
              continue;
            const Vector grown = stdx::max(old, present[m]);
            // Growth that changes the factor: beyond the limit (1) only.
            const Vector one = 1.;
            *p.largest_growth =
              std::max(*p.largest_growth, stdx::hmax(stdx::max(grown, one) - stdx::max(old, one)));
            released += U0[m] * (D(grown) - D(old));
            grown.copy_to(p.history[m] + q, stdx::element_aligned);
            Vector mu = 1.;
            for (unsigned int l = 0; l < bond_simd::width; ++l)
              mu[l] = Timoshenko::softening_factor(grown[l], kk);
            mu.copy_to(p.factor[m] + q, stdx::element_aligned);
          }
        Vector total(p.dissipated + q, stdx::element_aligned);
        total += k * released;
        total.copy_to(p.dissipated + q, stdx::element_aligned);
      }
    };

    /**
     * @brief The thermoelastic measure of for_each_bond_block(): 1/2 k C_N alpha s |xi| at both
     * ends of each intact bond (s the axial stretch of the whole strain, k the lane's pair
     * coefficient times its axial softening factor), the part of the axial energy's derivative
     * with respect to Delta T_b that each end takes; shear and bending take no thermal strain.
     */
    template <int dim>
    struct TimoshenkoMeasureLaw : TimoshenkoPairLaw<dim, false, false, false>
    {
      static constexpr unsigned int n_outputs    = 1;
      static constexpr bool         breaks_bonds = false;

      template <typename Bond>
      void
      pair(const Bond            &bond,
           const BondStrain<dim> &y,
           const typename TimoshenkoPairLaw<dim, false, false, false>::Side &,
           const BondLanes &lanes,
           Vector          *to_a,
           Vector          *to_b) const
      {
        const TimoshenkoLawData &p = this->p;
        Vector                   k = 0.;
        stdx::where(lanes.active, k) =
          Vector(p.coefficient + lanes.first_lane, stdx::element_aligned);
        if (p.factor[0] != nullptr)
          k *= Vector(p.factor[0] + lanes.first_lane, stdx::element_aligned);
        const Vector m = (0.5 * p.C_N * p.expansion * bond.length) * k * y.s;
        to_a[0]        = m;
        to_b[0]        = m;
      }
    };
  } // namespace

  template <int dim>
  TimoshenkoBondBased<dim>::TimoshenkoBondBased()
    : kernel(std::make_unique<Kernel>())
  {}

  template <int dim>
  TimoshenkoBondBased<dim>::~TimoshenkoBondBased() = default;

  template <int dim>
  void
  TimoshenkoBondBased<dim>::set_bond_coefficients(const ParticleSystem<dim> &particles,
                                                  const bool                 with_surface_factor)
  {
    bond_pair_coefficients(particles, 1., with_surface_factor, bond_coefficient);
    kernel->blocks.to_lanes(bond_coefficient, kernel->lane_coefficient);
  }

  template <int dim>
  void
  TimoshenkoBondBased<dim>::compute_forces(ParticleSystem<dim>  &particles,
                                           const ParticleVector &u,
                                           ParticleVector       &force,
                                           std::vector<double>  *energy_density,
                                           const double          critical_stretch)
  {
    Kernel    &k      = *kernel;
    const bool breaks = std::isfinite(critical_stretch);
    const bool soft   = (failure == FailureLaw::softening);
    AssertThrow(!breaks || std::isfinite(softening),
                ExcMessage("<Material/timoshenko bond based/Tensile strength> derives the "
                           "softening parameter from the fracture energy, but the critical "
                           "stretch was given as such. Accepted: <Material/critical "
                           "stretch/Fracture energy> > 0 with Critical stretch = 0, or no "
                           "Tensile strength."));
    // The histories are raised only by a call that may break bonds (explicit steps, the
    // converged state of a load step); the others see the bonds as the last such call left
    // them. A softening bond is removed once its force has fallen to 1e-6 of the peak.
    const double      threshold = !breaks ? std::numeric_limits<double>::infinity() :
                                  soft    ? 1. + std::log(1e6) / softening :
                                            1.;
    TimoshenkoLawData base;
    base.C_N     = bond_stiffness.normal;
    base.C_theta = bond_stiffness.shear;
    base.C_B     = bond_stiffness.bending;
    if (breaks)
      {
        const auto limit = failure_limits(critical_stretch);
        for (unsigned int m = 0; m < 3; ++m)
          base.inverse_limit[m] = 1. / limit[m];
        base.inverse_compression =
          compressive_strength > 0. ? youngs_modulus / compressive_strength : base.inverse_limit[0];
      }
    base.softening_parameter = softening;
    base.commit              = breaks;
    const auto classes       = class_table(k.blocks, base.C_theta, base.C_B);
    base.classes             = classes.data();
    base.expansion           = bond_expansion();
    if (breaks)
      k.largest_growth = 0.;
    // Without an expansion, a temperature change strains nothing: the loop of today.
    const ParticleVector *delta_T = this->temperature_change();
    const double         *t_field = delta_T != nullptr && base.expansion != 0. ?
                                      gather_temperature_change(k.blocks, *delta_T, k.t_field) :
                                      nullptr;
    const auto            run     = [&](auto with_energy) {
      constexpr bool e = decltype(with_energy)::value;
      if (t_field != nullptr)
        {
          if (soft)
            k.force_loop(TimoshenkoPairLaw<dim, e, true, true>{base},
                         particles.bonds(),
                         threshold,
                         t_field);
          else
            k.force_loop(TimoshenkoPairLaw<dim, e, false, true>{base},
                         particles.bonds(),
                         threshold,
                         t_field);
        }
      else if (soft)
        k.force_loop(TimoshenkoPairLaw<dim, e, true, false>{base},
                     particles.bonds(),
                     threshold,
                     nullptr);
      else
        k.force_loop(TimoshenkoPairLaw<dim, e, false, false>{base},
                     particles.bonds(),
                     threshold,
                     nullptr);
    };
    evaluate_bond_kernel<dim>(k.blocks,
                              particles,
                              u,
                              Kernel::n_components,
                              k.u_field,
                              k.f_field,
                              k.w_field,
                              force,
                              energy_density,
                              run);
  }

  template <int dim>
  void
  TimoshenkoBondBased<dim>::thermoelastic_measure(ParticleSystem<dim>  &particles,
                                                  const ParticleVector &u,
                                                  std::vector<double>  &measure)
  {
    Kernel                   &k = *kernel;
    TimoshenkoMeasureLaw<dim> law;
    law.p.coefficient  = k.lane_coefficient.data();
    law.p.C_N          = bond_stiffness.normal;
    law.p.C_theta      = bond_stiffness.shear;
    law.p.C_B          = bond_stiffness.bending;
    law.p.expansion    = bond_expansion();
    const auto classes = class_table(k.blocks, law.p.C_theta, law.p.C_B);
    law.p.classes      = classes.data();
    // The secant factors of softening bonds, as the forces take them.
    if (failure == FailureLaw::softening)
      law.p.factor[0] = k.factor[0].data();
    evaluate_bond_measure<dim, Kernel::n_components>(k.blocks,
                                                     particles,
                                                     u,
                                                     k.u_field,
                                                     k.w_field,
                                                     law,
                                                     measure);
  }

  template <int dim>
  FieldLayout
  TimoshenkoBondBased<dim>::field_layout() const
  {
    return FieldLayout::displacement_and_rotation(dim);
  }

  template <int dim>
  std::vector<double>
  TimoshenkoBondBased<dim>::inertia_densities(const double density) const
  {
    std::vector<double> inertia(Kernel::n_components, density);
    for (unsigned int c = dim; c < Kernel::n_components; ++c)
      inertia[c] = inertia_factor * density * spacing * spacing;
    return inertia;
  }

  template <int dim>
  SymmetricTensor<4, dim>
  TimoshenkoBondBased<dim>::elasticity_tensor() const
  {
    return isotropic_elasticity_tensor<dim>(youngs_modulus, poisson_ratio, context.planar);
  }

  template <int dim>
  double
  TimoshenkoBondBased<dim>::critical_stretch(const double fracture_energy) const
  {
    const double s0 = Timoshenko::brittle_stretch(bond_stiffness,
                                                  dim,
                                                  context.horizon,
                                                  context.thickness,
                                                  fracture_energy);
    if (tensile_strength > 0.)
      {
        // The limit is the strength's; G0 gives k (doc/theory/models.md, "Tensile strength").
        const std::string entry = "<Material/timoshenko bond based/Tensile strength>";
        const double      s_G   = fracture_factor[0] * s0;
        const double      limit = tensile_strength / youngs_modulus;
        AssertThrow(fracture_energy > 0. && limit < s_G,
                    ExcMessage(entry + " = " + ParameterUtilities::format_number(tensile_strength) +
                               " gives the elastic limit s_0 = sigma_t / E = " +
                               ParameterUtilities::format_number(limit) +
                               ", not below the brittle critical stretch s_G = " +
                               ParameterUtilities::format_number(s_G) + " of the fracture energy " +
                               ParameterUtilities::format_number(fracture_energy) +
                               " J/m^2: no softening bond dissipates it. Accepted: sigma_t < "
                               "E s_G = " +
                               ParameterUtilities::format_number(youngs_modulus * s_G) +
                               " Pa (or Tensile strength = 0)."));
        softening = Timoshenko::softening_for_limit_ratio(limit / s_G);
        return limit;
      }
    return fracture_factor[0] *
           (failure == FailureLaw::softening ? s0 * std::sqrt(softening / (softening + 2.)) : s0);
  }

  template <int dim>
  double
  TimoshenkoBondBased<dim>::softening_parameter() const
  {
    return softening;
  }

  template <int dim>
  std::array<double, 3>
  TimoshenkoBondBased<dim>::failure_limits(const double critical_stretch) const
  {
    const auto ratio = Timoshenko::limit_ratios(bond_stiffness, dim, context.horizon);
    return {{critical_stretch,
             critical_stretch * ratio[0] * fracture_factor[1] / fracture_factor[0],
             critical_stretch * ratio[1] * fracture_factor[2] / fracture_factor[0]}};
  }

  template <int dim>
  double
  TimoshenkoBondBased<dim>::bond_expansion() const
  {
    // The free in-plane strain per kelvin (planar_thermal_expansion() of an isotropic nu).
    return context.planar == PlanarAssumption::plane_strain ?
             (1. + poisson_ratio) * expansion.coefficient() :
             expansion.coefficient();
  }

  template <int dim>
  SymmetricTensor<2, dim>
  TimoshenkoBondBased<dim>::thermal_expansion() const
  {
    return bond_expansion() * unit_symmetric_tensor<dim>();
  }

  template <int dim>
  const Timoshenko::Stiffness &
  TimoshenkoBondBased<dim>::stiffness() const
  {
    return bond_stiffness;
  }

  template <int dim>
  ModelCapabilities
  TimoshenkoBondBased<dim>::capabilities() const
  {
    ModelCapabilities capabilities;
    capabilities.stiffness_fit         = true;
    capabilities.lattice_fracture      = true;
    capabilities.thermal_strain        = true;
    capabilities.thermoelastic_heating = true;
    return capabilities;
  }

  template class TimoshenkoBondBased<2>;
  template class TimoshenkoBondBased<3>;
} // namespace perideal

PERIDEAL_REGISTER_MATERIAL_MODEL(perideal::TimoshenkoBondBased,
                                 "timoshenko bond based",
                                 "bond-based PD with Timoshenko-beam bonds and particle rotations "
                                 "(seed 003): any nu up to 1/3 (plane stress) or 1/4.")
