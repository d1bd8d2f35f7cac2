// ---------------------------------------------------------------------
// PeriDeal: the anisotropic PD plane-stress model (seed 004, state form): its force kernel (the
// two passes as pair laws), the thermoelastic measure and the out-of-plane strain. The set-up
// (parameters, calibration, bond coefficients, summary) is anisotropic_plane_stress_setup.cc.
// ---------------------------------------------------------------------
#include <perideal/pd/anisotropic_plane_stress.h>
#include <perideal/pd/anisotropic_plane_stress_kernel.h>
#include <perideal/pd/bond_loop.h>

#include <algorithm>
#include <limits>

namespace perideal
{
  using namespace dealii;

  namespace
  {

    /// The linearized stretch s = xi . eta / |xi|^2 of the lanes (what breaks a bond).
    struct PlaneStressStretch
    {
      bond_simd::Vector stretch;
    };

    /// The linearized stretch of the lanes.
    template <typename Bond>
    inline PlaneStressStretch
    linear_stretch(const Bond &bond, const bond_simd::Vector *u_a, const bond_simd::Vector *u_b)
    {
      const bond_simd::Vector e = bond.xi[0] * (u_b[0] - u_a[0]) + bond.xi[1] * (u_b[1] - u_a[1]);
      return {e * (bond.inverse_length * bond.inverse_length)};
    }

    /**
     * @brief The strain of the plane-stress pair laws: the linearized stretch and, if
     * @p thermal, less the bond's free thermal stretch n . alpha' . n DeltaT_b, DeltaT_b the mean
     * of the temperature changes of its ends, read from the component after the displacement
     * (u_a[2], u_b[2]), alpha' the in-plane expansion: the mechanical stretch, by which bonds break
     * and from which both passes measure (doc/theory/thermal_strain_state_based.md).
     */
    template <bool thermal>
    struct PlaneStressStrain : StretchPairLaw<2>
    {
      /// alpha'_11, alpha'_22, alpha'_12 [1/K] (read only if thermal).
      std::array<double, 3> expansion;

      /// The lanes' free thermal stretch per kelvin, n . alpha' . n.
      template <typename Bond>
      bond_simd::Vector
      thermal_stretch(const Bond &bond) const
      {
        return (expansion[0] * bond.xi[0] * bond.xi[0] + expansion[1] * bond.xi[1] * bond.xi[1] +
                2. * expansion[2] * bond.xi[0] * bond.xi[1]) *
               (bond.inverse_length * bond.inverse_length);
      }

      template <typename Bond>
      PlaneStressStretch
      strain(const Bond &bond,
             const std::size_t /*first_lane*/,
             const bond_simd::Vector *u_a,
             const bond_simd::Vector *u_b) const
      {
        PlaneStressStretch y = linear_stretch(bond, u_a, u_b);
        if constexpr (thermal)
          y.stretch -= thermal_stretch(bond) * (0.5 * (u_a[2] + u_b[2]));
        return y;
      }
    };

    /**
     * @brief Pass 1 as a pair law of for_each_bond_block(): breaks bonds by their linearized
     * (mechanical) stretch, then adds g_b n . eta = g_b s |xi| (g_b = M:nn chi V_i V_j) at both
     * ends (A V_i B_i before the division).
     */
    template <bool thermal>
    struct PlaneStressDilatationLaw : PlaneStressStrain<thermal>
    {
      static constexpr unsigned int n_outputs    = 1;
      static constexpr bool         breaks_bonds = true;
      /// g per lane.
      const double *g;

      template <typename Bond>
      void
      pair(const Bond               &bond,
           const PlaneStressStretch &y,
           const StretchPairLaw<2>::Side &,
           const BondLanes   &lanes,
           bond_simd::Vector *to_a,
           bond_simd::Vector *to_b) const
      {
        using namespace bond_simd;
        Vector p = 0.;
        stdx::where(lanes.active, p) =
          Vector(g + lanes.first_lane, stdx::element_aligned) * y.stretch * bond.length;
        to_a[0] = p;
        to_b[0] = p;
      }
    };

