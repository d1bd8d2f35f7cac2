// ---------------------------------------------------------------------
// PeriDeal: anisotropic linearized bond-based PD in 3D and 2D (seed 004).
// ---------------------------------------------------------------------
#include <deal.II/base/numbers.h>
#include <deal.II/base/point.h>

#include <perideal/base/parameter_utilities.h>
#include <perideal/pd/anisotropic_bond_based.h>
#include <perideal/pd/bond_loop.h>
#include <perideal/pd/surface_correction.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace perideal
{
  using namespace dealii;
  namespace am = anisotropic_micromodulus;

  namespace
  {
    const std::string section = "Material/anisotropic bond based";

    /**
     * @brief The linearized stretch s = xi . eta / |xi|^2 of the lanes and the `stretch` that
     * breaks a bond, s times the bond's breaking factor sqrt(|c_b| / (c_mean g_b)).
     */
    struct LinearStretch
    {
      bond_simd::Vector s, stretch;
    };

    /**
     * @brief The pair law of the linearized bond (StretchPairLaw's side, its own strain): pair
     * force k s n on the particle side (-k s n on the neighbour), k = c(n) G chi V_i V_j per lane,
     * and, if @p with_energy, the pair energy k s^2 |xi| / 4 at both ends; if @p breaks, a bond
     * breaks where s times its factor (per lane) exceeds the reference critical stretch. With
     * @p thermal, s is the mechanical stretch, less n . alpha . n Delta T_b (per lane, Delta T_b
     * the bond's mean temperature change, the loop's input dim: bond_temperature_change()).
     */
    template <int dim, bool with_energy, bool breaks, bool thermal>
    struct LinearizedPairLaw : StretchPairLaw<dim>
    {
      static constexpr unsigned int n_outputs    = dim + (with_energy ? 1 : 0);
      static constexpr bool         breaks_bonds = breaks;
      /// k and the breaking factor per lane.
      const double *coefficient;
      const double *break_factor;
      /// n . alpha . n per lane (thermal only).
      const double *expansion;

      /// The linearized stretch (hides StretchPairLaw's deformed bond).
      template <typename Bond>
      LinearStretch
      strain(const Bond              &bond,
             const std::size_t        first_lane,
             const bond_simd::Vector *u_a,
             const bond_simd::Vector *u_b) const
      {
        using namespace bond_simd;
        Vector e = 0.;
        for (unsigned int d = 0; d < dim; ++d)
          e += bond.xi[d] * (u_b[d] - u_a[d]);
        Vector s = e * (bond.inverse_length * bond.inverse_length);
        if constexpr (thermal)
          s -= Vector(expansion + first_lane, stdx::element_aligned) *
               bond_temperature_change(u_a, u_b, dim);
        if constexpr (breaks)
          return {s, s * Vector(break_factor + first_lane, stdx::element_aligned)};
        else
          return {s, s};
      }

      template <typename Bond>
      void
      pair(const Bond          &bond,
           const LinearStretch &y,
           const typename StretchPairLaw<dim>::Side &,
           const BondLanes   &lanes,
           bond_simd::Vector *to_a,
           bond_simd::Vector *to_b) const
      {
        using namespace bond_simd;
        const Vector k(coefficient + lanes.first_lane, stdx::element_aligned);
        Vector       t               = 0.;
        stdx::where(lanes.active, t) = k * y.s * bond.inverse_length;
        for (unsigned int d = 0; d < dim; ++d)
          {
            to_a[d] = bond.xi[d] * t;
            to_b[d] = -to_a[d];
          }
        if constexpr (with_energy)
          {
            Vector e                     = 0.;
            stdx::where(lanes.active, e) = (0.25 * bond.length) * k * y.s * y.s;
            to_a[dim]                    = e;
            to_b[dim]                    = e;
          }
      }
    };

    /**
     * @brief The thermoelastic measure of for_each_bond_block(): 1/2 k (n . alpha . n) s |xi|
     * at both ends of each intact bond (s the linearized stretch of the whole strain), the part
     * of the pair energy's derivative with respect to Delta T_b that each end takes (as PMB's,
     * with the bond's own expansion).
     */
    template <int dim>
    struct LinearizedMeasureLaw : LinearizedPairLaw<dim, false, false, false>
    {
      static constexpr unsigned int n_outputs = 1;

      template <typename Bond>
      void
      pair(const Bond          &bond,
           const LinearStretch &y,
           const typename StretchPairLaw<dim>::Side &,
           const BondLanes   &lanes,
           bond_simd::Vector *to_a,
           bond_simd::Vector *to_b) const
      {
        using namespace bond_simd;
        const Vector k(this->coefficient + lanes.first_lane, stdx::element_aligned);
        const Vector alpha(this->expansion + lanes.first_lane, stdx::element_aligned);
        Vector       m               = 0.;
        stdx::where(lanes.active, m) = (0.5 * bond.length) * k * alpha * y.s;
        to_a[0]                      = m;
        to_b[0]                      = m;
      }
    };
  } // namespace

  template <int dim>
  struct AnisotropicBondBased<dim>::Kernel
  {
    /// The bonds in SIMD blocks, bond_coefficient and the breaking factor
    /// sqrt(|c_b| / (c_mean g_b)) per lane (g_b: the weight of the fracture energies), and
    /// bond_expansion per lane (empty without a thermal expansion).
    BondBlocks<dim>                 blocks;
    typename BondBlocks<dim>::Array lane_coefficient, lane_break_factor, lane_expansion;
    /// Kernel-order work fields: displacement, force, energy density, and the temperature
    /// change (sized on its first use).
    typename BondBlocks<dim>::Array u_field, f_field, w_field, t_field;

    /**
     * @brief The loop of LinearizedPairLaw (energy density if @p with_energy, bond breaking
     * if @p breaks, the thermal stretch of the kernel-order temperature change @p delta_T if
     * @p thermal).
     */
    template <bool with_energy, bool breaks, bool thermal>
    void
    run_loop(BondList &bonds, const double critical_stretch, const double *delta_T)
    {
      using Law = LinearizedPairLaw<dim, with_energy, breaks, thermal>;
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
      for_each_bond_block<n_input>(
        blocks,
        u,
        out,
        Law{{}, lane_coefficient.data(), lane_break_factor.data(), lane_expansion.data()},
        bonds,
        critical_stretch);
    }

    /**
     * @brief run_loop() with breaking only for a finite @p critical_stretch, thermal only with
     * a temperature change @p delta_T (kernel order; nullptr for none).
     */
    template <bool with_energy>
    void
    force_loop(BondList &bonds, const double critical_stretch, const double *delta_T)
    {
      const bool breaks = std::isfinite(critical_stretch);
      if (delta_T != nullptr)
        {
          if (breaks)
            run_loop<with_energy, true, true>(bonds, critical_stretch, delta_T);
          else
            run_loop<with_energy, false, true>(bonds, critical_stretch, delta_T);
        }
      else if (breaks)
        run_loop<with_energy, true, false>(bonds, critical_stretch, nullptr);
      else
        run_loop<with_energy, false, false>(bonds, critical_stretch, nullptr);
    }
  };

  template <int dim>
  AnisotropicBondBased<dim>::AnisotropicBondBased()
    : kernel(std::make_unique<Kernel>())
  {}

  template <int dim>
  AnisotropicBondBased<dim>::~AnisotropicBondBased() = default;

  template <int dim>
  void
  AnisotropicBondBased<dim>::declare_parameters(ParameterHandler &prm)
  {
    ElasticMaterial::declare_parameters(prm);
    prm.declare_entry("Cauchy relations",
                      "refuse",
                      Patterns::Selection("refuse|symmetrize"),
                      "What to do with constants that violate Cauchy's relations (C66 = C12, "
                      "C44 = C23, C55 = C13, C56 = C14, C46 = C25, C45 = C36 in the global axes, "
                      "relative tolerance 1e-8 of the largest |C_ijkl|; in 2D C66 = C12 of the "
                      "2D tensor of the planar assumption), which bond-based PD "
                      "imposes: refuse (stop with the violations) or symmetrize (use the "
                      "completely symmetric part (1/24) sum_perm C_ijkl; the change of every "
                      "constant is written to the log).");
    prm.declare_entry("Calibration",
                      "discrete",
                      Patterns::Selection("discrete|continuum"),
                      "How Lambda follows from C: discrete (fitted to the lattice's neighbour "
                      "sums at an interior particle: homogeneous deformations reproduce C there "
                      "to round-off; the same for the Fracture energy ratios) or continuum (the "
                      "integrals over the ball, seed note 004 sec. 1.3; the lattice error is "
                      "written to the log).");
    AnisotropicFractureEnergy<dim>::declare_parameters(prm);
    Grains<dim>::declare_parameters(prm);
  }

  template <int dim>
  void
  AnisotropicBondBased<dim>::parse_parameters(ParameterHandler &prm)
  {
    material.parse_parameters(prm, section);
    calibration =
      prm.get("Calibration") == "discrete" ? Calibration::discrete : Calibration::continuum;
    symmetrize = prm.get("Cauchy relations") == "symmetrize";
    fracture.parse_parameters(prm, section);
    grains.parse_parameters(prm, section);
    if constexpr (dim == 3)
      set_target(material.tensor<3>(PlanarAssumption::three_dimensional), "elastic constants");
  }

  template <int dim>
  void
  AnisotropicBondBased<dim>::set_target(const SymmetricTensor<4, dim> &C_input,
                                        const std::string             &what)
  {
    const double      tolerance = 1e-8 * am::largest_component(C_input);
    const std::string violated  = am::cauchy_violations(C_input);
    const std::string accepted =
      dim == 3 ? "constants with C66 = C12, C44 = C23, C55 = C13, C56 = C14, C46 = C25, C45 = C36 "
                 "(global axes, relative tolerance 1e-8)" :
                 "constants whose 2D tensor has C66 = C12 (relative tolerance 1e-8)";
    const std::string alternative =
      (dim == 2 && context.planar == PlanarAssumption::plane_stress) ?
        "; a 3D material with Cauchy's relations in plane stress is the model 'anisotropic "
        "plane stress' (<Material/Model> = anisotropic plane stress), whose reduced stiffness "
        "need not satisfy the 2D relation" :
        "";
    AssertThrow(violated.empty() || symmetrize,
                ExcMessage("The " + what + " of <" + section + "> (" + material.summary() +
                           (dim == 3 ? ") violate" : ") violates") +
                           " Cauchy's relations, which bond-based peridynamics "
                           "imposes:" +
                           violated + " accepted: " + accepted + ", or <" + section +
                           "/Cauchy relations> = symmetrize" + alternative + "."));
    C = am::completely_symmetric_part(C_input);
    symmetrization_report.clear();
    if (!violated.empty())
      {
        const auto         C_sym       = am::to_tensor<dim>(C);
        const unsigned int pair3[6][2] = {{0, 0}, {1, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}};
        const unsigned int pair2[3][2] = {{0, 0}, {1, 1}, {0, 1}};
        const unsigned int voigt2[3]   = {1, 2, 6};
        const unsigned int n_voigt     = dim == 3 ? 6 : 3;
        std::ostringstream report;
        report << "Cauchy relations violated (" << violated
               << ") and symmetrized; changed constants (global axes):";
        for (unsigned int I = 0; I < n_voigt; ++I)
          for (unsigned int J = I; J < n_voigt; ++J)
            {
              const unsigned int *p      = dim == 3 ? pair3[I] : pair2[I];
              const unsigned int *q      = dim == 3 ? pair3[J] : pair2[J];
              const double        before = C_input[p[0]][p[1]][q[0]][q[1]];
              const double        after  = C_sym[p[0]][p[1]][q[0]][q[1]];
              if (std::abs(after - before) > tolerance)
                report << " C" << (dim == 3 ? I + 1 : voigt2[I]) << (dim == 3 ? J + 1 : voigt2[J])
                       << " " << ParameterUtilities::format_number(before) << " -> "
                       << ParameterUtilities::format_number(after) << " Pa;";
            }
        symmetrization_report = report.str();
      }
  }

  template <int dim>
  void
  AnisotropicBondBased<dim>::initialize(ParticleSystem<dim> &particles,
                                        const ModelContext  &model_context)
  {
    context = model_context;
    if constexpr (dim == 2)
      set_target(material.tensor<2>(context.planar),
                 context.planar == PlanarAssumption::plane_stress ?
                   "plane-stress reduced stiffness (2D tensor, sigma_i3 = 0)" :
                   "plane-strain stiffness (the in-plane block, 2D tensor)");
    const am::Family<dim> family = am::interior_family(particles);
    AssertThrow(!family.xi.empty(),
                ExcMessage("The region of <" + section +
                           "> has no bonds: the horizon is too "
                           "small for the particle spacing."));
    const FullMatrix<double> M_lattice      = am::lattice_moment_matrix(family);
    const auto               relative_error = [&](const am::ComponentsOf<dim> &Lambda_trial) {
      am::ComponentsOf<dim> residual = am::multiply(M_lattice, Lambda_trial);
      for (unsigned int k = 0; k < am::n_components<dim>; ++k)
        residual[k] -= C[k];
      return am::norm(residual) / am::norm(C);
    };
    const am::ComponentsOf<dim> Lambda_continuum =
      am::solve(am::continuum_moment_matrix<dim>(context.horizon, context.thickness), C);
    lattice_error = relative_error(Lambda_continuum);
    Lambda = calibration == Calibration::discrete ? am::solve(M_lattice, C) : Lambda_continuum;
    calibration_residual = relative_error(Lambda);
    directions           = am::scan_directions<dim>(Lambda);
    double spacing       = std::numeric_limits<double>::infinity();
    for (const auto &xi : family.xi)
      spacing = std::min(spacing, xi.norm());
    symbol = am::scan_symbol(Lambda, family, spacing, 16);
    fracture.calibrate(material.axes(), family, calibration == Calibration::discrete);
    fracture_report = fracture.summary(family);
    AssertThrow(symbol.relative_minimum > -1e-10,
                ExcMessage("The elastic constants of <" + section + "> (" + material.summary() +
                           ") give a peridynamic operator whose Fourier symbol is not positive "
                           "definite (smallest eigenvalue " +
                           ParameterUtilities::format_number(symbol.relative_minimum) +
                           " of the largest): the particle model would be unstable. Accepted: "
                           "constants whose bond-based operator is positive definite at every "
                           "wave vector (the set-up checks " +
                           (dim == 3 ? std::string("16^3") : std::string("16^2")) + " of them)."));
    AssertThrow(am::mean_directional_modulus<dim>(Lambda) > 0.,
                ExcMessage("The elastic constants of <" + section +
                           "> give a micromodulus whose mean over the directions is not "
                           "positive; accepted: a positive definite operator."));
    set_up_grains(particles, family, spacing);

    Kernel &k = *kernel;
    k.blocks.reinit(particles);
    k.blocks.reinit_field(k.u_field, dim);
    k.blocks.reinit_field(k.f_field, dim);
    k.blocks.reinit_field(k.w_field, 1);
    {
      // The breaking factor per bond: the direction factor and fracture weight of its grain,
      // the means of its two grains' across a grain boundary (times the boundary's ratio).
      const double         c_mean = am::mean_directional_modulus<dim>(Lambda);
      const BondList      &bonds  = particles.bonds();
      const auto          &x      = particles.positions();
      std::vector<double> &factor = bond_break_factor;
      factor.resize(bonds.size());
      for (unsigned int i = 0; i < particles.n_owned(); ++i)
        for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
          {
            const unsigned int   gi = particle_grain[i], gj = particle_grain[bonds.neighbor[b]];
            const Tensor<1, dim> n((x[bonds.neighbor[b]] - x[i]) / bonds.length[b]);
            const double         weight = gi == gj ?
                                            grain_fracture[gi].weight(n) :
                                            0.5 * grains.boundary_ratio() *
                                      (grain_fracture[gi].weight(n) + grain_fracture[gj].weight(n));
            factor[b] = std::sqrt(std::abs(bond_modulus(gi, gj, n)) / (c_mean * weight));
          }
      k.blocks.to_lanes(factor, k.lane_break_factor);
    }
    set_bond_expansions(particles);
    k.t_field.clear();
    fit_report = apply_surface_correction<dim>(*this, particles, context);
    set_bond_coefficients(particles, true);
  }

  template <int dim>
  SymmetricTensor<2, dim>
  AnisotropicBondBased<dim>::grain_expansion(const unsigned int g) const
  {
    const ElasticMaterial grain = material.rotated(grains.rotation(g));
    return planar_thermal_expansion<dim>(grain.thermal_expansion(),
                                         grain.voigt_stiffness(),
                                         context.planar);
  }

  template <int dim>
  SymmetricTensor<2, dim>
  AnisotropicBondBased<dim>::thermal_expansion() const
  {
    return planar_thermal_expansion<dim>(material.thermal_expansion(),
                                         material.voigt_stiffness(),
                                         context.planar);
  }

  template <int dim>
  void
  AnisotropicBondBased<dim>::set_bond_expansions(const ParticleSystem<dim> &particles)
  {
    bond_expansion.clear();
    kernel->lane_expansion.clear();
    if (material.thermal_expansion_entry().is_zero())
      return;
    // n . alpha . n of the bond's grain, the mean of its two grains' across a boundary.
    std::vector<SymmetricTensor<2, dim>> alpha;
    for (unsigned int g = 0; g < grains.size(); ++g)
      alpha.push_back(grain_expansion(g));
    const BondList &bonds = particles.bonds();
    const auto     &x     = particles.positions();
    bond_expansion.assign(bonds.size(), 0.);
    for (unsigned int i = 0; i < particles.n_owned(); ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        {
          const unsigned int   gi = particle_grain[i], gj = particle_grain[bonds.neighbor[b]];
          const Tensor<1, dim> n((x[bonds.neighbor[b]] - x[i]) / bonds.length[b]);
          bond_expansion[b] = 0.5 * (n * (alpha[gi] * n) + n * (alpha[gj] * n));
        }
    kernel->blocks.to_lanes(bond_expansion, kernel->lane_expansion);
  }

  template <int dim>
  std::unique_ptr<SurfaceCorrectionLaw<dim>>
  AnisotropicBondBased<dim>::surface_correction_law(ParticleSystem<dim> &particles)
  {
    auto law = elastic_surface_correction_law<dim>(*this, particles, [this, &particles]() {
      set_bond_coefficients(particles, false);
    });
    // Per end and unit chi V_i V_j, c(n) |xi| (n.e.n)^2 / 4 under a homogeneous strain (one
    // grain: capabilities()).
    law->stiffness = [this](const Tensor<1, dim> &xi, double &axial, double &shear) {
      const double length = xi.norm();
      axial               = 0.5 * bond_modulus(0, 0, xi / length) * length;
      shear               = 0.;
    };
    return law;
  }

  template <int dim>
  void
  AnisotropicBondBased<dim>::set_bond_coefficients(const ParticleSystem<dim> &particles,
                                                   const bool                 with_surface_factor)
  {
    bond_pair_coefficients(particles, 1., with_surface_factor, bond_coefficient);
    const BondList &bonds = particles.bonds();
    const auto     &x     = particles.positions();
    for (unsigned int i = 0; i < particles.n_owned(); ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        bond_coefficient[b] *=
          bond_modulus(particle_grain[i],
                       particle_grain[bonds.neighbor[b]],
                       Tensor<1, dim>((x[bonds.neighbor[b]] - x[i]) / bonds.length[b]));
    kernel->blocks.to_lanes(bond_coefficient, kernel->lane_coefficient);
  }

  template <int dim>
  ModelCapabilities
  AnisotropicBondBased<dim>::capabilities() const
  {
    ModelCapabilities capabilities;
    capabilities.stiffness_fit         = grains.size() <= 1;
    capabilities.sequentially_linear   = true;
    capabilities.thermal_strain        = true;
    capabilities.thermoelastic_heating = true;
    return capabilities;
  }

  template <int dim>
  std::string
  AnisotropicBondBased<dim>::nonuniform_constants() const
  {
    return grains.has_file() ? "<" + section + "/Grains file> makes the particles a polycrystal" :
                               std::string();
  }

  template <int dim>
  double
  AnisotropicBondBased<dim>::bond_modulus(const unsigned int    g,
                                          const unsigned int    h,
                                          const Tensor<1, dim> &n) const
  {
    const double c = am::directional_modulus(grain_Lambda[g], n);
    return g == h ? c : 0.5 * (c + am::directional_modulus(grain_Lambda[h], n));
  }

  template <int dim>
  void
  AnisotropicBondBased<dim>::set_up_grains(const ParticleSystem<dim> &particles,
                                           const am::Family<dim>     &family,
                                           const double               spacing)
  {
    const FullMatrix<double> M =
      calibration == Calibration::discrete ?
        am::lattice_moment_matrix(family) :
        am::continuum_moment_matrix<dim>(context.horizon, context.thickness);
    grain_Lambda.clear();
    grain_fracture.clear();
    for (unsigned int g = 0; g < grains.size(); ++g)
      {
        const ElasticMaterial   grain = material.rotated(grains.rotation(g));
        SymmetricTensor<4, dim> C_grain;
        if constexpr (dim == 2)
          C_grain = grain.tensor<2>(context.planar);
        else
          C_grain = grain.tensor<3>(PlanarAssumption::three_dimensional);
        // Rotations keep the complete symmetry: this is C rotated (or its symmetrized part).
        grain_Lambda.push_back(am::solve(M, am::completely_symmetric_part(C_grain)));
        if (grains.size() > 1)
          AssertThrow(am::scan_symbol(grain_Lambda[g], family, spacing, 16).relative_minimum >
                        -1e-10,
                      ExcMessage("Grain " + std::to_string(g) + " of <" + section +
                                 "/Grains file> gives a peridynamic operator whose Fourier "
                                 "symbol is not positive definite on this lattice; accepted: "
                                 "constants and orientations whose operator is positive "
                                 "definite at every wave vector."));
        grain_fracture.push_back(fracture);
        grain_fracture[g].calibrate(grain.axes(), family, calibration == Calibration::discrete);
      }
    const auto &x = particles.positions();
    particle_grain.resize(particles.n_local());
    for (unsigned int i = 0; i < particles.n_local(); ++i)
      particle_grain[i] = grains.grain_of(x[i]);
  }

  template <int dim>
  void
  AnisotropicBondBased<dim>::compute_forces(ParticleSystem<dim>  &particles,
                                            const ParticleVector &u,
                                            ParticleVector       &force,
                                            std::vector<double>  *energy_density,
                                            const double          critical_stretch)
  {
    Kernel &k = *kernel;
    // Without an expansion, a temperature change strains nothing: the loop of today.
    const ParticleVector *delta_T = this->temperature_change();
    const double         *t_field = delta_T != nullptr && !bond_expansion.empty() ?
                                      gather_temperature_change(k.blocks, *delta_T, k.t_field) :
                                      nullptr;
    evaluate_bond_kernel<dim>(k.blocks,
                              particles,
                              u,
                              dim,
                              k.u_field,
                              k.f_field,
                              k.w_field,
                              force,
                              energy_density,
                              [&](auto with_energy) {
                                k.template force_loop<decltype(with_energy)::value>(
                                  particles.bonds(),
                                  critical_stretch,
                                  t_field);
                              });
  }

  template <int dim>
  void
  AnisotropicBondBased<dim>::thermoelastic_measure(ParticleSystem<dim>  &particles,
                                                   const ParticleVector &u,
                                                   std::vector<double>  &measure)
  {
    Kernel &k = *kernel;
    if (bond_expansion.empty())
      {
        // Without an expansion the energy does not depend on the temperature.
        measure.assign(particles.n_owned(), 0.);
        return;
      }
    evaluate_bond_measure<dim>(
      k.blocks,
      particles,
      u,
      k.u_field,
      k.w_field,
      LinearizedMeasureLaw<dim>{
        {{}, k.lane_coefficient.data(), k.lane_break_factor.data(), k.lane_expansion.data()}},
      measure);
  }

  template <int dim>
  SymmetricTensor<4, dim>
  AnisotropicBondBased<dim>::elasticity_tensor() const
  {
    return am::to_tensor<dim>(C);
  }

  template <int dim>
  double
  AnisotropicBondBased<dim>::critical_stretch(const double fracture_energy) const
  {
    const double c_mean = am::mean_directional_modulus<dim>(Lambda);
    if constexpr (dim == 2)
      return std::sqrt(4. * fracture_energy /
                       (c_mean * context.thickness * std::pow(context.horizon, 4)));
    else
      return std::sqrt(10. * fracture_energy /
                       (numbers::PI * c_mean * std::pow(context.horizon, 5)));
  }

  template <int dim>
  std::vector<double>
  AnisotropicBondBased<dim>::breaking_factors(const ParticleSystem<dim> &) const
  {
    return bond_break_factor;
  }

  template <int dim>
  const am::ComponentsOf<dim> &
  AnisotropicBondBased<dim>::micromodulus_tensor() const
  {
    return Lambda;
  }

  template <int dim>
  double
  AnisotropicBondBased<dim>::continuum_lattice_error() const
  {
    return lattice_error;
  }

  template <int dim>
  const am::DirectionScanOf<dim> &
  AnisotropicBondBased<dim>::direction_scan() const
  {
    return directions;
  }

  template <int dim>
  const am::SymbolScanOf<dim> &
  AnisotropicBondBased<dim>::symbol_scan() const
  {
    return symbol;
  }

  template <int dim>
  std::string
  AnisotropicBondBased<dim>::summary() const
  {
    std::ostringstream out;
    out << "anisotropic bond based (linearized, omega = 1/|xi|"
        << (dim == 2 ? (context.planar == PlanarAssumption::plane_stress ? ", plane stress" :
                                                                           ", plane strain") :
                       "")
        << "): " << material.summary() << "; "
        << (calibration == Calibration::discrete ? "discrete" : "continuum")
        << " calibration, interior error |M Lambda - C|/|C| = " << calibration_residual
        << " (continuum calibration on this lattice: " << lattice_error << "); surface correction: "
        << (!context.surface_correction ? std::string("none") :
            context.stiffness_fit       ? fit_report.summary() :
                                          std::string("energy method (C_aaaa per axis)"));
    if (!symmetrization_report.empty())
      out << "\n  " << symmetrization_report;
    if (!fracture_report.empty())
      out << "\n  " << fracture_report;
    if (const std::string polycrystal = grains.summary(); !polycrystal.empty())
      out << "\n  " << polycrystal;
    if (directions.negative_fraction > 0.)
      out << "\n  warning: the micromodulus is negative in " << 100. * directions.negative_fraction
          << " % of the directions (smallest c(n) = " << directions.minimum << " N/m^6 at n = ("
          << directions.minimum_direction
          << ")); the Fourier symbol is positive definite (smallest eigenvalue "
          << symbol.relative_minimum << " of the largest)";
    return out.str();
  }

  template class AnisotropicBondBased<2>;
  template class AnisotropicBondBased<3>;
} // namespace perideal

PERIDEAL_REGISTER_MATERIAL_MODEL(perideal::AnisotropicBondBased,
                                 "anisotropic bond based",
                                 "linearized bond-based PD of any elasticity tensor with Cauchy's "
                                 "relations (seed 004); the FE side's symmetry classes and "
                                 "orientation; in 2D the tensor of the planar assumption (2D "
                                 "Cauchy relation C66 = C12).")
