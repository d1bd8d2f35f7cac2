// ---------------------------------------------------------------------
// PeriDeal: the set-up of the Timoshenko bond model: its parameters, the calibration of the bond
// stiffnesses, the surface correction and the summary.
// ---------------------------------------------------------------------
#include <perideal/base/parameter_utilities.h>
#include <perideal/pd/lattice_fracture.h>
#include <perideal/pd/surface_correction.h>
#include <perideal/pd/timoshenko_bond_based.h>
#include <perideal/pd/timoshenko_kernel.h>

#include <cmath>
#include <limits>
#include <sstream>

namespace perideal
{
  using namespace dealii;

  template <int dim>
  void
  TimoshenkoBondBased<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Young's modulus", "0", Patterns::Double(0.), "Young's modulus E [Pa].");
    prm.declare_entry("Poisson's ratio",
                      "0.2",
                      Patterns::Double(),
                      "Poisson's ratio nu, -1 < nu <= 1/3 in plane stress, <= 1/4 in plane strain "
                      "and 3D (the bond's shear stiffness C_theta is 0 at the limit: the "
                      "classical bond-based model).");
    prm.declare_entry("Calibration",
                      "lattice",
                      Patterns::Anything(),
                      "How C_N and C_theta follow from E and nu: 'lattice' (fitted to the "
                      "interior lattice sums of the particles' family, so that D_11 and D_12 are "
                      "exact in the interior; the square lattice's shear modulus is reported) or "
                      "'continuum' (the paper's eqs. 9-11, integrals over the horizon; the "
                      "lattice Poisson ratio then misses nu by up to 57 % at delta = 3 dx).");
    prm.declare_entry("Bending stiffness ratio",
                      "0",
                      Patterns::Double(0.),
                      "C_B / C_theta >= 0, the stiffness of the bond against the relative rotation "
                      "of its ends; 0 is the paper's C_M = 3/4 C_theta. Homogeneous deformations "
                      "do not see it.");
    prm.declare_entry("Rotational inertia factor",
                      "0.0833333333333333",
                      Patterns::Double(),
                      "The factor j > 0 [-] of the rotational inertia per unit volume "
                      "J = j rho dx^2 [kg/m]; 1/12 is rho I / A of a bond with a square section "
                      "of side dx. It changes "
                      "dynamics and the stable time step, never a static solution.");
    prm.declare_entry("Failure law",
                      "brittle",
                      Patterns::Anything(),
                      "'brittle' (a bond breaks when its stretch, shear strain or bending rotation "
                      "exceeds its limit) or 'softening' (each mode softens exponentially beyond "
                      "its limit, irreversibly; seed eqs. 15-19).");
    prm.declare_entry("Softening parameter",
                      "",
                      Patterns::Anything(),
                      "k > 0 of the softening law: force C x0 exp(-k (x - x0)/x0) beyond the "
                      "limit x0; the limits are the brittle ones times sqrt(k / (k + 2)). Empty: "
                      "10, or, with a Tensile strength, the k that strength and the fracture "
                      "energy imply (then it must stay empty).");
    prm.declare_entry(
      "Tensile strength",
      "0",
      Patterns::Double(0.),
      "sigma_t [Pa] > 0: the bond's elastic limit, with the softening law: the "
      "critical stretch s_0 = sigma_t / E (a bond along a uniaxial stress "
      "sigma_t reaches it), the shear and bending limits in the same ratio to "
      "their brittle ones, and k from <Material/critical stretch/Fracture energy> "
      "G0 so that each bond still dissipates the brittle work of G0: (k + 2)/k = "
      "(s_G / s_0)^2, s_G the brittle critical stretch of G0 (accepted: sigma_t < "
      "E s_G, printed in the summary; <Softening parameter> empty; a Critical stretch "
      "given instead of the Fracture energy is refused). 0: the limits "
      "follow from G0 and k alone (seed eqs. 18, 19).");
    prm.declare_entry("Compressive strength",
                      "0",
                      Patterns::Double(0.),
                      "sigma_c [Pa] > 0, with a Tensile strength only: the stretch limit of a "
                      "bond in compression, -sigma_c / E, beyond which it softens with the same "
                      "k (one history: the larger of s / s_0 and -s E / sigma_c). 0: compression "
                      "fails at -s_0 like tension (seed eq. 15 as printed).");
    ThermalExpansion::declare_parameters(prm, false);
    prm.declare_entry("Softening tolerance",
                      "1e-3",
                      Patterns::Double(),
                      "Softening, quasi-static runs: a load step is solved again (with the secant "
                      "stiffness of the histories reached) while a history beyond its limit grows "
                      "by more than this fraction of the limit in one solve; accepted: (0, 0.1].");
  }

  template <int dim>
  void
  TimoshenkoBondBased<dim>::parse_parameters(ParameterHandler &prm)
  {
    const std::string section = "Material/timoshenko bond based/";
    youngs_modulus            = prm.get_double("Young's modulus");
    ParameterUtilities::require_positive(youngs_modulus, section + "Young's modulus");
    poisson_ratio = prm.get_double("Poisson's ratio");
    AssertThrow(poisson_ratio > -1.,
                ExcMessage("<" + section + "Poisson's ratio> = " +
                           ParameterUtilities::format_number(poisson_ratio) +
                           " must be > -1 (and at most 1/3 in plane stress, 1/4 in plane "
                           "strain and 3D)."));
    expansion.parse_parameters(prm, "Material/timoshenko bond based", false);
    const std::string calibration_name = prm.get("Calibration");
    AssertThrow(calibration_name == "lattice" || calibration_name == "continuum",
                ExcMessage("<" + section + "Calibration> = '" + calibration_name +
                           "' is not known; accepted values: lattice | continuum."));
    calibration    = calibration_name == "lattice" ? Timoshenko::Calibration::lattice :
                                                     Timoshenko::Calibration::continuum;
    bending_ratio  = prm.get_double("Bending stiffness ratio");
    inertia_factor = prm.get_double("Rotational inertia factor");
    AssertThrow(inertia_factor > 0.,
                ExcMessage("<" + section + "Rotational inertia factor> = " +
                           ParameterUtilities::format_number(inertia_factor) +
                           " must be > 0 (J = j rho dx^2; 1/12 for a square bond section)."));
    const std::string law = prm.get("Failure law");
    AssertThrow(law == "brittle" || law == "softening",
                ExcMessage("<" + section + "Failure law> = '" + law +
                           "' is not known; accepted values: brittle | softening."));
    failure                = law == "brittle" ? FailureLaw::brittle : FailureLaw::softening;
    tensile_strength       = prm.get_double("Tensile strength");
    const std::string k    = prm.get("Softening parameter");
    const bool        no_k = k.find_first_not_of(" \t") == std::string::npos;
    compressive_strength   = prm.get_double("Compressive strength");
    AssertThrow(compressive_strength == 0. || tensile_strength > 0.,
                ExcMessage("<" + section + "Compressive strength> = " +
                           prm.get("Compressive strength") + " needs <" + section +
                           "Tensile strength> > 0 (the strengths set the limits together). "
                           "Accepted: both, or Compressive strength = 0."));
    if (tensile_strength > 0.)
      {
        AssertThrow(failure == FailureLaw::softening,
                    ExcMessage("<" + section +
                               "Tensile strength> = " + prm.get("Tensile strength") +
                               " is the elastic limit of a softening bond; with <" + section +
                               "Failure law> = brittle a bond would break there and dissipate "
                               "far less than the fracture energy. Accepted: Failure law = "
                               "softening, or Tensile strength = 0."));
        AssertThrow(no_k,
                    ExcMessage("<" + section +
                               "Tensile strength> = " + prm.get("Tensile strength") +
                               " derives the softening parameter from the fracture energy, "
                               "but <" +
                               section + "Softening parameter> = " + k +
                               " gives it. Accepted: one of the two (Softening parameter "
                               "empty with a Tensile strength)."));
        // Derived by critical_stretch() from the fracture energy.
        softening = std::numeric_limits<double>::quiet_NaN();
      }
    else
      {
        AssertThrow(no_k || Patterns::Double().match(k),
                    ExcMessage("<" + section + "Softening parameter> = '" + k +
                               "' is not a number; accepted: a number > 0, or empty (10)."));
        softening = no_k ? 10. : std::stod(k);
        AssertThrow(softening > 0.,
                    ExcMessage("<" + section + "Softening parameter> = " +
                               ParameterUtilities::format_number(softening) +
                               " must be > 0 (the limits scale by sqrt(k / (k + 2)))."));
      }
    softening_tolerance = prm.get_double("Softening tolerance");
    AssertThrow(softening_tolerance > 0. && softening_tolerance <= 0.1,
                ExcMessage("<" + section + "Softening tolerance> = " +
                           ParameterUtilities::format_number(softening_tolerance) +
                           "; accepted: (0, 0.1] (a fraction of the limit)."));
  }

  template <int dim>
  void
  TimoshenkoBondBased<dim>::initialize(ParticleSystem<dim> &particles,
                                       const ModelContext  &model_context)
  {
    context            = model_context;
    spacing            = particles.settings().spacing;
    communicator       = particles.get_communicator();
    const double limit = Timoshenko::poisson_limit(context.planar);
    AssertThrow(poisson_ratio <= limit + 1e-12,
                ExcMessage("<Material/timoshenko bond based/Poisson's ratio> = " +
                           ParameterUtilities::format_number(poisson_ratio) +
                           " is above the model's reach, nu <= " +
                           ParameterUtilities::format_number(limit) + " (" +
                           (context.planar == PlanarAssumption::plane_stress ?
                              "plane stress" :
                              (dim == 2 ? "plane strain" : "3D")) +
                           "): the bonds' shear stiffness C_theta would be negative."));
    const auto D = Timoshenko::target_moduli(youngs_modulus, poisson_ratio, context.planar);
    std::vector<Tensor<1, dim>> family;
    std::vector<double>         weight;
    particles.lattice_family(family, weight);
    if (calibration == Timoshenko::Calibration::continuum)
      bond_stiffness = Timoshenko::continuum_stiffness(D, dim, context.horizon, context.thickness);
    else
      {
        bond_stiffness =
          Timoshenko::lattice_stiffness(D, Timoshenko::lattice_sums<dim>(family, weight));
        AssertThrow(bond_stiffness.shear >=
                      -1e-12 * bond_stiffness.normal * context.horizon * context.horizon,
                    ExcMessage("<Material/timoshenko bond based/Calibration> = lattice gives a "
                               "negative shear stiffness C_theta for nu = " +
                               ParameterUtilities::format_number(poisson_ratio) +
                               " on this lattice; use a smaller Poisson's ratio or "
                               "Calibration = continuum."));
      }
    if (std::abs(poisson_ratio - limit) <= 1e-12 &&
        calibration == Timoshenko::Calibration::continuum)
      bond_stiffness.shear = 0.;
    bond_stiffness.bending = bending_ratio * bond_stiffness.shear;
    lattice_moduli         = Timoshenko::lattice_moduli<dim>(bond_stiffness, family, weight);

    Kernel &k = *kernel;
    k.blocks.reinit(particles);
    k.blocks.reinit_field(k.u_field, Kernel::n_components);
    k.blocks.reinit_field(k.f_field, Kernel::n_components);
    k.blocks.reinit_field(k.w_field, 1);
    k.t_field.clear();
    if (failure == FailureLaw::softening)
      {
        // Sized like the lanes before the first force evaluation (the surface correction's).
        const std::vector<double> zero(particles.bonds().size(), 0.), one(zero.size(), 1.);
        for (unsigned int m = 0; m < 3; ++m)
          {
            k.blocks.to_lanes(zero, k.history[m]);
            k.blocks.to_lanes(one, k.factor[m]);
          }
        k.blocks.to_lanes(zero, k.dissipated);
        k.dissipated_reported = 0.;
      }
    fit_report = apply_surface_correction<dim>(*this, particles, context);
    set_bond_coefficients(particles, true);
    fracture_factor = {{1., 1., 1.}};
    if (context.lattice_fracture)
      {
        // A bond at the continuum's limits of 1 J/m^2 holds k C_N |xi| s_0^2 / 2,
        // k 6 C_theta gamma_0^2 / |xi| and k C_B kappa_0^2 / (2 |xi|) in the three modes.
        const double s0 =
          Timoshenko::brittle_stretch(bond_stiffness, dim, context.horizon, context.thickness, 1.);
        const auto   ratio = Timoshenko::limit_ratios(bond_stiffness, dim, context.horizon);
        const double g0 = s0 * ratio[0], kappa0 = s0 * ratio[1];
        const Timoshenko::Stiffness                        C = bond_stiffness;
        const std::array<std::function<double(double)>, 3> energy{
          {[&](const double r) { return 0.5 * C.normal * r * s0 * s0; },
           [&](const double r) { return 6. * C.shear * g0 * g0 / r; },
           [&](const double r) { return 0.5 * C.bending * kappa0 * kappa0 / r; }}};
        for (unsigned int m = 0; m < 3; ++m)
          if (m == 0 || std::isfinite(ratio[m - 1]))
            fracture_factor[m] = lattice_fracture_factor<dim>(
              particles,
              [&](const unsigned int, const std::size_t b) { return bond_coefficient[b]; },
              energy[m]);
      }
  }

  template <int dim>
  std::unique_ptr<SurfaceCorrectionLaw<dim>>
  TimoshenkoBondBased<dim>::surface_correction_law(ParticleSystem<dim> &particles)
  {
    auto law                      = std::make_unique<SurfaceCorrectionLaw<dim>>();
    law->uncorrected_coefficients = [this, &particles]() {
      set_bond_coefficients(particles, false);
    };
    law->energy_density = model_energy_density<dim>(*this, particles);
    const auto D        = Timoshenko::target_moduli(youngs_modulus, poisson_ratio, context.planar);
    law->modulus.fill(D[0]);
    // Per end and unit chi V_i V_j, w / 2 = [C_N |xi| (n.e.n)^2 / 2 + 6 C_theta
    // (|e.n|^2 - (n.e.n)^2) / |xi|] / 2 under a homogeneous strain, theta its rotation.
    const double C_N = bond_stiffness.normal, C_theta = bond_stiffness.shear;
    law->stiffness = [C_N, C_theta](const Tensor<1, dim> &xi, double &axial, double &shear) {
      const double l = xi.norm();
      axial          = 0.5 * (C_N * l - 12. * C_theta / l);
      shear          = 6. * C_theta / l;
    };
    law->stiffness_modulus = D[0];
    return law;
  }

  template <int dim>
  std::string
  TimoshenkoBondBased<dim>::summary() const
  {
    const double       E = youngs_modulus, nu = poisson_ratio;
    const double       mu = E / (2. * (1. + nu));
    std::ostringstream out;
    out << "timoshenko bond based: E = " << E << " Pa, nu = " << nu << ", "
        << (calibration == Timoshenko::Calibration::lattice ? "lattice" : "continuum")
        << " calibration: C_N = " << bond_stiffness.normal
        << " N/m^6, C_theta = " << bond_stiffness.shear
        << " N/m^4, C_M = " << bond_stiffness.paper_bending()
        << " N/m^4, C_B = " << bond_stiffness.bending
        << " N/m^4; interior lattice D_12/D_11 = " << lattice_moduli[1] / lattice_moduli[0]
        << ", D_66/mu = " << lattice_moduli[2] / mu << "; J = " << inertia_factor
        << " rho dx^2; failure " << (failure == FailureLaw::brittle ? "brittle" : "softening, k = ")
        << (failure == FailureLaw::brittle ? std::string() : std::to_string(softening));
    if (tensile_strength > 0.)
      out << " (from the tensile strength " << tensile_strength
          << " Pa: s_0 = " << tensile_strength / youngs_modulus << ")";
    if (compressive_strength > 0.)
      out << ", compression limit " << compressive_strength / youngs_modulus;
    if (context.surface_correction && context.stiffness_fit)
      out << "; " << fit_report.summary();
    if (!expansion.is_zero())
      out << "; thermal expansion (axial) " << expansion.summary()
          << (context.planar == PlanarAssumption::plane_strain ?
                ", in plane (1 + nu) alpha = " + std::to_string(bond_expansion()) + " 1/K" :
                std::string());
    if (context.lattice_fracture)
      out << "; lattice calibration of the fracture energy: limits s_0, gamma_0, kappa_0 "
          << fracture_factor[0] << ", " << fracture_factor[1] << ", " << fracture_factor[2]
          << " times the continuum's";
    return out.str();
  }

  template void
  TimoshenkoBondBased<2>::declare_parameters(ParameterHandler &);
  template void
  TimoshenkoBondBased<3>::declare_parameters(ParameterHandler &);
  template void
  TimoshenkoBondBased<2>::parse_parameters(ParameterHandler &);
  template void
  TimoshenkoBondBased<3>::parse_parameters(ParameterHandler &);
  template void
  TimoshenkoBondBased<2>::initialize(ParticleSystem<2> &, const ModelContext &);
  template void
  TimoshenkoBondBased<3>::initialize(ParticleSystem<3> &, const ModelContext &);
  template std::unique_ptr<SurfaceCorrectionLaw<2>>
  TimoshenkoBondBased<2>::surface_correction_law(ParticleSystem<2> &);
  template std::unique_ptr<SurfaceCorrectionLaw<3>>
  TimoshenkoBondBased<3>::surface_correction_law(ParticleSystem<3> &);
  template std::string
  TimoshenkoBondBased<2>::summary() const;
  template std::string
  TimoshenkoBondBased<3>::summary() const;
} // namespace perideal