    /**
     * @brief Pass 2: the pair force [k_b s - g_b (beta_i A_i + beta_j A_j)] n on the particle
     * side (its negative on the neighbour) and, if @p with_energy, the bond energy k_b s^2 |xi| / 4
     * at both ends; with @p thermal, s is the mechanical stretch (PlaneStressStrain).
     */
    template <bool with_energy, bool thermal>
    struct PlaneStressForceLaw : PlaneStressStrain<thermal>
    {
      static constexpr unsigned int n_outputs    = 2 + (with_energy ? 1 : 0);
      static constexpr bool         breaks_bonds = false;
      /// k and g per lane; beta A per particle (kernel order).
      const double *k, *g, *beta_A;

      struct Side
      {
        bond_simd::Vector beta_A;
      };

      Side
      side(const unsigned int a) const
      {
        return {bond_simd::Vector(beta_A + a, std::experimental::element_aligned)};
      }

      /// The lanes' k_b s - g_b (beta_i A_i + beta_j A_j) (0 in inactive lanes): dE/ds / |xi|.
      bond_simd::Vector
      tension(const PlaneStressStretch &y, const Side &i, const BondLanes &lanes) const
      {
        using namespace bond_simd;
        const Vector k_b(k + lanes.first_lane, stdx::element_aligned);
        const Vector g_b(g + lanes.first_lane, stdx::element_aligned);
        const Vector beta_A_b(beta_A + lanes.neighbour, stdx::element_aligned);
        Vector       t               = 0.;
        stdx::where(lanes.active, t) = k_b * y.stretch - g_b * (i.beta_A + beta_A_b);
        return t;
      }

      template <typename Bond>
      void
      pair(const Bond               &bond,
           const PlaneStressStretch &y,
           const Side               &i,
           const BondLanes          &lanes,
           bond_simd::Vector        *to_a,
           bond_simd::Vector        *to_b) const
      {
        using namespace bond_simd;
        const Vector t = tension(y, i, lanes) * bond.inverse_length;
        for (unsigned int d = 0; d < 2; ++d)
          {
            to_a[d] = bond.xi[d] * t;
            to_b[d] = -to_a[d];
          }
        if constexpr (with_energy)
          {
            const Vector k_b(k + lanes.first_lane, stdx::element_aligned);
            Vector       e               = 0.;
            stdx::where(lanes.active, e) = (0.25 * bond.length) * k_b * y.stretch * y.stretch;
            to_a[2]                      = e;
            to_b[2]                      = e;
          }
      }
    };

    /**
     * @brief The thermoelastic measure's pass (doc/theory/thermoelasticity.md): at both ends
     * 1/2 (n . alpha' . n) |xi| [k_b s - g_b (beta_i A_i + beta_j A_j)], the bond's share of
     * -dE/dDeltaT_b (DeltaT_b the mean of the ends'), s the linearized stretch of the whole
     * strain and A of the whole strain (pass 1 without a temperature).
     */
    struct PlaneStressMeasureLaw : PlaneStressForceLaw<false, false>
    {
      static constexpr unsigned int n_outputs = 1;

      template <typename Bond>
      void
      pair(const Bond               &bond,
           const PlaneStressStretch &y,
           const Side               &i,
           const BondLanes          &lanes,
           bond_simd::Vector        *to_a,
           bond_simd::Vector        *to_b) const
      {
        const bond_simd::Vector p =
          (0.5 * bond.length) * this->thermal_stretch(bond) * this->tension(y, i, lanes);
        to_a[0] = p;
        to_b[0] = p;
      }
    };
  } // namespace

  /// Pass 1 (PlaneStressDilatationLaw) with in-plane expansion @p expansion if @p thermal.
  template <bool thermal>
  void
  AnisotropicPlaneStress::Kernel::dilatation_loop(BondList                    &bonds,
                                                  const double                 critical_stretch,
                                                  const std::array<double, 3> &expansion)
  {
    for_each_bond_block<2 + thermal, 2>(blocks,
                                        unknowns<thermal>(),
                                        {{blocks.component(a_field, 0)}},
                                        PlaneStressDilatationLaw<thermal>{{{}, expansion},
                                                                          lane_g.data()},
                                        bonds,
                                        critical_stretch);
  }

