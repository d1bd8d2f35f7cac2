// ---------------------------------------------------------------------
// PeriDeal: anisotropic linearized bond-based PD in 3D (seed 004).
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
     * breaks a bond, s times the bond class's breaking factor sqrt(|c(n)| / c_mean).
     */
    struct LinearStretch
    {
      bond_simd::Vector s, stretch;
    };

    /**
     * @brief The pair law of the linearized bond (StretchPairLaw's side, its own strain): pair
     * force k s n on the particle side (-k s n on the neighbour), k = c(n) G beta V_i V_j per lane,
     * and, if @p with_energy, the pair energy k s^2 |xi| / 4 at both ends; if @p breaks, a bond
     * breaks where s times its class's factor exceeds the reference critical stretch.
     */
    template <bool with_energy, bool breaks>
    struct LinearizedPairLaw : StretchPairLaw<3>
    {
      static constexpr unsigned int n_outputs    = 3 + (with_energy ? 1 : 0);
      static constexpr bool         breaks_bonds = breaks;
      /// k per lane.
      const double *coefficient;
      /// The bond classes of the blocks (the loop hands their elements) and their factors.
      const BondBlocks<3>::BondClass *classes;
      const double                   *break_factor;

      /// The linearized stretch (hides StretchPairLaw's deformed bond).
      LinearStretch
      strain(const BondBlocks<3>::BondClass &bond,
             const bond_simd::Vector        *u_a,
             const bond_simd::Vector        *u_b) const
      {
        bond_simd::Vector e = 0.;
        for (unsigned int d = 0; d < 3; ++d)
          e += bond.xi[d] * (u_b[d] - u_a[d]);
        const bond_simd::Vector s = e * (bond.inverse_length * bond.inverse_length);
        if constexpr (breaks)
          return {s, s * break_factor[&bond - classes]};
        else
          return {s, s};
      }

      void
      pair(const BondBlocks<3>::BondClass &bond,
           const LinearStretch            &y,
           const StretchPairLaw<3>::Side &,
           const BondLanes   &lanes,
           bond_simd::Vector *to_a,
           bond_simd::Vector *to_b) const
      {
        using namespace bond_simd;
        const Vector k(coefficient + lanes.first_lane, stdx::element_aligned);
        Vector       t               = 0.;
        stdx::where(lanes.active, t) = k * y.s * bond.inverse_length;
        for (unsigned int d = 0; d < 3; ++d)
          {
            to_a[d] = bond.xi[d] * t;
            to_b[d] = -to_a[d];
          }
        if constexpr (with_energy)
          {
            Vector e                     = 0.;
            stdx::where(lanes.active, e) = (0.25 * bond.length) * k * y.s * y.s;
            to_a[3]                      = e;
            to_b[3]                      = e;
          }
      }
    };
  } // namespace

  struct AnisotropicBondBased::Kernel
  {
    /// The bonds in SIMD blocks, bond_coefficient per lane and the breaking factor
    /// sqrt(|c(n)| / c_mean) per bond class.
    BondBlocks<3>        blocks;
    BondBlocks<3>::Array lane_coefficient;
    std::vector<double>  class_break_factor;
    /// Kernel-order work fields: displacement, force, energy density.
    BondBlocks<3>::Array u_field, f_field, w_field;

    /**
     * @brief The loop of LinearizedPairLaw (energy density if @p with_energy, bond breaking
     * if @p breaks).
     */
    template <bool with_energy, bool breaks>
    void
    run_loop(BondList &bonds, const double critical_stretch)
    {
      using Law = LinearizedPairLaw<with_energy, breaks>;
      std::array<const double *, 3>        u;
      std::array<double *, Law::n_outputs> out;
      for (unsigned int d = 0; d < 3; ++d)
        {
          u[d]   = blocks.component(u_field, d);
          out[d] = blocks.component(f_field, d);
        }
      if constexpr (with_energy)
        out[3] = blocks.component(w_field, 0);
      for_each_bond_block<3>(
        blocks,
        u,
        out,
        Law{{}, lane_coefficient.data(), blocks.classes().data(), class_break_factor.data()},
        bonds,
        critical_stretch);
    }

    /**
     * @brief run_loop() with breaking only for a finite @p critical_stretch.
     */
    template <bool with_energy>
    void
    force_loop(BondList &bonds, const double critical_stretch)
    {
      if (std::isfinite(critical_stretch))
        run_loop<with_energy, true>(bonds, critical_stretch);
      else
        run_loop<with_energy, false>(bonds, critical_stretch);
    }
  };

  AnisotropicBondBased::AnisotropicBondBased()
    : kernel(std::make_unique<Kernel>())
  {}

  AnisotropicBondBased::~AnisotropicBondBased() = default;

  void
  AnisotropicBondBased::declare_parameters(ParameterHandler &prm)
  {
    ElasticMaterial::declare_parameters(prm);
    prm.declare_entry("Cauchy relations",
                      "refuse",
                      Patterns::Selection("refuse|symmetrize"),
                      "What to do with constants that violate Cauchy's relations (C66 = C12, "
                      "C44 = C23, C55 = C13, C56 = C14, C46 = C25, C45 = C36 in the global axes, "
                      "relative tolerance 1e-8 of the largest |C_ijkl|), which bond-based PD "
                      "imposes: refuse (stop with the violations) or symmetrize (use the "
                      "completely symmetric part (1/24) sum_perm C_ijkl; the change of every "
                      "constant is written to the log).");
    prm.declare_entry("Calibration",
                      "discrete",
                      Patterns::Selection("discrete|continuum"),
                      "How Lambda follows from C: discrete (fitted to the lattice's neighbour "
                      "sums at an interior particle: homogeneous deformations reproduce C there "
                      "to round-off) or continuum (the integral over the ball, seed note 004 sec. "
                      "1.3; its lattice error is written to the log).");
  }

  void
  AnisotropicBondBased::parse_parameters(ParameterHandler &prm)
  {
    material.parse_parameters(prm, section);
    calibration =
      prm.get("Calibration") == "discrete" ? Calibration::discrete : Calibration::continuum;
    const auto C_input = material.tensor<3>(PlanarAssumption::three_dimensional);
    double     scale   = 0.;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        for (unsigned int k = 0; k < 3; ++k)
          for (unsigned int l = 0; l < 3; ++l)
            scale = std::max(scale, std::abs(C_input[i][j][k][l]));
    const double       tolerance = 1e-8 * scale;
    std::ostringstream violated;
    for (const auto &relation : am::cauchy_relations(C_input))
      if (std::abs(relation.difference) > tolerance)
        violated << " " << relation.relation << " is off by "
                 << ParameterUtilities::format_number(relation.difference) << " Pa ("
                 << ParameterUtilities::format_number(relation.difference / scale)
                 << " of the largest constant);";
    AssertThrow(violated.str().empty() || prm.get("Cauchy relations") == "symmetrize",
                ExcMessage("The elastic constants of <" + section + "> (" + material.summary() +
                           ") violate Cauchy's relations, which bond-based peridynamics "
                           "imposes:" +
                           violated.str() +
                           " accepted: constants with C66 = C12, C44 = C23, C55 = C13, C56 = "
                           "C14, C46 = C25, C45 = C36 (global axes, relative tolerance 1e-8), "
                           "or <" +
                           section + "/Cauchy relations> = symmetrize."));
    C = am::completely_symmetric_part(C_input);
    symmetrization_report.clear();
    if (!violated.str().empty())
      {
        const auto         C_sym      = am::to_tensor(C);
        const unsigned int pair[6][2] = {{0, 0}, {1, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}};
        std::ostringstream report;
        report << "Cauchy relations violated (" << violated.str()
               << ") and symmetrized; changed constants (global axes):";
        for (unsigned int I = 0; I < 6; ++I)
          for (unsigned int J = I; J < 6; ++J)
            {
              const double before = C_input[pair[I][0]][pair[I][1]][pair[J][0]][pair[J][1]];
              const double after  = C_sym[pair[I][0]][pair[I][1]][pair[J][0]][pair[J][1]];
              if (std::abs(after - before) > tolerance)
                report << " C" << I + 1 << J + 1 << " " << ParameterUtilities::format_number(before)
                       << " -> " << ParameterUtilities::format_number(after) << " Pa;";
            }
        symmetrization_report = report.str();
      }
  }

  void
  AnisotropicBondBased::initialize(ParticleSystem<3> &particles, const ModelContext &model_context)
  {
    context                        = model_context;
    const am::LatticeFamily family = am::interior_family(particles);
    AssertThrow(!family.xi.empty(),
                ExcMessage("The region of <" + section +
                           "> has no bonds: the horizon is too "
                           "small for the particle spacing."));
    const FullMatrix<double> M_lattice      = am::lattice_moment_matrix(family);
    const auto               relative_error = [&](const am::Components &Lambda_trial) {
      am::Components residual = am::multiply(M_lattice, Lambda_trial);
      for (unsigned int k = 0; k < 15; ++k)
        residual[k] -= C[k];
      return am::norm(residual) / am::norm(C);
    };
    const am::Components Lambda_continuum =
      am::solve(am::continuum_moment_matrix(context.horizon), C);
    lattice_error = relative_error(Lambda_continuum);
    Lambda = calibration == Calibration::discrete ? am::solve(M_lattice, C) : Lambda_continuum;
    calibration_residual = relative_error(Lambda);
    directions           = am::scan_directions(Lambda);
    double spacing       = std::numeric_limits<double>::infinity();
    for (const auto &xi : family.xi)
      spacing = std::min(spacing, xi.norm());
    symbol = am::scan_symbol(Lambda, family, spacing, 16);
    AssertThrow(symbol.relative_minimum > -1e-10,
                ExcMessage("The elastic constants of <" + section + "> (" + material.summary() +
                           ") give a peridynamic operator whose Fourier symbol is not positive "
                           "definite (smallest eigenvalue " +
                           ParameterUtilities::format_number(symbol.relative_minimum) +
                           " of the largest): the particle model would be unstable. Accepted: "
                           "constants whose bond-based operator is positive definite at every "
                           "wave vector (the set-up checks 16^3 of them)."));
    AssertThrow(am::mean_directional_modulus(Lambda) > 0.,
                ExcMessage("The elastic constants of <" + section +
                           "> give a micromodulus whose mean over the directions is not "
                           "positive; accepted: a positive definite operator."));

    Kernel &k = *kernel;
    k.blocks.reinit(particles);
    k.blocks.reinit_field(k.u_field, 3);
    k.blocks.reinit_field(k.f_field, 3);
    k.blocks.reinit_field(k.w_field, 1);
    const double c_mean = am::mean_directional_modulus(Lambda);
    k.class_break_factor.clear();
    for (const auto &bond_class : k.blocks.classes())
      {
        const Tensor<1, 3> n = Point<3>(bond_class.xi[0], bond_class.xi[1], bond_class.xi[2]);
        k.class_break_factor.push_back(
          std::sqrt(std::abs(am::directional_modulus(Lambda, n / n.norm())) / c_mean));
      }
    if (context.surface_correction)
      {
        ParticleVector force;
        particles.reinit_vector(force, 3);
        set_bond_coefficients(particles, false);
        const auto energy = [&](const ParticleVector &u, std::vector<double> &w) {
          compute_forces(particles, u, force, &w, std::numeric_limits<double>::infinity());
        };
        const auto            C_tensor = elasticity_tensor();
        std::array<double, 3> modulus;
        for (unsigned int a = 0; a < 3; ++a)
          modulus[a] = C_tensor[a][a][a][a];
        apply_energy_surface_correction<3>(particles, this->field_layout(), modulus, energy);
      }
    set_bond_coefficients(particles, true);
  }

  void
  AnisotropicBondBased::set_bond_coefficients(const ParticleSystem<3> &particles,
                                              const bool               with_surface_factor)
  {
    bond_pair_coefficients(particles, 1., with_surface_factor, bond_coefficient);
    const BondList &bonds = particles.bonds();
    const auto     &x     = particles.positions();
    for (unsigned int i = 0; i < particles.n_owned(); ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        bond_coefficient[b] *=
          am::directional_modulus(Lambda, (x[bonds.neighbor[b]] - x[i]) / bonds.length[b]);
    kernel->blocks.to_lanes(bond_coefficient, kernel->lane_coefficient);
  }

  void
  AnisotropicBondBased::compute_forces(ParticleSystem<3>    &particles,
                                       const ParticleVector &u,
                                       ParticleVector       &force,
                                       std::vector<double>  *energy_density,
                                       const double          critical_stretch)
  {
    Kernel &k = *kernel;
    evaluate_bond_kernel<3>(k.blocks,
                            particles,
                            u,
                            3,
                            k.u_field,
                            k.f_field,
                            k.w_field,
                            force,
                            energy_density,
                            [&](auto with_energy) {
                              k.template force_loop<decltype(with_energy)::value>(particles.bonds(),
                                                                                  critical_stretch);
                            });
  }

  SymmetricTensor<4, 3>
  AnisotropicBondBased::elasticity_tensor() const
  {
    return am::to_tensor(C);
  }

  double
  AnisotropicBondBased::critical_stretch(const double fracture_energy) const
  {
    return std::sqrt(
      10. * fracture_energy /
      (numbers::PI * am::mean_directional_modulus(Lambda) * std::pow(context.horizon, 5)));
  }

  const am::Components &
  AnisotropicBondBased::micromodulus_tensor() const
  {
    return Lambda;
  }

  double
  AnisotropicBondBased::continuum_lattice_error() const
  {
    return lattice_error;
  }

  const am::DirectionScan &
  AnisotropicBondBased::direction_scan() const
  {
    return directions;
  }

  const am::SymbolScan &
  AnisotropicBondBased::symbol_scan() const
  {
    return symbol;
  }

  std::string
  AnisotropicBondBased::summary() const
  {
    std::ostringstream out;
    out << "anisotropic bond based (linearized, omega = 1/|xi|): " << material.summary() << "; "
        << (calibration == Calibration::discrete ? "discrete" : "continuum")
        << " calibration, interior error |M Lambda - C|/|C| = " << calibration_residual
        << " (continuum calibration on this lattice: " << lattice_error << "); surface correction: "
        << (context.surface_correction ? "energy method (C_aaaa per axis)" : "none");
    if (!symmetrization_report.empty())
      out << "\n  " << symmetrization_report;
    if (directions.negative_fraction > 0.)
      out << "\n  warning: the micromodulus is negative in " << 100. * directions.negative_fraction
          << " % of the directions (smallest c(n) = " << directions.minimum << " N/m^6 at n = ("
          << directions.minimum_direction
          << ")); the Fourier symbol is positive definite (smallest eigenvalue "
          << symbol.relative_minimum << " of the largest)";
    return out.str();
  }
} // namespace perideal

PERIDEAL_REGISTER_PLUGIN(::perideal::MaterialModel<3>,
                         ::perideal::AnisotropicBondBased,
                         "anisotropic bond based",
                         "linearized bond-based PD of any elasticity tensor with Cauchy's "
                         "relations (seed 004), 3D only; the FE side's symmetry classes and "
                         "orientation.")
