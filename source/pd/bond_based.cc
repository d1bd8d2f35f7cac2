// ---------------------------------------------------------------------
// PeriDeal: the prototype microelastic brittle (PMB) bond-based model.
// ---------------------------------------------------------------------
#include <deal.II/base/numbers.h>
#include <deal.II/base/tensor.h>

#include <perideal/base/parameter_utilities.h>
#include <perideal/pd/bond_based.h>
#include <perideal/pd/bond_loop.h>
#include <perideal/pd/lattice_fracture.h>
#include <perideal/pd/surface_correction.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace perideal
{
  using namespace dealii;

  namespace
  {
    /**
     * @brief The PMB pair law of for_each_bond_block(): pair force F = k s (xi + eta)/|xi + eta|
     * on the particle side (-F on the neighbour) and, if @p with_energy, the pair energy
     * k s^2 |xi| / 4 at both ends, with k = c G chi V_i V_j per lane; breaks bonds by stretch.
     * With @p thermal, s is the mechanical stretch s - alpha Delta T_b (Delta T_b the bond's
     * mean temperature change, the loop's input dim: bond_temperature_change()); without, the
     * law is today's, instantiated apart (no per-lane branch).
     */
    template <int dim, bool with_energy, bool thermal>
    struct PMBPairLaw : StretchPairLaw<dim>
    {
      static constexpr unsigned int n_outputs    = dim + (with_energy ? 1 : 0);
      static constexpr bool         breaks_bonds = true;
      /// k per lane.
      const double *coefficient;
      /// The thermal expansion alpha of the bonds (thermal only).
      double expansion;

      /// The deformed bond, its stretch less the thermal stretch if thermal.
      template <typename Bond>
      DeformedBond<dim>
      strain(const Bond              &bond,
             const std::size_t        first_lane,
             const bond_simd::Vector *u_a,
             const bond_simd::Vector *u_b) const
      {
        DeformedBond<dim> y = StretchPairLaw<dim>::strain(bond, first_lane, u_a, u_b);
        if constexpr (thermal)
          y.stretch -= expansion * bond_temperature_change(u_a, u_b, dim);
        return y;
      }

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
        const Vector k(coefficient + lanes.first_lane, stdx::element_aligned);
        Vector       t               = 0.;
        stdx::where(lanes.active, t) = k * y.stretch * (y.rho * bond.inverse_length);
        for (unsigned int d = 0; d < dim; ++d)
          {
            to_a[d] = y.r[d] * t;
            to_b[d] = -to_a[d];
          }
        if constexpr (with_energy)
          {
            Vector e                     = 0.;
            stdx::where(lanes.active, e) = (0.25 * bond.length) * k * y.stretch * y.stretch;
            to_a[dim]                    = e;
            to_b[dim]                    = e;
          }
      }
    };

    /**
     * @brief The thermoelastic measure of for_each_bond_block(): 1/2 k alpha s |xi| at both ends
     * of each intact bond (the stretch of the whole strain, k = c G chi V_i V_j per lane), the
     * part of the pair energy's derivative with respect to Delta T_b that each end takes.
     */
    template <int dim>
    struct PMBMeasureLaw : StretchPairLaw<dim>
    {
      static constexpr unsigned int n_outputs    = 1;
      static constexpr bool         breaks_bonds = false;
      /// k per lane.
      const double *coefficient;
      /// The thermal expansion alpha of the bonds.
      double expansion;

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
        const Vector k(coefficient + lanes.first_lane, stdx::element_aligned);
        Vector       m               = 0.;
        stdx::where(lanes.active, m) = (0.5 * expansion * bond.length) * k * y.stretch;
        to_a[0]                      = m;
        to_b[0]                      = m;
      }
    };
  } // namespace

  template <int dim>
  struct BondBased<dim>::Kernel
  {
    /// The bonds in SIMD blocks, and the pair coefficient per lane (the one copy: the model
    /// keeps none per bond).
    BondBlocks<dim>                 blocks;
    typename BondBlocks<dim>::Array lane_coefficient;
    /// With softening, the intact bonds' coefficients per lane (lane_coefficient is mu_t times
    /// them); empty without.
    typename BondBlocks<dim>::Array intact_coefficient;
    /// Kernel-order work fields: displacement, force, energy density, and the temperature
    /// change (sized on its first use).
    typename BondBlocks<dim>::Array u_field, f_field, w_field, t_field;

    /**
     * @brief The force loop of PMBPairLaw; the energy density is accumulated only if
     * @p with_energy; with @p thermal, the stretch is measured from the thermal stretch
     * @p expansion Delta T_b of the temperature change @p delta_T (kernel order).
     */
    template <bool with_energy, bool thermal>
    void
    force_loop(BondList     &bonds,
               const double  critical_stretch,
               const double  expansion,
               const double *delta_T)
    {
      using Law                                    = PMBPairLaw<dim, with_energy, thermal>;
      constexpr unsigned int               n_input = dim + (thermal ? 1 : 0);
      std::array<const double *, n_input>  u;
      std::array<double *, Law::n_outputs> out;
      for (unsigned int d = 0; d < dim; ++d)
        {
          u[d]   = blocks.component(u_field, d);
          out[d] = blocks.component(f_field, d);
        }
      if constexpr (thermal)
        u[dim] = delta_T;
      if constexpr (with_energy)
        out[dim] = blocks.component(w_field, 0);
      for_each_bond_block<n_input>(blocks,
                                   u,
                                   out,
                                   Law{{}, lane_coefficient.data(), expansion},
                                   bonds,
                                   critical_stretch);
    }
  };

  template <int dim>
  BondBased<dim>::BondBased()
    : kernel(std::make_unique<Kernel>())
  {}

  template <int dim>
  BondBased<dim>::~BondBased() = default;

  template <int dim>
  void
  BondBased<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Young's modulus",
                      "0",
                      Patterns::Double(0.),
                      "Young's modulus E [Pa]. The model implies nu = 1/4 in 3D and plane strain, "
                      "nu = 1/3 in plane stress.");
    ThermalExpansion::declare_parameters(prm, false);
  }

  template <int dim>
  void
  BondBased<dim>::parse_parameters(ParameterHandler &prm)
  {
    youngs_modulus = prm.get_double("Young's modulus");
    ParameterUtilities::require_positive(youngs_modulus, "Material/bond based/Young's modulus");
    expansion.parse_parameters(prm, "Material/bond based", false);
  }

  template <int dim>
  double
  BondBased<dim>::implied_poisson_ratio() const
  {
    return context.planar == PlanarAssumption::plane_stress ? 1. / 3. : 0.25;
  }

  template <int dim>
  double
  BondBased<dim>::micromodulus() const
  {
    return c;
  }

  template <int dim>
  void
  BondBased<dim>::initialize(ParticleSystem<dim> &particles, const ModelContext &model_context)
  {
    context            = model_context;
    const double delta = context.horizon, E = youngs_modulus, pi = numbers::PI;
    switch (context.planar)
      {
        case PlanarAssumption::three_dimensional:
          c = 12. * E / (pi * std::pow(delta, 4));
          break;
        case PlanarAssumption::plane_stress:
          c = 9. * E / (pi * context.thickness * std::pow(delta, 3));
          break;
        case PlanarAssumption::plane_strain:
          c = 48. * E / (5. * pi * context.thickness * std::pow(delta, 3));
          break;
      }
    // The surface factors go straight into the lane coefficients (pair_coefficient()): the
    // model keeps none per bond, and frees the bond list's before the blocks are built.
    BondBlocks<dim> &blocks = kernel->blocks;
    BondList        &bonds  = particles.bonds();
    bonds.surface_factor    = std::vector<double>();
    blocks.reinit(particles);
    blocks.reinit_field(kernel->u_field, dim);
    blocks.reinit_field(kernel->f_field, dim);
    blocks.reinit_field(kernel->w_field, 1);
    kernel->t_field.clear();
    fit_report           = apply_surface_correction<dim>(*this,
                                               particles,
                                               context,
                                               [&](const SurfaceFactors &surface_factor) {
                                                 set_bond_coefficients(particles, surface_factor);
                                               });
    bonds.surface_factor = std::vector<double>();
    tooth.clear();
    kernel->intact_coefficient.clear();
    softened_energy = 0.;
    if (context.softening.law() == BondFailure::linear_softening)
      {
        tooth.assign(bonds.size(), 0);
        kernel->intact_coefficient = kernel->lane_coefficient;
      }
    // The softening bond's work to break is the brittle bond's, so the calibration is the same.
    fracture_factor = 1.;
    if (context.lattice_fracture)
      {
        // A bond at the critical stretch s0 holds k s0^2 |xi| / 2.
        const double s0          = critical_stretch(1.);
        const auto   coefficient = pair_coefficients(particles);
        fracture_factor          = lattice_fracture_factor<dim>(
          particles,
          [&coefficient](const unsigned int, const std::size_t b) { return coefficient(b); },
          [s0](double r) { return 0.5 * s0 * s0 * r; });
      }
  }

  template <int dim>
  double
  BondBased<dim>::pair_coefficient(const ParticleSystem<dim> &particles,
                                   const unsigned int         i,
                                   const std::size_t          b) const
  {
    return kernel->lane_coefficient[kernel->blocks.lane_of(particles.bonds(), i, b)];
  }

  template <int dim>
  typename BondBased<dim>::PairCoefficients
  BondBased<dim>::pair_coefficients(const ParticleSystem<dim> &particles) const
  {
    PairCoefficients coefficients;
    coefficients.coefficient = kernel->lane_coefficient.data();
    // The lanes are those of the particles the model was initialized on; a system without
    // bonds (the empty particle part of the FE solve of the Schwarz method) has none to find.
    if (particles.bonds().size() > 0)
      kernel->blocks.lanes_of_bonds(particles.bonds().size(), coefficients.lane);
    return coefficients;
  }

  template <int dim>
  std::unique_ptr<SurfaceCorrectionLaw<dim>>
  BondBased<dim>::surface_correction_law(ParticleSystem<dim> &particles)
  {
    auto law = elastic_surface_correction_law<dim>(*this, particles, [this, &particles]() {
      set_bond_coefficients(particles, {});
    });
    // Per end and unit chi V_i V_j, c |xi| (n.e.n)^2 / 4 under a homogeneous strain.
    const double micromodulus = c;
    law->stiffness = [micromodulus](const Tensor<1, dim> &xi, double &axial, double &shear) {
      axial = 0.5 * micromodulus * xi.norm();
      shear = 0.;
    };
    return law;
  }

  template <int dim>
  void
  BondBased<dim>::set_bond_coefficients(
    const ParticleSystem<dim>                                          &particles,
    const std::function<double(const unsigned int, const std::size_t)> &surface_factor)
  {
    const BondList &bonds  = particles.bonds();
    const auto     &volume = particles.volumes();
    kernel->blocks.to_lanes(
      bonds,
      [&](const unsigned int i, const std::size_t b) {
        // bond_pair_coefficient() with the factor G of the correction.
        const unsigned int j = bonds.neighbor[b];
        return surface_factor ? c * (surface_factor(i, b) * particles.bond_energy_weight(i, j)) *
                                  bonds.volume_factor(b) * volume[i] * volume[j] :
                                bond_pair_coefficient(particles, c, false, i, b);
      },
      kernel->lane_coefficient);
  }

  template <int dim>
  void
  BondBased<dim>::compute_forces(ParticleSystem<dim>  &particles,
                                 const ParticleVector &u,
                                 ParticleVector       &force,
                                 std::vector<double>  *energy_density,
                                 const double          critical_stretch)
  {
    AssertThrow(tooth.empty() || !std::isfinite(critical_stretch),
                ExcMessage("<Material/critical stretch/Failure law> = linear softening runs with "
                           "<Solver/Control/Method> = sequentially linear only (its saw teeth "
                           "are events of that control); for load steps or explicit dynamics "
                           "use Failure law = brittle."));
    Kernel               &k       = *kernel;
    const ParticleVector *delta_T = this->temperature_change();
    const double         *t_field =
      delta_T != nullptr ? gather_temperature_change(k.blocks, *delta_T, k.t_field) : nullptr;
    const double alpha = bond_expansion();
    evaluate_bond_kernel<dim>(
      k.blocks,
      particles,
      u,
      dim,
      k.u_field,
      k.f_field,
      k.w_field,
      force,
      energy_density,
      [&](auto with_energy) {
        constexpr bool e = decltype(with_energy)::value;
        if (t_field != nullptr)
          k.template force_loop<e, true>(particles.bonds(), critical_stretch, alpha, t_field);
        else
          k.template force_loop<e, false>(particles.bonds(), critical_stretch, 0., nullptr);
      });
  }

  template <int dim>
  void
  BondBased<dim>::thermoelastic_measure(ParticleSystem<dim>  &particles,
                                        const ParticleVector &u,
                                        std::vector<double>  &measure)
  {
    Kernel &k = *kernel;
    evaluate_bond_measure<dim>(k.blocks,
                               particles,
                               u,
                               k.u_field,
                               k.w_field,
                               PMBMeasureLaw<dim>{{}, k.lane_coefficient.data(), bond_expansion()},
                               measure);
  }

  template <int dim>
  double
  BondBased<dim>::bond_expansion() const
  {
    // The free in-plane strain per kelvin (planar_thermal_expansion() of the implied nu).
    return context.planar == PlanarAssumption::plane_strain ?
             (1. + implied_poisson_ratio()) * expansion.coefficient() :
             expansion.coefficient();
  }

  template <int dim>
  SymmetricTensor<2, dim>
  BondBased<dim>::thermal_expansion() const
  {
    return bond_expansion() * unit_symmetric_tensor<dim>();
  }

  template <int dim>
  double
  BondBased<dim>::thermal_stretch(const ParticleSystem<dim> &particles, const std::size_t b) const
  {
    const ParticleVector *delta_T = this->temperature_change();
    if (delta_T == nullptr)
      return 0.;
    const BondList &bonds = particles.bonds();
    return bond_expansion() * 0.5 *
           (delta_T->local_element(bonds.row_of(b)) + delta_T->local_element(bonds.neighbor[b]));
  }

  template <int dim>
  double
  BondBased<dim>::mechanical_stretch(const ParticleSystem<dim> &particles,
                                     const ParticleVector      &u,
                                     const std::size_t          b) const
  {
    const BondList    &bonds = particles.bonds();
    const auto        &x     = particles.positions();
    const unsigned int i     = bonds.row_of(b);
    const unsigned int j     = bonds.neighbor[b];
    Tensor<1, dim>     r     = x[j] - x[i];
    for (unsigned int d = 0; d < dim; ++d)
      r[d] += u.local_element(j * dim + d) - u.local_element(i * dim + d);
    return r.norm() / bonds.length[b] - 1. - thermal_stretch(particles, b);
  }

  template <int dim>
  double
  BondBased<dim>::released_energy(ParticleSystem<dim> &particles, const ParticleVector &u)
  {
    BondList &bonds    = particles.bonds();
    double    released = softened_energy;
    softened_energy    = 0.;
    for (const unsigned int b : bonds.newly_broken)
      {
        // The pair coefficient of the bond's particle: the row of the bond list that holds it.
        const double s = mechanical_stretch(particles, u, b);
        released += particles.bond_share(b) * 0.5 *
                    pair_coefficient(particles, bonds.row_of(b), b) * s * s * bonds.length[b];
      }
    bonds.newly_broken.clear();
    return released;
  }

  template <int dim>
  std::vector<double>
  BondBased<dim>::breaking_factors(const ParticleSystem<dim> &particles) const
  {
    std::vector<double> factor(particles.bonds().size(), 1.);
    for (std::size_t b = 0; b < tooth.size(); ++b)
      factor[b] = 1. / context.softening.drop_over_brittle(tooth[b]);
    return factor;
  }

  template <int dim>
  bool
  BondBased<dim>::bond_breaks_at_limit(const std::size_t b) const
  {
    return tooth.empty() || tooth[b] + 1u >= context.softening.teeth();
  }

  template <int dim>
  void
  BondBased<dim>::limit_reached(ParticleSystem<dim>  &particles,
                                const ParticleVector &u,
                                const std::size_t     b)
  {
    if (bond_breaks_at_limit(b))
      {
        MaterialModel<dim>::limit_reached(particles, u, b);
        return;
      }
    BondList    &bonds = particles.bonds();
    const double s     = mechanical_stretch(particles, u, b);
    const auto   lane  = kernel->blocks.lane_of(bonds, bonds.row_of(b), b);
    const double k     = kernel->intact_coefficient[lane];
    const double mu    = context.softening.secant_factor(tooth[b]);
    const double next  = context.softening.secant_factor(tooth[b] + 1u);
    softened_energy += particles.bond_share(b) * 0.5 * (mu - next) * k * s * s * bonds.length[b];
    ++tooth[b];
    kernel->lane_coefficient[lane] = next * k;
  }

  template <int dim>
  unsigned int
  BondBased<dim>::n_bond_history_values() const
  {
    return tooth.empty() ? 0 : 1;
  }

  template <int dim>
  std::vector<double>
  BondBased<dim>::bond_history(const ParticleSystem<dim> &) const
  {
    return std::vector<double>(tooth.begin(), tooth.end());
  }

  template <int dim>
  void
  BondBased<dim>::set_bond_history(const ParticleSystem<dim> &particles,
                                   const std::vector<double> &values)
  {
    const std::size_t n_bonds = particles.bonds().size();
    AssertDimension(values.size(), n_bond_history_values() * n_bonds);
    if (tooth.empty())
      return;
    std::vector<double> mu(n_bonds);
    for (std::size_t b = 0; b < n_bonds; ++b)
      {
        tooth[b] = static_cast<std::uint8_t>(values[b]);
        mu[b]    = context.softening.secant_factor(tooth[b]);
      }
    kernel->blocks.to_lanes(mu, kernel->lane_coefficient);
    for (std::size_t l = 0; l < kernel->lane_coefficient.size(); ++l)
      kernel->lane_coefficient[l] *= kernel->intact_coefficient[l];
  }

  template <int dim>
  SymmetricTensor<4, dim>
  BondBased<dim>::elasticity_tensor() const
  {
    return isotropic_elasticity_tensor<dim>(youngs_modulus,
                                            implied_poisson_ratio(),
                                            context.planar);
  }

  template <int dim>
  double
  BondBased<dim>::critical_stretch(const double fracture_energy) const
  {
    const double G = fracture_energy, E = youngs_modulus, delta = context.horizon, pi = numbers::PI;
    switch (context.planar)
      {
        case PlanarAssumption::three_dimensional:
          return fracture_factor * std::sqrt(5. * G / (6. * E * delta));
        case PlanarAssumption::plane_stress:
          return fracture_factor * std::sqrt(4. * pi * G / (9. * E * delta));
        case PlanarAssumption::plane_strain:
          return fracture_factor * std::sqrt(5. * pi * G / (12. * E * delta));
      }
    return 0.;
  }

  template <int dim>
  ModelCapabilities
  BondBased<dim>::capabilities() const
  {
    ModelCapabilities capabilities;
    capabilities.stiffness_fit         = true;
    capabilities.sequentially_linear   = true;
    capabilities.lattice_fracture      = true;
    capabilities.thermal_strain        = true;
    capabilities.thermoelastic_heating = true;
    capabilities.bond_softening        = true;
    return capabilities;
  }

  template <int dim>
  std::string
  BondBased<dim>::summary() const
  {
    std::ostringstream out;
    out << "bond based (PMB): E = " << youngs_modulus << " Pa, implied Poisson ratio "
        << implied_poisson_ratio() << ", micromodulus c = " << c << " N/m^6";
    if (context.surface_correction && context.stiffness_fit)
      out << "; " << fit_report.summary();
    if (context.lattice_fracture)
      out << "; lattice calibration of the fracture energy: critical stretch " << fracture_factor
          << " times the continuum's";
    if (!tooth.empty())
      out << "; bonds: " << context.softening.summary();
    if (!expansion.is_zero())
      out << "; thermal expansion " << expansion.summary()
          << (context.planar == PlanarAssumption::plane_strain ?
                ", in plane (1 + nu) alpha = " + std::to_string(bond_expansion()) + " 1/K" :
                std::string());
    return out.str();
  }

  template class BondBased<2>;
  template class BondBased<3>;
} // namespace perideal

PERIDEAL_REGISTER_MATERIAL_MODEL(perideal::BondBased,
                                 "bond based",
                                 "prototype microelastic brittle (PMB) bond-based model; "
                                 "nu = 1/4 (3D, plane strain) or 1/3 (plane stress).")