  /// Pass 2 (PlaneStressForceLaw), with the energy density if @p with_energy.
  template <bool with_energy, bool thermal>
  void
  AnisotropicPlaneStress::Kernel::force_loop(BondList                    &bonds,
                                             const std::array<double, 3> &expansion)
  {
    using Law = PlaneStressForceLaw<with_energy, thermal>;
    std::array<double *, Law::n_outputs> out;
    for (unsigned int d = 0; d < 2; ++d)
      out[d] = blocks.component(f_field, d);
    if constexpr (with_energy)
      out[2] = blocks.component(w_field, 0);
    for_each_bond_block<2 + thermal, 2>(
      blocks,
      unknowns<thermal>(),
      out,
      Law{{{}, expansion}, lane_k.data(), lane_g.data(), blocks.component(beta_A_field, 0)},
      bonds,
      0.);
  }

  void
  AnisotropicPlaneStress::compute_forces(ParticleSystem<2>    &particles,
                                         const ParticleVector &u,
                                         ParticleVector       &force,
                                         std::vector<double>  *energy_density,
                                         const double          critical_stretch)
  {
    Kernel            &k       = *kernel;
    BondList          &bonds   = particles.bonds();
    const double      *volume  = particles.volumes().data();
    const auto        &beta    = particles.energy_weights();
    const unsigned int n_owned = particles.n_owned();
    k.blocks.sync_state(bonds);
    k.blocks.gather(u.begin(), 2, k.u_field);
    // With a temperature change, the instantiation of the laws that measures the stretches
    // from the thermal ones; without one, the purely mechanical kernel.
    const ParticleVector *delta_T = this->temperature_change();
    const bool thermal = delta_T != nullptr && in_plane_expansion != std::array<double, 3>{};
    if (thermal)
      k.blocks.gather(delta_T->begin(), 1, k.delta_T_field);

    const ParticleVector A = out_of_plane_pass(particles, critical_stretch, thermal);

    // Pass 2: forces (and bond energies), summed per particle and divided by V_i.
    std::fill(k.f_field.begin(), k.f_field.end(), 0.);
    if (energy_density != nullptr)
      std::fill(k.w_field.begin(), k.w_field.end(), 0.);
    if (energy_density != nullptr && thermal)
      k.force_loop<true, true>(bonds, in_plane_expansion);
    else if (energy_density != nullptr)
      k.force_loop<true, false>(bonds, in_plane_expansion);
    else if (thermal)
      k.force_loop<false, true>(bonds, in_plane_expansion);
    else
      k.force_loop<false, false>(bonds, in_plane_expansion);
    k.blocks.scatter_owned(k.f_field, 2, volume, force.begin());
    if (energy_density != nullptr)
      {
        energy_density->resize(n_owned);
        k.blocks.scatter_owned(k.w_field, 1, volume, energy_density->data());
        for (unsigned int i = 0; i < n_owned; ++i)
          (*energy_density)[i] -= beta[i] * 0.5 * B[i] * A.local_element(i) * A.local_element(i);
      }
  }

  ParticleVector
  AnisotropicPlaneStress::out_of_plane_pass(ParticleSystem<2> &particles,
                                            const double       critical_stretch,
                                            const bool         thermal)
  {
    Kernel            &k       = *kernel;
    BondList          &bonds   = particles.bonds();
    const auto        &volume  = particles.volumes();
    const auto        &beta    = particles.energy_weights();
    const unsigned int n_owned = particles.n_owned();
    // Break over-stretched bonds, then A_i = sum g_b n . eta / (V_i B_i).
    std::fill(k.a_field.begin(), k.a_field.end(), 0.);
    if (thermal)
      k.dilatation_loop<true>(bonds, critical_stretch, in_plane_expansion);
    else
      k.dilatation_loop<false>(bonds, critical_stretch, in_plane_expansion);
    ParticleVector A;
    particles.reinit_vector(A, 1);
    k.blocks.scatter_owned(k.a_field, 1, nullptr, A.begin());
    for (unsigned int i = 0; i < n_owned; ++i)
      A.local_element(i) /= volume[i] * B[i];
    A.update_ghost_values();
    std::vector<double> beta_A(particles.n_local());
    for (unsigned int i = 0; i < particles.n_local(); ++i)
      beta_A[i] = beta[i] * A.local_element(i);
    k.blocks.gather(beta_A.data(), 1, k.beta_A_field);
    return A;
  }

