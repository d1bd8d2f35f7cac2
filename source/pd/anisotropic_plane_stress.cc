// ---------------------------------------------------------------------
// PeriDeal: the anisotropic PD plane-stress model (seed 004, state form).
// ---------------------------------------------------------------------
#include <deal.II/base/numbers.h>
#include <deal.II/base/point.h>

#include <perideal/base/parameter_utilities.h>
#include <perideal/pd/anisotropic_plane_stress.h>
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
    const std::string section = "Material/anisotropic plane stress";

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

  struct AnisotropicPlaneStress::Kernel
  {
    /// The bonds in SIMD blocks, k and g per lane.
    BondBlocks<2>        blocks;
    BondBlocks<2>::Array lane_k, lane_g;
    /// Kernel-order work fields: displacement, force, energy density, pass-1 sums, beta A,
    /// temperature change.
    BondBlocks<2>::Array u_field, f_field, w_field, a_field, beta_A_field, delta_T_field;

    /// The kernel-order unknowns of the laws: the displacement and, if @p thermal, the
    /// temperature change.
    template <bool thermal>
    std::array<const double *, 2 + thermal>
    unknowns()
    {
      std::array<const double *, 2 + thermal> u;
      for (unsigned int d = 0; d < 2; ++d)
        u[d] = blocks.component(u_field, d);
      if constexpr (thermal)
        u[2] = blocks.component(delta_T_field, 0);
      return u;
    }

    /// Pass 1 (PlaneStressDilatationLaw) with in-plane expansion @p expansion if @p thermal.
    template <bool thermal>
    void
    dilatation_loop(BondList                    &bonds,
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
    force_loop(BondList &bonds, const std::array<double, 3> &expansion)
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
  };

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
                           ") violate Cauchy's relations, which the 3D bond-based model behind "
                           "the plane-stress model imposes:" +
                           violated.str() +
                           " accepted: constants with C66 = C12, C44 = C23, C55 = C13, C56 = "
                           "C14, C46 = C25, C45 = C36 (global axes, relative tolerance 1e-8), "
                           "or <" +
                           section + "/Cauchy relations> = symmetrize."));
    C3 = am::completely_symmetric_part(C_input);
    symmetrization_report.clear();
    if (!violated.str().empty())
      symmetrization_report = "Cauchy relations violated (" + violated.str() +
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
