// ---------------------------------------------------------------------
// PeriDeal: the ordinary state-based linear peridynamic solid (LPS).
// ---------------------------------------------------------------------
#include <deal.II/base/numbers.h>

#include <perideal/base/parameter_utilities.h>
#include <perideal/base/thermal_expansion.h>
#include <perideal/pd/bond_loop.h>
#include <perideal/pd/lattice_fracture.h>
#include <perideal/pd/linear_peridynamic_solid.h>

#include <cmath>
#include <limits>
#include <sstream>

namespace perideal
{
  using namespace dealii;

  namespace
  {
    /**
     * @brief The strain of the LPS pair laws: the deformed bond (StretchPairLaw); if
     * @p thermal, its stretch less the free thermal stretch a DeltaT_b of the bond, DeltaT_b the
     * mean of the temperature changes of its ends, read from the component after the
     * displacement (u_a[dim] and u_b[dim]): the mechanical stretch, by which bonds break and from
     * which the extension of both passes is e - a |xi| DeltaT_b
     * (doc/theory/thermal_strain_state_based.md).
     */
    template <int dim, bool thermal>
    struct LPSStrain : StretchPairLaw<dim>
    {
      /// The in-plane thermal expansion a [1/K] (read only if thermal).
      double expansion;

      template <typename Bond>
      DeformedBond<dim>
      strain(const Bond &bond,
             const std::size_t /*first_lane*/,
             const bond_simd::Vector *u_a,
             const bond_simd::Vector *u_b) const
      {
        DeformedBond<dim> y = deformed_bond<dim>(bond, u_a, u_b);
        if constexpr (thermal)
          y.stretch -= (0.5 * expansion) * (u_a[dim] + u_b[dim]);
        return y;
      }
    };

    /**
     * @brief Pass 1 of the LPS kernel as a pair law of for_each_bond_block(): breaks bonds by
     * (mechanical) stretch, then adds the pair sum p omega chi V_i V_j |xi| e (e = |xi| s) at
     * both ends (the dilatation before the factor n / (m_i V_i)).
     */
    template <int dim, bool thermal>
    struct LPSDilatationLaw : LPSStrain<dim, thermal>
    {
      static constexpr unsigned int n_outputs    = 1;
      static constexpr bool         breaks_bonds = true;
      /// omega chi V_i V_j per lane.
      const double *weight;

      template <typename Bond>
      void
      pair(const Bond              &bond,
           const DeformedBond<dim> &y,
           const typename StretchPairLaw<dim>::Side &,
           const BondLanes   &lanes,
           bond_simd::Vector *to_a,
           bond_simd::Vector *to_b) const
      {
        using namespace bond_simd;
        Vector p                     = 0.;
        stdx::where(lanes.active, p) = Vector(weight + lanes.first_lane, stdx::element_aligned) *
                                       y.stretch * (bond.length * bond.length);
        to_a[0] = p;
        to_b[0] = p;
      }
    };

    /**
     * @brief What the pair laws after the dilatation pass read of the particles: the weight
     * omega chi V_i V_j per lane and, in kernel order, beta theta / m, beta alpha and theta
     * (beta the energy weights), the particle side once per group (side()).
     */
    template <int dim, bool thermal>
    struct LPSStateLaw : LPSStrain<dim, thermal>
    {
      /// omega chi V_i V_j per lane.
      const double *weight;
      /// Kernel order: beta theta / m, beta alpha, theta.
      const double *theta_over_m, *alpha, *theta;

      struct Side
      {
        bond_simd::Vector theta_over_m, alpha, theta;
      };

      Side
      side(const unsigned int a) const
      {
        using namespace bond_simd;
        return {Vector(theta_over_m + a, stdx::element_aligned),
                Vector(alpha + a, stdx::element_aligned),
                Vector(theta + a, stdx::element_aligned)};
      }
    };

    /**
     * @brief Pass 2 of the LPS kernel as a pair law of for_each_bond_block(): the pair force
     * [(n k - (n + 2) mu) |xi| (theta_i / m_i + theta_j / m_j) + (alpha_i + alpha_j) e]
     * omega chi V_i V_j (xi + eta)/|xi + eta| on the particle side (its negative on the
     * neighbour) and, if @p with_energy, the deviatoric pair energies
     * alpha_i omega chi V_i V_j (e - theta_i |xi| / n)^2 / 2 at i and the same with j at j
     * (theta / m and alpha carry the particles' energy weights); with @p thermal, e and theta
     * are the mechanical ones (LPSStrain).
     */
    template <int dim, bool with_energy, bool thermal>
    struct LPSForceLaw : LPSStateLaw<dim, thermal>
    {
      static constexpr unsigned int n_outputs    = dim + (with_energy ? 1 : 0);
      static constexpr bool         breaks_bonds = false;
      using Side                                 = typename LPSStateLaw<dim, thermal>::Side;
      /// n k - (n + 2) mu.
      double dilatation_coefficient;