  void
  AnisotropicPlaneStress::thermoelastic_measure(ParticleSystem<2>    &particles,
                                                const ParticleVector &u,
                                                std::vector<double>  &measure)
  {
    Kernel &k = *kernel;
    if (in_plane_expansion == std::array<double, 3>{})
      {
        // Without an in-plane expansion the energy does not depend on the temperature.
        measure.assign(particles.n_owned(), 0.);
        return;
      }
    k.blocks.sync_state(particles.bonds());
    k.blocks.gather(u.begin(), 2, k.u_field);
    // A of the whole strain (no bond breaks here), then the measure's pass.
    out_of_plane_pass(particles, std::numeric_limits<double>::infinity(), false);
    std::fill(k.w_field.begin(), k.w_field.end(), 0.);
    for_each_bond_block<2, 2>(k.blocks,
                              k.unknowns<false>(),
                              {{k.blocks.component(k.w_field, 0)}},
                              PlaneStressMeasureLaw{{{{}, in_plane_expansion},
                                                     k.lane_k.data(),
                                                     k.lane_g.data(),
                                                     k.blocks.component(k.beta_A_field, 0)}},
                              particles.bonds(),
                              0.);
    measure.resize(particles.n_owned());
    k.blocks.scatter_owned(k.w_field, 1, particles.volumes().data(), measure.data());
  }

  std::vector<double>
  AnisotropicPlaneStress::out_of_plane_strain(const ParticleSystem<2> &particles,
                                              const ParticleVector    &u) const
  {
    const BondList     &bonds   = particles.bonds();
    const auto         &x       = particles.positions();
    const auto         &volume  = particles.volumes();
    const unsigned int  n_owned = particles.n_owned();
    const auto          offset  = thermal_extensions(particles);
    std::vector<double> sum(n_owned, 0.);
    for (unsigned int i = 0; i < n_owned; ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        if (bonds.intact[b])
          {
            const unsigned int j = bonds.neighbor[b];
            double             e = -offset[b];
            for (unsigned int d = 0; d < 2; ++d)
              e += (x[j][d] - x[i][d]) / bonds.length[b] *
                   (u.local_element(j * 2 + d) - u.local_element(i * 2 + d));
            sum[i] += g[b] * e;
            if (j < n_owned)
              sum[j] += g[b] * e;
          }
    // The mechanical eps_33 is -A; the thermal strain alpha_33 DeltaT adds to it.
    const ParticleVector *delta_T = this->temperature_change();
    for (unsigned int i = 0; i < n_owned; ++i)
      sum[i] = -sum[i] / (volume[i] * B[i]) +
               (delta_T != nullptr ? expansion_33 * delta_T->local_element(i) : 0.);
    return sum;
  }

  std::vector<DerivedParticleField>
  AnisotropicPlaneStress::derived_fields(const ParticleSystem<2> &particles,
                                         const ParticleVector    &u) const
  {
    return {{"out_of_plane_strain", 1, out_of_plane_strain(particles, u)}};
  }

  std::vector<double>
  AnisotropicPlaneStress::thermal_extensions(const ParticleSystem<2> &particles) const
  {
    const BondList       &bonds   = particles.bonds();
    const auto           &x       = particles.positions();
    const ParticleVector *delta_T = this->temperature_change();
    const auto            alpha   = thermal_expansion();
    std::vector<double>   offset(bonds.size(), 0.);
    if (delta_T != nullptr)
      for (unsigned int i = 0; i < particles.n_owned(); ++i)
        for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
          {
            const unsigned int j  = bonds.neighbor[b];
            const Tensor<1, 2> xi = x[j] - x[i];
            offset[b]             = xi * (alpha * xi) / bonds.length[b] * 0.5 *
                        (delta_T->local_element(i) + delta_T->local_element(j));
          }
    return offset;
  }
} // namespace perideal
