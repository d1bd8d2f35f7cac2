// ---------------------------------------------------------------------
// PeriDeal: the set-up of the anisotropic PD plane-stress model (seed 004, state form): its
// parameters, the calibration of lambda_0, lambda_2 and B on the lattice, the bond coefficients,
// the surface correction and the summary. The force kernel is anisotropic_plane_stress.cc.
// ---------------------------------------------------------------------
#include <deal.II/base/numbers.h>
#include <deal.II/base/point.h>

#include <perideal/base/parameter_utilities.h>
#include <perideal/pd/anisotropic_plane_stress.h>
#include <perideal/pd/anisotropic_plane_stress_kernel.h>
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
    const std::string section = "Material/anisotropic plane stress";

    /// The components 11, 22, 12 of a symmetric 2-tensor and their multiplicities.
    const unsigned int pair_index[3][2] = {{0, 0}, {1, 1}, {0, 1}};
    const double       pair_count[3]    = {1., 1., 2.};

    /// M:nn for the components @p M (11, 22, 12).
    double
    quadratic_form(const std::array<double, 3> &M, const Tensor<1, 2> &n)
    {
      return M[0] * n[0] * n[0] + M[1] * n[1] * n[1] + 2. * M[2] * n[0] * n[1];
    }

    /// The 3 x 3 matrix L of sum_b (M:n_b n_b) |xi_b| n_b n_b w_b = L M on the family.
    FullMatrix<double>
    lattice_quadratic_matrix(const am::Family<2> &family)
    {
      FullMatrix<double> L(3, 3);
      for (std::size_t b = 0; b < family.xi.size(); ++b)
        {
          const double       r = family.xi[b].norm();
          const Tensor<1, 2> n = family.xi[b] / r;
          for (unsigned int a = 0; a < 3; ++a)
            for (unsigned int c = 0; c < 3; ++c)
              L(a, c) += family.weight[b] * r * pair_count[c] * n[pair_index[a][0]] *
                         n[pair_index[a][1]] * n[pair_index[c][0]] * n[pair_index[c][1]];
        }
      return L;
    }

    /// The continuum L over the disc: h delta^3/3 mult int n_a n_b n_c n_d d theta.
    FullMatrix<double>
    continuum_quadratic_matrix(const double horizon, const double thickness)
    {
      // int cos^4 = int sin^4 = 3 pi/4, int cos^2 sin^2 = pi/4.
      const double       s = thickness * std::pow(horizon, 3) / 3. * numbers::PI / 4.;
      FullMatrix<double> L(3, 3);
      L(0, 0) = L(1, 1) = 3. * s;
      L(0, 1) = L(1, 0) = s;
      L(2, 2)           = 2. * s;
      return L;
    }

    std::array<double, 3>
    solve3(const FullMatrix<double> &L, const std::array<double, 3> &rhs)
    {
      FullMatrix<double> inverse(3, 3);
      inverse.invert(L);
      std::array<double, 3> x{};
      for (unsigned int a = 0; a < 3; ++a)
        for (unsigned int c = 0; c < 3; ++c)
          x[a] += inverse(a, c) * rhs[c];
      return x;
    }

    /// |L x - rhs| / |rhs| (the tensor norms, shear counted twice).
    double
    relative_residual3(const FullMatrix<double>    &L,
                       const std::array<double, 3> &x,
                       const std::array<double, 3> &rhs)
    {
      double error = 0., scale = 0.;
      for (unsigned int a = 0; a < 3; ++a)
        {
          double r = -rhs[a];
          for (unsigned int c = 0; c < 3; ++c)
            r += L(a, c) * x[c];
          error += pair_count[a] * r * r;
          scale += pair_count[a] * rhs[a] * rhs[a];
        }
      return std::sqrt(error / scale);
    }
  } // namespace

  AnisotropicPlaneStress::AnisotropicPlaneStress()
    : kernel(std::make_unique<Kernel>())
  {}

  AnisotropicPlaneStress::~AnisotropicPlaneStress() = default;

  void
  AnisotropicPlaneStress::declare_parameters(ParameterHandler &prm)
  {
    ElasticMaterial::declare_parameters(prm);
    prm.declare_entry("Cauchy relations",
                      "refuse",
                      Patterns::Selection("refuse|symmetrize"),
                      "What to do with 3D constants that violate Cauchy's relations (C66 = C12, "
                      "C44 = C23, C55 = C13, C56 = C14, C46 = C25, C45 = C36 in the global axes, "
                      "relative tolerance 1e-8 of the largest |C_ijkl|), which the 3D bond-based "
                      "model behind the plane-stress model imposes: refuse or symmetrize (the "
                      "completely symmetric part; the changes are written to the log).");
    prm.declare_entry("Calibration",
                      "discrete",
                      Patterns::Selection("discrete|continuum"),
                      "How the kernels lambda_0, lambda_2 and B follow from C: discrete (fitted to "
                      "the lattice's neighbour sums at an interior particle: homogeneous "
                      "deformations reproduce the reduced stiffness there to round-off) or "
                      "continuum (integrals over the disc; the lattice error is logged).");
  }

  void
  AnisotropicPlaneStress::parse_parameters(ParameterHandler &prm)
  {
    material.parse_parameters(prm, section);
    calibration =
      prm.get("Calibration") == "discrete" ? Calibration::discrete : Calibration::continuum;
    const auto        C_input   = material.tensor<3>(PlanarAssumption::three_dimensional);
    const double      tolerance = 1e-8 * am::largest_component(C_input);
    const std::string violated  = am::cauchy_violations(C_input);
    AssertThrow(violated.empty() || prm.get("Cauchy relations") == "symmetrize",
                ExcMessage("The elastic constants of <" + section + "> (" + material.summary() +
                           ") violate Cauchy's relations, which the 3D bond-based model behind "
                           "the plane-stress model imposes:" +
                           violated +
                           " accepted: constants with C66 = C12, C44 = C23, C55 = C13, C56 = "
                           "C14, C46 = C25, C45 = C36 (global axes, relative tolerance 1e-8), "
                           "or <" +
                           section + "/Cauchy relations> = symmetrize."));
    C3 = am::completely_symmetric_part(C_input);
    symmetrization_report.clear();
    if (!violated.empty())
      symmetrization_report = "Cauchy relations violated (" + violated +
                              ") and symmetrized: the completely symmetric part of C is used";
    // z = 0 must be a mirror plane: the components with an odd number of 3's vanish (1113,
    // 1333, 1223, 2223, 2333, 1123: components 9 ... 14).
    std::ostringstream odd;
    for (unsigned int k = 9; k < 15; ++k)
      if (std::abs(C3[k]) > tolerance)
        odd << " C_" << am::component_name(k) << " = " << ParameterUtilities::format_number(C3[k])
            << " Pa;";
    AssertThrow(odd.str().empty(),
                ExcMessage(
                  "The material of <" + section + "> (" + material.summary() +
                  ") does not have the plate's mid-plane z = 0 as a mirror plane:" + odd.str() +
                  " the plane-stress reduction needs C_ijk3 = 0 for an odd number of "
                  "3's. Accepted: a material whose axes are rotated about z only "
                  "(<Orientation> = phi, 0, 0, or theta a multiple of 180 degrees), or "
                  "a general C with z = 0 a symmetry plane; a triclinic C has no plane-"
                  "stress model."));
    C_in = {{C3[0], C3[1], C3[3], C3[6], C3[7]}};
    P    = {{C3[4], C3[5], C3[8]}};
    C33  = C3[2];
    // The thermal expansion in the global axes: the mirror plane z = 0 needs alpha_13 =
    // alpha_23 = 0; the plane-stress model takes its in-plane block, eps_33 its alpha_33.
    const SymmetricTensor<2, 3> alpha = material.thermal_expansion();
    AssertThrow(std::abs(alpha[0][2]) <= 1e-8 * alpha.norm() &&
                  std::abs(alpha[1][2]) <= 1e-8 * alpha.norm(),
                ExcMessage("The thermal expansion of <" + section +
                           "/Thermal expansion> has alpha_13 = " +
                           ParameterUtilities::format_number(alpha[0][2]) +
                           " 1/K and alpha_23 = " + ParameterUtilities::format_number(alpha[1][2]) +
                           " 1/K in the global axes: the plate's mid-plane z = 0 is not a "
                           "mirror plane of it. Accepted: an expansion whose material axes are "
                           "rotated about z only (<Orientation> = phi, 0, 0), or isotropic."));
    for (unsigned int a = 0; a < 3; ++a)
      in_plane_expansion[a] = alpha[pair_index[a][0]][pair_index[a][1]];
    expansion_33 = alpha[2][2];
  }

  void
  AnisotropicPlaneStress::initialize(ParticleSystem<2>  &particles,
                                     const ModelContext &model_context)
  {
    context = model_context;
    AssertThrow(context.planar == PlanarAssumption::plane_stress,
                ExcMessage("The model 'anisotropic plane stress' is a plane-stress model; "
                           "accepted: <Material/Planar assumption> = plane stress (for plane "
                           "strain use <Material/Model> = anisotropic bond based)."));
    AssertThrow(context.thickness <= context.horizon * (1. + 1e-12),
                ExcMessage("The plate thickness " +
                           ParameterUtilities::format_number(context.thickness) +
                           " m is larger than the horizon " +
                           ParameterUtilities::format_number(context.horizon) +
                           " m; the plane-stress model of seed 004 assumes a thin plate, "
                           "thickness 2h <= delta. Accepted: <Discretization/Thickness> "
                           "at most the horizon."));
    const am::Family<2> family = am::interior_family(particles);
    AssertThrow(!family.xi.empty(),
                ExcMessage("The region of <" + section +
                           "> has no bonds: the horizon is too small for the particle spacing."));

    // lambda_0: the 2D moment system on the in-plane part of C; lambda_2: sum (M:nn) |xi| n n w
    // = P; B_i = C_3333 m_i / m.
    const FullMatrix<double> M_lattice = am::lattice_moment_matrix(family);
    const FullMatrix<double> M_continuum =
      am::continuum_moment_matrix<2>(context.horizon, context.thickness);
    const FullMatrix<double> L_lattice = lattice_quadratic_matrix(family);
    const FullMatrix<double> L_continuum =
      continuum_quadratic_matrix(context.horizon, context.thickness);
    const auto residual0 = [&](const am::ComponentsOf<2> &Lambda) {
      am::ComponentsOf<2> r = am::multiply(M_lattice, Lambda);
      for (unsigned int k = 0; k < 5; ++k)
        r[k] -= C_in[k];
      return am::norm(r) / am::norm(C_in);
    };
    const am::ComponentsOf<2>   Lambda0_continuum = am::solve(M_continuum, C_in);
    const std::array<double, 3> M_continuum2      = solve3(L_continuum, P);
    double                      m_interior        = 0.;
    for (std::size_t b = 0; b < family.xi.size(); ++b)
      m_interior += family.xi[b].norm() * family.weight[b];
    const double m_continuum =
      2. * numbers::PI * context.thickness * std::pow(context.horizon, 3) / 3.;
    lattice_error        = std::max({residual0(Lambda0_continuum),
                                     relative_residual3(L_lattice, M_continuum2, P),
                                     std::abs(m_interior / m_continuum - 1.)});
    const bool discrete  = calibration == Calibration::discrete;
    Lambda0              = discrete ? am::solve(M_lattice, C_in) : Lambda0_continuum;
    M                    = discrete ? solve3(L_lattice, P) : M_continuum2;
    const double m_ref   = discrete ? m_interior : m_continuum;
    calibration_residual = std::max(
      {residual0(Lambda0), relative_residual3(L_lattice, M, P), std::abs(m_interior / m_ref - 1.)});

    // The Fourier symbol of the interior operator: K(k) = sum lambda_0 xi xi (1 - cos k.xi) w
    // - s s^T / B, s = sum lambda_2 xi sin(k.xi) w (W = 1/2 u^H K u for u e^(ik.x)).
    {
      const double B_interior = C33 * m_interior / m_ref;
      double       spacing    = std::numeric_limits<double>::infinity();
      for (const auto &xi : family.xi)
        spacing = std::min(spacing, xi.norm());
      const auto coupling = [&](const Tensor<1, 2> &k, SymmetricTensor<2, 2> &K) {
        Tensor<1, 2> s;
        for (std::size_t b = 0; b < family.xi.size(); ++b)
          {
            const Tensor<1, 2> n = family.xi[b] / family.xi[b].norm();
            s += quadratic_form(M, n) * family.weight[b] * std::sin(k * family.xi[b]) * n;
          }
        K -= symmetrize(outer_product(s, s)) / B_interior;
      };
      symbol_min = am::scan_symbol<2>(Lambda0, family, spacing, 16, coupling).relative_minimum;
    }
    AssertThrow(symbol_min > -1e-10,
                ExcMessage("The elastic constants of <" + section + "> (" + material.summary() +
                           ") give a plane-stress operator whose Fourier symbol is not positive "
                           "definite (smallest eigenvalue " +
                           ParameterUtilities::format_number(symbol_min) +
                           " of the largest): the particle model would be unstable. Accepted: "
                           "constants whose operator is positive definite at every wave vector "
                           "(the set-up checks 16^2 of them)."));

    // B_i = C_3333 m_i / m (m_i the particle's own weighted volume with the surface
    // correction).
    const BondList     &bonds  = particles.bonds();
    const auto         &volume = particles.volumes();
    std::vector<double> m_local(particles.n_local(), 0.);
    for (unsigned int i = 0; i < particles.n_owned(); ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        {
          const unsigned int j = bonds.neighbor[b];
          m_local[i] += bonds.length[b] * bonds.volume_factor(b) * volume[j];
          if (j < particles.n_owned())
            m_local[j] += bonds.length[b] * bonds.volume_factor(b) * volume[i];
        }
    ParticleVector m_vector;
    particles.reinit_vector(m_vector, 1);
    for (unsigned int i = 0; i < particles.n_owned(); ++i)
      m_vector.local_element(i) = context.surface_correction ? m_local[i] : m_ref;
    m_vector.update_ghost_values();
    B.resize(particles.n_local());
    for (unsigned int i = 0; i < particles.n_local(); ++i)
      B[i] = C33 * m_vector.local_element(i) / m_ref;

    Kernel &k = *kernel;
    k.blocks.reinit(particles);
    k.blocks.reinit_field(k.u_field, 2);
    k.blocks.reinit_field(k.f_field, 2);
    for (auto *field : {&k.w_field, &k.a_field, &k.beta_A_field, &k.delta_T_field})
      k.blocks.reinit_field(*field, 1);

    // The bond term near surfaces: the energy method on the whole model (B_i corrected), with
    // the reduced stiffness C'_aaaa of the uniaxial test fields; its factors scale k_b.
    apply_surface_correction<2>(*this, particles, context);
    set_bond_coefficients(particles, true);
  }

  std::unique_ptr<SurfaceCorrectionLaw<2>>
  AnisotropicPlaneStress::surface_correction_law(ParticleSystem<2> &particles)
  {
    return elastic_surface_correction_law<2>(*this, particles, [this, &particles]() {
      set_bond_coefficients(particles, false);
    });
  }

  void
  AnisotropicPlaneStress::set_bond_coefficients(const ParticleSystem<2> &particles,
                                                const bool               with_surface_factor)
  {
    const BondList &bonds  = particles.bonds();
    const auto     &x      = particles.positions();
    const auto     &volume = particles.volumes();
    bond_pair_coefficients(particles, 1., with_surface_factor, k0);
    g.assign(bonds.size(), 0.);
    for (unsigned int i = 0; i < particles.n_owned(); ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        {
          const unsigned int j = bonds.neighbor[b];
          const Tensor<1, 2> n = (x[j] - x[i]) / bonds.length[b];
          k0[b] *= am::directional_modulus(Lambda0, n);
          g[b] = quadratic_form(M, n) * bonds.volume_factor(b) * volume[i] * volume[j];
        }
    kernel->blocks.to_lanes(k0, kernel->lane_k);
    kernel->blocks.to_lanes(g, kernel->lane_g);
  }

  SymmetricTensor<2, 2>
  AnisotropicPlaneStress::thermal_expansion() const
  {
    SymmetricTensor<2, 2> alpha;
    for (unsigned int a = 0; a < 3; ++a)
      alpha[pair_index[a][0]][pair_index[a][1]] = in_plane_expansion[a];
    return alpha;
  }

  ModelCapabilities
  AnisotropicPlaneStress::capabilities() const
  {
    ModelCapabilities capabilities;
    capabilities.thermal_strain        = true;
    capabilities.thermoelastic_heating = true;
    return capabilities;
  }

  SymmetricTensor<4, 2>
  AnisotropicPlaneStress::elasticity_tensor() const
  {
    SymmetricTensor<4, 2> C = am::to_tensor<2>(C_in);
    for (unsigned int a = 0; a < 3; ++a)
      for (unsigned int c = 0; c < 3; ++c)
        C[pair_index[a][0]][pair_index[a][1]][pair_index[c][0]][pair_index[c][1]] -=
          P[a] * P[c] / C33;
    return C;
  }

  double
  AnisotropicPlaneStress::critical_stretch(const double) const
  {
    AssertThrow(false,
                ExcMessage("The model 'anisotropic plane stress' has no critical stretch from a "
                           "fracture energy (seed 004 leaves fracture of the plane-stress model "
                           "open); accepted: a critical stretch given to the damage model, or "
                           "no damage."));
    return 0.;
  }

  unsigned int
  AnisotropicPlaneStress::force_reach() const
  {
    return 2;
  }

  double
  AnisotropicPlaneStress::continuum_lattice_error() const
  {
    return lattice_error;
  }

  double
  AnisotropicPlaneStress::symbol_minimum() const
  {
    return symbol_min;
  }

  std::string
  AnisotropicPlaneStress::summary() const
  {
    std::ostringstream out;
    const auto         Cr = elasticity_tensor();
    out << "anisotropic plane stress (state form, option M of seed note 004): "
        << material.summary() << "; reduced stiffness C'11 = " << Cr[0][0][0][0]
        << " Pa, C'22 = " << Cr[1][1][1][1] << " Pa, C'12 = " << Cr[0][0][1][1]
        << " Pa, C'66 = " << Cr[0][1][0][1] << " Pa; "
        << (calibration == Calibration::discrete ? "discrete" : "continuum")
        << " calibration, interior error " << calibration_residual
        << " (continuum calibration on this lattice: " << lattice_error
        << "); Fourier symbol smallest/largest eigenvalue " << symbol_min << "; B_i "
        << (context.surface_correction ?
              "per particle (C_3333 m_i / m), bond term by the energy method (C'_aaaa per axis)" :
              "C_3333");
    if (!symmetrization_report.empty())
      out << "\n  " << symmetrization_report;
    return out.str();
  }
} // namespace perideal

PERIDEAL_REGISTER_PLUGIN(::perideal::MaterialModel<2>,
                         ::perideal::AnisotropicPlaneStress,
                         "anisotropic plane stress",
                         "the generalized plane-stress model of anisotropic linearized bond-"
                         "based PD (seed 004, a 2D state-based form with lambda_0, lambda_2, "
                         "B): reduced stiffness C' of a 3D C with Cauchy's relations and the "
                         "mirror plane z = 0; output eps_33. 2D, plane stress only.")