      template <typename Bond>
      void
      pair(const Bond              &bond,
           const DeformedBond<dim> &y,
           const Side              &i,
           const BondLanes         &lanes,
           bond_simd::Vector       *to_a,
           bond_simd::Vector       *to_b) const
      {
        using namespace bond_simd;
        const double      n = dim;
        const std::size_t b = lanes.neighbour;
        const Vector      e = bond.length * y.stretch;
        const Vector      p(this->weight + lanes.first_lane, stdx::element_aligned);
        const Vector      alpha_b(this->alpha + b, stdx::element_aligned);
        const Vector      t =
          (dilatation_coefficient * bond.length) *
            (i.theta_over_m + Vector(this->theta_over_m + b, stdx::element_aligned)) +
          (i.alpha + alpha_b) * e;
        Vector scale                     = 0.;
        stdx::where(lanes.active, scale) = t * p * (y.rho * bond.inverse_length);
        for (unsigned int d = 0; d < dim; ++d)
          {
            to_a[d] = y.r[d] * scale;
            to_b[d] = -to_a[d];
          }
        if constexpr (with_energy)
          {
            const Vector ei = e - i.theta * (bond.length / n);
            const Vector ej =
              e - Vector(this->theta + b, stdx::element_aligned) * (bond.length / n);
            Vector wi = 0., wj = 0.;
            stdx::where(lanes.active, wi) = 0.5 * i.alpha * p * ei * ei;
            stdx::where(lanes.active, wj) = 0.5 * alpha_b * p * ej * ej;
            to_a[dim]                     = wi;
            to_b[dim]                     = wj;
          }
      }
    };

    /**
     * @brief The thermoelastic measure's pair sums as a pair law of for_each_bond_block(): the
     * derivative of the energy with respect to the temperature change of each end of a bond,
     * less the particle's own term (doc/theory/thermoelasticity.md): at the particle side
     * 1/2 a p |xi| [n k (theta / m)_j |xi| + alpha_j (e - theta_j |xi| / n)] with the
     * neighbour's values, at the neighbour side the same with the particle's (theta / m and
     * alpha carry the energy weights; e the extension of the whole strain).
     */
    template <int dim>
    struct LPSMeasureLaw : LPSStateLaw<dim, false>
    {
      static constexpr unsigned int n_outputs    = 1;
      static constexpr bool         breaks_bonds = false;
      using Side                                 = typename LPSStateLaw<dim, false>::Side;
      /// n k and the in-plane expansion a.
      double dilatation_modulus, expansion;

      template <typename Bond>
      void
      pair(const Bond              &bond,
           const DeformedBond<dim> &y,
           const Side              &i,
           const BondLanes         &lanes,
           bond_simd::Vector       *to_a,
           bond_simd::Vector       *to_b) const
      {
        using namespace bond_simd;
        const double n = dim;
        const Vector e = bond.length * y.stretch;
        const Vector p(this->weight + lanes.first_lane, stdx::element_aligned);
        const Vector scale = (0.5 * expansion) * p * bond.length;
        // The derivative through each end's dilatation and deviatoric extension, with that end's
        // state.
        const auto from = [&](const Side &end) {
          return dilatation_modulus * bond.length * end.theta_over_m +
                 end.alpha * (e - end.theta * (bond.length / n));
        };
        const Vector from_a = from(i), from_b = from(this->side(lanes.neighbour));
        Vector       ma = 0., mb = 0.;
        stdx::where(lanes.active, ma) = scale * from_b;
        stdx::where(lanes.active, mb) = scale * from_a;
        to_a[0]                       = ma;
        to_b[0]                       = mb;
      }
    };
  } // namespace

  template <int dim>
  struct LinearPeridynamicSolid<dim>::Kernel
  {
    /// The bonds in SIMD blocks, and pair_weight per lane.
    BondBlocks<dim>                 blocks;
    typename BondBlocks<dim>::Array lane_weight;
    /// Kernel-order work fields of compute_forces(): displacement, force, energy density,
    /// dilatation, beta theta / m, beta alpha, beta / m (beta: the particles' energy weights) and
    /// the temperature change.
    typename BondBlocks<dim>::Array u_field, f_field, w_field, theta_field, theta_over_m_field,
      alpha_field, beta_over_m_field, delta_T_field;

    /**
     * @brief The kernel-order unknowns of the pair laws: the dim displacement components and,
     * if @p thermal, the temperature change.
     */
    template <bool thermal>
    std::array<const double *, dim + thermal>
    unknowns()
    {
      std::array<const double *, dim + thermal> u;
      for (unsigned int d = 0; d < dim; ++d)
        u[d] = blocks.component(u_field, d);
      if constexpr (thermal)
        u[dim] = blocks.component(delta_T_field, 0);
      return u;
    }

    /**
     * @brief Pass 1 (LPSDilatationLaw): bonds above @p critical_stretch break, theta_field
     * receives the pair sums; @p expansion is the thermal expansion a if @p thermal.
     */
    template <bool thermal>
    void
    dilatation_loop(BondList &bonds, const double critical_stretch, const double expansion)
    {
      const LPSDilatationLaw<dim, thermal> law{{{}, expansion}, lane_weight.data()};
      for_each_bond_block<dim + thermal, dim>(blocks,
                                              unknowns<thermal>(),
                                              {{blocks.component(theta_field, 0)}},
                                              law,
                                              bonds,
                                              critical_stretch);
    }

    /**
     * @brief Pass 2 (LPSForceLaw) with dilatation coefficient @p dilatation_coefficient; the
     * energy density is accumulated only if @p with_energy.
     */
    template <bool with_energy, bool thermal>
    void
    force_loop(BondList &bonds, const double dilatation_coefficient, const double expansion)
    {
      using Law = LPSForceLaw<dim, with_energy, thermal>;
      std::array<double *, Law::n_outputs> out;
      for (unsigned int d = 0; d < dim; ++d)
        out[d] = blocks.component(f_field, d);
      if constexpr (with_energy)
        out[dim] = blocks.component(w_field, 0);
      const Law law{{{{}, expansion},
                     lane_weight.data(),
                     blocks.component(theta_over_m_field, 0),
                     blocks.component(alpha_field, 0),
                     blocks.component(theta_field, 0)},
                    dilatation_coefficient};
      for_each_bond_block<dim + thermal, dim>(blocks, unknowns<thermal>(), out, law, bonds, 0.);
    }
  };

  template <int dim>
  LinearPeridynamicSolid<dim>::LinearPeridynamicSolid()
    : kernel(std::make_unique<Kernel>())
  {}

  template <int dim>
  LinearPeridynamicSolid<dim>::~LinearPeridynamicSolid() = default;

  template <int dim>
  void
  LinearPeridynamicSolid<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Young's modulus", "0", Patterns::Double(0.), "Young's modulus E [Pa].");
    prm.declare_entry("Poisson's ratio",
                      "0.25",
                      Patterns::Double(-1., 0.5),
                      "Poisson's ratio nu [-], in (-1, 1/2).");
    prm.declare_entry("Influence function",
                      "inverse distance",
                      Patterns::Selection(PluginRegistry<InfluenceFunction>::pattern_string()),
                      "The influence function omega(|xi|). " +
                        PluginRegistry<InfluenceFunction>::documentation());
    ThermalExpansion::declare_parameters(prm, false);
  }

  template <int dim>
  void
  LinearPeridynamicSolid<dim>::parse_parameters(ParameterHandler &prm)
  {
    const std::string prefix = "Material/linear peridynamic solid/";
    youngs_modulus           = prm.get_double("Young's modulus");
    ParameterUtilities::require_positive(youngs_modulus, prefix + "Young's modulus");
    poisson_ratio = prm.get_double("Poisson's ratio");
    AssertThrow(poisson_ratio > -1. && poisson_ratio < 0.5,
                ExcMessage("The parameter <" + prefix + "Poisson's ratio> is " +
                           ParameterUtilities::format_number(poisson_ratio) +
                           "; accepted: -1 < nu < 0.5."));
    influence_name = prm.get("Influence function");
    influence =
      PluginRegistry<InfluenceFunction>::create(influence_name, prefix + "Influence function");
    ThermalExpansion thermal_expansion;
    thermal_expansion.parse_parameters(prm, "Material/linear peridynamic solid", false);
    expansion = thermal_expansion.coefficient();
  }

  template <int dim>
  void
  LinearPeridynamicSolid<dim>::initialize(ParticleSystem<dim> &particles,
                                          const ModelContext  &model_context)
  {
    context        = model_context;
    const double E = youngs_modulus, nu = poisson_ratio;
    shear_modulus       = E / (2. * (1. + nu));
    const double lambda = E * nu / ((1. + nu) * (1. - 2. * nu));
    switch (context.planar)
      {
        case PlanarAssumption::three_dimensional:
          bulk_modulus = lambda + 2. * shear_modulus / 3.;
          break;
        case PlanarAssumption::plane_strain:
          bulk_modulus = lambda + shear_modulus;
          break;
        case PlanarAssumption::plane_stress:
          bulk_modulus = E / (2. * (1. - nu));
          break;
      }
    // The free in-plane strain per kelvin: in plane strain the suppressed expansion out of the
    // plane adds nu alpha in the plane (planar_thermal_expansion() of an isotropic material).
    planar_expansion =
      context.planar == PlanarAssumption::plane_strain ? (1. + nu) * expansion : expansion;

    const BondList &bonds  = particles.bonds();
    const auto     &volume = particles.volumes();
    pair_weight.resize(bonds.size());
    for (unsigned int i = 0; i < particles.n_owned(); ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        pair_weight[b] = influence->value(bonds.length[b], context.horizon) *
                         bonds.volume_factor(b) * volume[i] * volume[bonds.neighbor[b]];
    Kernel &k = *kernel;
    k.blocks.reinit(particles);
    k.blocks.to_lanes(pair_weight, k.lane_weight);
    for (auto *field : {&k.u_field, &k.f_field})
      k.blocks.reinit_field(*field, dim);
    for (auto *field : {&k.w_field,
                        &k.theta_field,
                        &k.theta_over_m_field,
                        &k.alpha_field,
                        &k.beta_over_m_field,
                        &k.delta_T_field})
      k.blocks.reinit_field(*field, 1);

    // Each particle's own discrete weighted volume m_i = sum_j omega |xi|^2 V_j beta, with or
    // without surface correction: only with it are the forces the gradient of the energy
    // (doc/theory/models.md).
    particles.reinit_vector(weighted_volume, 1);
    particles.reinit_vector(theta, 1);
    for (unsigned int i = 0; i < particles.n_owned(); ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        {
          const unsigned int j  = bonds.neighbor[b];
          const double       r2 = bonds.length[b] * bonds.length[b];
          weighted_volume.local_element(i) += pair_weight[b] * r2 / volume[i];
          if (j < particles.n_owned())
            weighted_volume.local_element(j) += pair_weight[b] * r2 / volume[j];
        }
    weighted_volume.update_ghost_values();
    const double n       = dim;
    const double alpha_m = shear_modulus * n * (n + 2.);
    alpha.resize(particles.n_local());
    for (unsigned int i = 0; i < particles.n_local(); ++i)
      alpha[i] = alpha_m / weighted_volume.local_element(i);
    // The kernels work with the particles' force states weighted by their energy weights
    // beta_i (E = sum_i beta_i W_i V_i): beta alpha and beta theta / m.
    const auto         &beta = particles.energy_weights();
    std::vector<double> weighted(particles.n_local());
    for (unsigned int i = 0; i < particles.n_local(); ++i)
      weighted[i] = beta[i] * alpha[i];
    k.blocks.gather(weighted.data(), 1, k.alpha_field);
    for (unsigned int i = 0; i < particles.n_local(); ++i)
      weighted[i] = beta[i] / weighted_volume.local_element(i);
    k.blocks.gather(weighted.data(), 1, k.beta_over_m_field);
    fracture_factor = 1.;
    if (context.lattice_fracture)
      {
        // Not a sum of bond energies: a mode I cleave of a box of the same lattice measures what
        // the continuum's critical stretch of 1 J/m^2 dissipates.
        LinearPeridynamicSolid<dim> probe;
        probe.youngs_modulus = youngs_modulus;
        probe.poisson_ratio  = poisson_ratio;
        probe.influence_name = influence_name;
        probe.influence      = PluginRegistry<InfluenceFunction>::create(
          influence_name,
          "Material/linear peridynamic solid/Influence function");
        ModelContext probe_context     = context;
        probe_context.lattice_fracture = false;
        fracture_factor = 1. / std::sqrt(cleave_fracture_energy<dim>(particles.settings(),
                                                                     probe,
                                                                     probe_context,
                                                                     critical_stretch(1.),
                                                                     particles.get_communicator()));
      }
  }

  template <int dim>
  void
  LinearPeridynamicSolid<dim>::compute_forces(ParticleSystem<dim>  &particles,
                                              const ParticleVector &u,
                                              ParticleVector       &force,
                                              std::vector<double>  *energy_density,
                                              const double          critical_stretch)
  {
    Kernel            &k       = *kernel;
    BondList          &bonds   = particles.bonds();
    const double      *volume  = particles.volumes().data();
    const unsigned int n_owned = particles.n_owned();
    const double       n       = dim;
    k.blocks.sync_state(bonds);
    k.blocks.gather(u.begin(), dim, k.u_field);
    // With a temperature change, the separate instantiation of the laws that measures the
    // extensions from the thermal ones; without one, the kernel of the purely mechanical model.
    const ParticleVector *delta_T = this->temperature_change();
    const bool            thermal = delta_T != nullptr && planar_expansion != 0.;
    if (thermal)
      k.blocks.gather(delta_T->begin(), 1, k.delta_T_field);

    dilatation_pass(particles, critical_stretch, thermal);

    // Pass 2: forces (and energy), summed per particle and divided by V_i.
    const double dilatation_coefficient = n * bulk_modulus - (n + 2.) * shear_modulus;
    std::fill(k.f_field.begin(), k.f_field.end(), 0.);
    if (energy_density != nullptr)
      std::fill(k.w_field.begin(), k.w_field.end(), 0.);
    if (energy_density != nullptr && thermal)
      k.template force_loop<true, true>(bonds, dilatation_coefficient, planar_expansion);
    else if (energy_density != nullptr)
      k.template force_loop<true, false>(bonds, dilatation_coefficient, 0.);
    else if (thermal)
      k.template force_loop<false, true>(bonds, dilatation_coefficient, planar_expansion);
    else
      k.template force_loop<false, false>(bonds, dilatation_coefficient, 0.);
    k.blocks.scatter_owned(k.f_field, dim, volume, force.begin());
    if (energy_density != nullptr)
      {
        energy_density->resize(n_owned);
        k.blocks.scatter_owned(k.w_field, 1, volume, energy_density->data());
        const auto &beta = particles.energy_weights();
        for (unsigned int i = 0; i < n_owned; ++i)
          (*energy_density)[i] +=
            beta[i] * 0.5 * bulk_modulus * theta.local_element(i) * theta.local_element(i);
      }
  }

  template <int dim>
  void
  LinearPeridynamicSolid<dim>::dilatation_pass(ParticleSystem<dim> &particles,
                                               const double         critical_stretch,
                                               const bool           thermal)
  {
    // Pass 1: break overstretched bonds (mechanical stretch above the critical stretch), then
    // the dilatation from the pair sums, divided by V_i; theta / m for pass 2.
    Kernel            &k       = *kernel;
    BondList          &bonds   = particles.bonds();
    const double      *volume  = particles.volumes().data();
    const unsigned int n_owned = particles.n_owned();
    const double      *m       = weighted_volume.begin();
    const double       n       = dim;
    std::fill(k.theta_field.begin(), k.theta_field.end(), 0.);
    if (thermal)
      k.template dilatation_loop<true>(bonds, critical_stretch, planar_expansion);
    else
      k.template dilatation_loop<false>(bonds, critical_stretch, 0.);
    double *theta_owned = theta.begin();
    k.blocks.scatter_owned(k.theta_field, 1, nullptr, theta_owned);
    for (unsigned int i = 0; i < n_owned; ++i)
      theta_owned[i] *= n / (m[i] * volume[i]);
    theta.update_ghost_values();
    k.blocks.gather(theta.begin(), 1, k.theta_field);
    for (std::size_t q = 0; q < k.theta_field.size(); ++q)
      k.theta_over_m_field[q] = k.theta_field[q] * k.beta_over_m_field[q];
  }

  template <int dim>
  void
  LinearPeridynamicSolid<dim>::thermoelastic_measure(ParticleSystem<dim>  &particles,
                                                     const ParticleVector &u,
                                                     std::vector<double>  &measure)
  {
    Kernel            &k       = *kernel;
    const unsigned int n_owned = particles.n_owned();
    const double       n       = dim;
    k.blocks.sync_state(particles.bonds());
    k.blocks.gather(u.begin(), dim, k.u_field);
    // The dilatation of the whole strain (no bond breaks here).
    dilatation_pass(particles, std::numeric_limits<double>::infinity(), false);
    std::fill(k.w_field.begin(), k.w_field.end(), 0.);
    const LPSMeasureLaw<dim> law{{{{}, 0.},
                                  k.lane_weight.data(),
                                  k.blocks.component(k.theta_over_m_field, 0),
                                  k.blocks.component(k.alpha_field, 0),
                                  k.blocks.component(k.theta_field, 0)},
                                 n * bulk_modulus,
                                 planar_expansion};
    for_each_bond_block<dim, dim>(k.blocks,
                                  k.template unknowns<false>(),
                                  {{k.blocks.component(k.w_field, 0)}},
                                  law,
                                  particles.bonds(),
                                  0.);
    measure.resize(n_owned);
    k.blocks.scatter_owned(k.w_field, 1, particles.volumes().data(), measure.data());
    // The particle's own term: the derivative of k theta_i^2 / 2 through the thermal dilatation's
    // share 1/2 of every bond of the particle.
    const auto &beta = particles.energy_weights();
    for (unsigned int i = 0; i < n_owned; ++i)
      measure[i] += 0.5 * n * planar_expansion * bulk_modulus * beta[i] * theta.local_element(i);
  }

  template <int dim>
  SymmetricTensor<4, dim>
  LinearPeridynamicSolid<dim>::elasticity_tensor() const
  {
    return isotropic_elasticity_tensor<dim>(youngs_modulus, poisson_ratio, context.planar);
  }

  template <int dim>
  SymmetricTensor<2, dim>
  LinearPeridynamicSolid<dim>::thermal_expansion() const
  {
    return planar_expansion * unit_symmetric_tensor<dim>();
  }

  template <int dim>
  double
  LinearPeridynamicSolid<dim>::critical_stretch(const double fracture_energy) const
  {
    const double G = fracture_energy, mu = shear_modulus, k = bulk_modulus, delta = context.horizon,
                 pi = numbers::PI;
    if (dim == 3)
      return fracture_factor *
             std::sqrt(G / ((3. * mu + std::pow(0.75, 4) * (k - 5. * mu / 3.)) * delta));
    return fracture_factor *
           std::sqrt(G / ((6. * mu / pi + 16. / (9. * pi * pi) * (k - 2. * mu)) * delta));
  }

  template <int dim>
  unsigned int
  LinearPeridynamicSolid<dim>::force_reach() const
  {
    return 2;
  }

  template <int dim>
  std::string
  LinearPeridynamicSolid<dim>::summary() const
  {
    std::ostringstream out;
    out << "linear peridynamic solid: E = " << youngs_modulus << " Pa, nu = " << poisson_ratio
        << ", bulk modulus k = " << bulk_modulus << " Pa, shear modulus mu = " << shear_modulus
        << " Pa, influence function '" << influence_name << "'";
    if (expansion != 0.)
      {
        out << ", thermal expansion alpha = " << expansion << " 1/K";
        if (context.planar == PlanarAssumption::plane_strain)
          out << " (in the plane (1 + nu) alpha = " << planar_expansion << " 1/K)";
      }
    if (context.lattice_fracture)
      out << "; lattice calibration of the fracture energy: critical stretch " << fracture_factor
          << " times the continuum's";
    return out.str();
  }

  template <int dim>
  const ParticleVector &
  LinearPeridynamicSolid<dim>::dilatation() const
  {
    return theta;
  }

  template <int dim>
  ModelCapabilities
  LinearPeridynamicSolid<dim>::capabilities() const
  {
    ModelCapabilities capabilities;
    capabilities.sequentially_linear   = true;
    capabilities.lattice_fracture      = true;
    capabilities.thermal_strain        = true;
    capabilities.thermoelastic_heating = true;
    return capabilities;
  }

  template class LinearPeridynamicSolid<2>;
  template class LinearPeridynamicSolid<3>;
} // namespace perideal

PERIDEAL_REGISTER_MATERIAL_MODEL(perideal::LinearPeridynamicSolid,
                                 "linear peridynamic solid",
                                 "ordinary state-based linear peridynamic solid (LPS), any nu.")
