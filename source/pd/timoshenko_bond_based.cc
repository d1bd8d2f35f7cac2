// ---------------------------------------------------------------------
// PeriDeal: bond-based peridynamics with Timoshenko-beam bonds and particle rotations (seed 003).
// ---------------------------------------------------------------------
#include <deal.II/base/numbers.h>

#include <perideal/base/parameter_utilities.h>
#include <perideal/pd/bond_loop.h>
#include <perideal/pd/surface_correction.h>
#include <perideal/pd/timoshenko_bond_based.h>

#include <cmath>
#include <limits>
#include <sstream>

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
     * @brief The pair law of the Timoshenko bond (TimoshenkoBondBased): force k f on the
     * particle side, -k f on the neighbour, moments k m_i and k m_j, and, if @p with_energy,
     * the pair energy k w / 2 at both ends (k per lane = G beta V_i V_j). With @p softening,
     * each mode is scaled by its factor per lane (stiffness of the largest value reached); if
     * `commit`, the pair first raises the lanes' histories to the present values and updates
     * their factors and dissipated energies.
     */
    /**
     * @brief The constants and per-lane arrays a TimoshenkoPairLaw reads.
     */
    struct TimoshenkoLawData
    {
      /// k = G beta V_i V_j per lane.
      const double *coefficient = nullptr;
      double        C_N = 0., C_theta = 0., C_B = 0.;
      /// 1/s_0, 1/gamma_0, 1/kappa_0 (0: that mode does not fail).
      double inverse_limit[3] = {0., 0., 0.};
      /// Softening: histories x (largest value / limit) and factors mu per mode and lane, the
      /// dissipated energy per lane, k, and whether this evaluation raises the histories.
      double *history[3] = {nullptr, nullptr, nullptr};
      double *factor[3]  = {nullptr, nullptr, nullptr};
      double *dissipated = nullptr;
      /// The largest growth of a history in this evaluation (written by commits).
      double *largest_growth      = nullptr;
      double  softening_parameter = 1.;
      bool    commit              = false;
    };

    /**
     * @brief The pair law of the Timoshenko bond (TimoshenkoBondBased): force k f on the
     * particle side, -k f on the neighbour, moments k m_i and k m_j, and, if @p with_energy,
     * the pair energy k w / 2 at both ends (k per lane = G beta V_i V_j). With @p softening,
     * each mode is scaled by its factor per lane (secant stiffness at the largest value
     * reached); if `commit`, the pair first raises the lanes' histories to the present values
     * and updates their factors and dissipated energies.
     */
    template <int dim, bool with_energy, bool softening>
    struct TimoshenkoPairLaw
    {
      static constexpr unsigned int n_rot        = n_rotations(dim);
      static constexpr unsigned int n_shear      = (dim == 2 ? 1 : 3);
      static constexpr unsigned int n_outputs    = dim + n_rot + (with_energy ? 1 : 0);
      static constexpr bool         breaks_bonds = true;
      TimoshenkoLawData             p;

      struct Side
      {};
      Side
      side(const unsigned int) const
      {
        return {};
      }

      template <typename Bond>
      BondStrain<dim>
      strain(const Bond &bond,
             const std::size_t /*first_lane*/,
             const Vector *u_a,
             const Vector *u_b) const
      {
        using Value = BondValue<Bond>;
        BondStrain<dim> y;
        const Value     il = bond.inverse_length;
        Value           n[dim];
        for (unsigned int d = 0; d < dim; ++d)
          n[d] = bond.xi[d] * il;
        Vector eta[dim];
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
            // gamma = (eta - (n . eta) n)/|xi| - (theta_a + theta_b) x n / 2.
            Vector t[3], k[3];
            for (unsigned int d = 0; d < 3; ++d)
              {
                t[d] = 0.5 * (u_a[3 + d] + u_b[3 + d]);
                k[d] = u_b[3 + d] - u_a[3 + d];
              }
            const Vector tn[3] = {t[1] * n[2] - t[2] * n[1],
                                  t[2] * n[0] - t[0] * n[2],
                                  t[0] * n[1] - t[1] * n[0]};
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
        const Vector x2 = stdx::max(y.s * y.s * (p.inverse_limit[0] * p.inverse_limit[0]),
                                    stdx::max(gamma2 * (p.inverse_limit[1] * p.inverse_limit[1]),
                                              kappa2 * (p.inverse_limit[2] * p.inverse_limit[2])));
        y.stretch       = stdx::sqrt(x2);
        return y;
      }

      template <typename Bond>
      void
      pair(const Bond            &bond,
           const BondStrain<dim> &y,
           const Side &,
           const BondLanes &lanes,
           Vector          *to_a,
           Vector          *to_b) const
      {
        using Value    = BondValue<Bond>;
        const Value il = bond.inverse_length, l = bond.length;
        Value       n[dim];
        for (unsigned int d = 0; d < dim; ++d)
          n[d] = bond.xi[d] * il;
        Vector k = 0.;
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
        const Vector shear = (12. * p.C_theta * il * il) * k_g;
        const Vector arm   = (6. * p.C_theta * il) * k_g;
        const Vector bend  = (p.C_B * il) * k_b;
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
            const Vector e      = 0.25 * (axial * y.s * l + shear * g2 * l + bend * b2);
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
        Vector present[3] = {stdx::abs(y.s) * p.inverse_limit[0],
                             stdx::sqrt(g2) * p.inverse_limit[1],
                             stdx::sqrt(b2) * p.inverse_limit[2]};
        for (auto &x : present)
          stdx::where(k == 0., x) = 0.;
        // U_0 per mode: p.C_N |xi| s_0^2, 12 p.C_theta gamma_0^2 / |xi|, p.C_B kappa_0^2 / |xi|.
        const BondValue<Bond> U0[3] = {
          p.inverse_limit[0] > 0. ?
            p.C_N * bond.length / (p.inverse_limit[0] * p.inverse_limit[0]) :
            BondValue<Bond>(0.),
          p.inverse_limit[1] > 0. ?
            12. * p.C_theta * bond.inverse_length / (p.inverse_limit[1] * p.inverse_limit[1]) :
            BondValue<Bond>(0.),
          p.inverse_limit[2] > 0. ?
            p.C_B * bond.inverse_length / (p.inverse_limit[2] * p.inverse_limit[2]) :
            BondValue<Bond>(0.)};
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
  } // namespace

  template <int dim>
  struct TimoshenkoBondBased<dim>::Kernel
  {
    static constexpr unsigned int   n_components = dim + n_rotations(dim);
    BondBlocks<dim>                 blocks;
    typename BondBlocks<dim>::Array lane_coefficient;
    typename BondBlocks<dim>::Array u_field, f_field, w_field;
    /// Softening: per lane the histories and factors of the three modes, and the dissipated
    /// energy (lanes of bonds to ghosts count on both ranks).
    typename BondBlocks<dim>::Array history[3], factor[3], dissipated;
    double                          dissipated_reported = 0., largest_growth = 0.;

    template <bool with_energy, bool softening>
    void
    force_loop(TimoshenkoPairLaw<dim, with_energy, softening> law,
               BondList                                      &bonds,
               const double                                   threshold)
    {
      std::array<const double *, n_components>                                        u;
      std::array<double *, TimoshenkoPairLaw<dim, with_energy, softening>::n_outputs> out;
      for (unsigned int c = 0; c < n_components; ++c)
        {
          u[c]   = blocks.component(u_field, c);
          out[c] = blocks.component(f_field, c);
        }
      if constexpr (with_energy)
        out[n_components] = blocks.component(w_field, 0);
      law.p.coefficient = lane_coefficient.data();
      if constexpr (softening)
        {
          for (unsigned int m = 0; m < 3; ++m)
            {
              law.p.history[m] = history[m].data();
              law.p.factor[m]  = factor[m].data();
            }
          law.p.dissipated     = dissipated.data();
          law.p.largest_growth = &largest_growth;
        }
      for_each_bond_block<n_components>(blocks, u, out, law, bonds, threshold);
    }
  };

  template <int dim>
  TimoshenkoBondBased<dim>::TimoshenkoBondBased()
    : kernel(std::make_unique<Kernel>())
  {}

  template <int dim>
  TimoshenkoBondBased<dim>::~TimoshenkoBondBased() = default;

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
                      "10",
                      Patterns::Double(),
                      "k > 0 of the softening law: force C x0 exp(-k (x - x0)/x0) beyond the "
                      "limit x0; the limits are the brittle ones times sqrt(k / (k + 2)).");
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
    failure   = law == "brittle" ? FailureLaw::brittle : FailureLaw::softening;
    softening = prm.get_double("Softening parameter");
    AssertThrow(softening > 0.,
                ExcMessage("<" + section + "Softening parameter> = " +
                           ParameterUtilities::format_number(softening) +
                           " must be > 0 (the limits scale by sqrt(k / (k + 2)))."));
    softening_tolerance = prm.get_double("Softening tolerance");
    AssertThrow(softening_tolerance > 0. && softening_tolerance <= 0.1,
                ExcMessage("<" + section + "Softening tolerance> = " +
                           ParameterUtilities::format_number(softening_tolerance) +
                           "; accepted: (0, 0.1] (a fraction of the limit)."));
  }

  template <int dim>
  FieldLayout
  TimoshenkoBondBased<dim>::field_layout() const
  {
    return FieldLayout::displacement_and_rotation(dim);
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
    if (context.surface_correction)
      {
        ParticleVector force;
        particles.reinit_vector(force, Kernel::n_components);
        set_bond_coefficients(particles, false);
        const auto energy = [&](const ParticleVector &u, std::vector<double> &w) {
          compute_forces(particles, u, force, &w, std::numeric_limits<double>::infinity());
        };
        if (context.stiffness_fit)
          {
            // Per end and unit beta V_i V_j, w / 2 = [C_N |xi| (n.e.n)^2 / 2 + 6 C_theta
            // (|e.n|^2 - (n.e.n)^2) / |xi|] / 2 under a homogeneous strain, theta its rotation.
            const double C_N = bond_stiffness.normal, C_theta = bond_stiffness.shear;
            const auto   law = [C_N,
                              C_theta](const Tensor<1, dim> &xi, double &axial, double &shear) {
              const double l = xi.norm();
              axial          = 0.5 * (C_N * l - 12. * C_theta / l);
              shear          = 6. * C_theta / l;
            };
            fit_report = apply_stiffness_fit<dim>(particles, law, D[0]);
          }
        else
          {
            std::array<double, dim> modulus;
            modulus.fill(D[0]);
            apply_energy_surface_correction<dim>(particles, field_layout(), modulus, energy);
          }
      }
    set_bond_coefficients(particles, true);
  }

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
    const auto ratio  = Timoshenko::limit_ratios(bond_stiffness, dim, context.horizon);
    const bool soft   = (failure == FailureLaw::softening);
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
        base.inverse_limit[0] = 1. / critical_stretch;
        base.inverse_limit[1] = 1. / (critical_stretch * ratio[0]);
        base.inverse_limit[2] = 1. / (critical_stretch * ratio[1]);
      }
    base.softening_parameter = softening;
    base.commit              = breaks;
    if (breaks)
      k.largest_growth = 0.;
    const auto run = [&](auto with_energy) {
      constexpr bool e = decltype(with_energy)::value;
      if (soft)
        {
          k.template force_loop<e, true>({base}, particles.bonds(), threshold);
        }
      else
        {
          k.template force_loop<e, false>({base}, particles.bonds(), threshold);
        }
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
  template <typename Emit>
  void
  TimoshenkoBondBased<dim>::bond_rows(const ParticleSystem<dim> &particles,
                                      const unsigned int         i,
                                      const std::size_t          b,
                                      const Emit                &emit) const
  {
    using Entry                = LinearizedModel::Entry;
    const BondList    &bonds   = particles.bonds();
    const unsigned int j       = bonds.neighbor[b];
    const double       r       = bonds.length[b];
    const double       k       = bond_coefficient[b];
    const auto         xi      = particles.positions()[j] - particles.positions()[i];
    const auto         n       = xi / r;
    const auto        &C       = bond_stiffness;
    const unsigned int n_trans = dim;
    // Transverse unit vectors e (dim - 1 of them) and the rotation axes n x e of their shear.
    std::vector<Tensor<1, dim>> e;
    std::vector<Tensor<1, 3>>   axis;
    if constexpr (dim == 2)
      {
        Tensor<1, dim> t;
        t[0] = -n[1];
        t[1] = n[0];
        e.push_back(t);
        Tensor<1, 3> z;
        z[2] = 1.;
        axis.push_back(z);
      }
    else
      {
        Tensor<1, 3> a;
        a[std::abs(n[0]) < 0.6 ? 0 : 1] = 1.;
        const Tensor<1, 3> e1           = cross_product_3d(n, a) / cross_product_3d(n, a).norm();
        const Tensor<1, 3> e2           = cross_product_3d(n, e1);
        e                               = {e1, e2};
        axis                            = {cross_product_3d(n, e1), cross_product_3d(n, e2)};
      }
    std::vector<Entry> entries;
    entries.reserve(4 * dim);
    // Stretch: n . (u_j - u_i), weight k C_N / |xi|.
    for (unsigned int d = 0; d < dim; ++d)
      {
        entries.push_back({i, d, -n[d]});
        entries.push_back({j, d, n[d]});
      }
    emit(k * C.normal / r, entries, 0u);
    // Shear strains: e . (u_j - u_i) / |xi| - (n x e) . (theta_i + theta_j) / 2, weight
    // 12 k C_theta / |xi|.
    if (C.shear != 0.)
      for (unsigned int a = 0; a < e.size(); ++a)
        {
          entries.clear();
          for (unsigned int d = 0; d < dim; ++d)
            {
              entries.push_back({i, d, -e[a][d] / r});
              entries.push_back({j, d, e[a][d] / r});
            }
          for (unsigned int q = 0; q < n_rotations(dim); ++q)
            {
              const double g = -0.5 * axis[a][dim == 2 ? 2 : q];
              entries.push_back({i, n_trans + q, g});
              entries.push_back({j, n_trans + q, g});
            }
          emit(12. * k * C.shear / r, entries, 1u);
        }
    // Bending rotations: e . (theta_j - theta_i) (2D: rz_j - rz_i), weight k C_B / |xi|.
    if (C.bending != 0.)
      for (unsigned int a = 0; a < (dim == 2 ? 1 : 2); ++a)
        {
          entries.clear();
          for (unsigned int q = 0; q < n_rotations(dim); ++q)
            {
              const double g = (dim == 2 ? 1. : e[a][q]);
              entries.push_back({i, n_trans + q, -g});
              entries.push_back({j, n_trans + q, g});
            }
          emit(k * C.bending / r, entries, 2u);
        }
  }

  template <int dim>
  void
  TimoshenkoBondBased<dim>::linearize(const ParticleSystem<dim> &particles,
                                      LinearizedModel           &linearized) const
  {
    const BondList &bonds = particles.bonds();
    linearized.reinit(Kernel::n_components, particles.n_owned());
    std::vector<double> factor[3];
    if (failure == FailureLaw::softening)
      for (unsigned int m = 0; m < 3; ++m)
        {
          factor[m].assign(bonds.size(), 1.);
          kernel->blocks.from_lanes(kernel->factor[m], factor[m]);
        }
    for (unsigned int i = 0; i < particles.n_owned(); ++i)
      for (std::size_t b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        if (bonds.intact[b])
          {
            bond_rows(particles,
                      i,
                      b,
                      [&](const double w, const auto &entries, const unsigned int mode) {
                        const double mu = factor[mode].empty() ? 1. : factor[mode][b];
                        linearized.add_row(w * mu * particles.bond_share(b), entries);
                      });
          }
    // The stiffness of a particle's prescribed rows: its axial bond stiffness.
    std::vector<double> bound;
    stiffness_bound(particles, bound);
    for (unsigned int i = 0; i < particles.n_owned(); ++i)
      linearized.stiffness_scale()[i] = bound[i * Kernel::n_components] * particles.volumes()[i];
  }

  template <int dim>
  void
  TimoshenkoBondBased<dim>::stiffness_bound(const ParticleSystem<dim> &particles,
                                            std::vector<double>       &per_particle) const
  {
    // Gershgorin over the rows of the strain operator, for the matrix scaled by the inertias
    // (D^-1/2 K D^-1/2, whose eigenvalues are those of D^-1 K): row r adds
    // w |g_pc| sum_e |g_e| sqrt(rho_c / rho_e) to the row of unknown (p, c) of K = G^T diag(w) G.
    // Without the scaling, the entries 1/|xi| of translations against 1/2 of rotations would
    // bound the rotations' stiffness by that of the translations and shrink the step tenfold.
    const BondList    &bonds   = particles.bonds();
    const unsigned int n_owned = particles.n_owned(), nc = Kernel::n_components;
    const double       ratio = std::sqrt(inertia_factor) * spacing; // sqrt(J / rho)
    const auto         scale = [&](const unsigned int c, const unsigned int e) {
      const bool rc = c >= unsigned(dim), re = e >= unsigned(dim);
      return rc == re ? 1. : (rc ? ratio : 1. / ratio);
    };
    per_particle.assign(std::size_t(n_owned) * nc, 0.);
    for (unsigned int i = 0; i < n_owned; ++i)
      for (std::size_t b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        if (bonds.intact[b])
          bond_rows(particles, i, b, [&](const double w, const auto &entries, unsigned int) {
            for (const auto &entry : entries)
              if (entry.particle < n_owned)
                {
                  double sum = 0.;
                  for (const auto &other : entries)
                    sum += std::abs(other.coefficient) * scale(entry.component, other.component);
                  per_particle[entry.particle * nc + entry.component] +=
                    w * std::abs(entry.coefficient) * sum / particles.volumes()[entry.particle];
                }
          });
  }

  template <int dim>
  double
  TimoshenkoBondBased<dim>::released_energy(ParticleSystem<dim> &particles, const ParticleVector &u)
  {
    BondList &bonds    = particles.bonds();
    double    released = 0.;
    // The bond energy 1/2 sum_r w_r (G_r u)^2 of each newly broken bond (factors as they were).
    std::vector<double> factor[3];
    if (failure == FailureLaw::softening && !bonds.newly_broken.empty())
      for (unsigned int m = 0; m < 3; ++m)
        {
          factor[m].assign(bonds.size(), 1.);
          kernel->blocks.from_lanes(kernel->factor[m], factor[m]);
        }
    const unsigned int nc = Kernel::n_components;
    for (const unsigned int b : bonds.newly_broken)
      {
        const unsigned int i = std::upper_bound(bonds.row_start.begin(), bonds.row_start.end(), b) -
                               bonds.row_start.begin() - 1;
        bond_rows(particles,
                  i,
                  b,
                  [&](const double w, const auto &entries, const unsigned int mode) {
                    double strain = 0.;
                    for (const auto &entry : entries)
                      strain +=
                        entry.coefficient * u.local_element(entry.particle * nc + entry.component);
                    const double mu = factor[mode].empty() ? 1. : factor[mode][b];
                    released += particles.bond_share(b) * 0.5 * w * mu * strain * strain;
                  });
      }
    bonds.newly_broken.clear();
    if (failure == FailureLaw::softening)
      {
        // The energy the softening bonds dissipated, lanes of bonds to ghosts counted half.
        std::vector<double> per_bond(bonds.size(), 0.);
        kernel->blocks.from_lanes(kernel->dissipated, per_bond);
        double total = 0.;
        for (std::size_t b = 0; b < bonds.size(); ++b)
          total += particles.bond_share(b) * per_bond[b];
        released += total - kernel->dissipated_reported;
        kernel->dissipated_reported = total;
      }
    return released;
  }

  template <int dim>
  bool
  TimoshenkoBondBased<dim>::damage_changed() const
  {
    return failure == FailureLaw::softening &&
           Utilities::MPI::max(kernel->largest_growth, communicator) > softening_tolerance;
  }

  template <int dim>
  unsigned int
  TimoshenkoBondBased<dim>::n_bond_history_values() const
  {
    return failure == FailureLaw::softening ? 4 : 0;
  }

  template <int dim>
  std::vector<double>
  TimoshenkoBondBased<dim>::bond_history(const ParticleSystem<dim> &particles) const
  {
    if (failure != FailureLaw::softening)
      return {};
    const typename BondBlocks<dim>::Array *lanes[4] = {&kernel->history[0],
                                                       &kernel->history[1],
                                                       &kernel->history[2],
                                                       &kernel->dissipated};
    std::vector<double> per_bond(particles.bonds().size()), values(4 * per_bond.size());
    for (unsigned int v = 0; v < 4; ++v)
      {
        kernel->blocks.from_lanes(*lanes[v], per_bond);
        for (std::size_t b = 0; b < per_bond.size(); ++b)
          values[4 * b + v] = per_bond[b];
      }
    return values;
  }

  template <int dim>
  void
  TimoshenkoBondBased<dim>::set_bond_history(const ParticleSystem<dim> &particles,
                                             const std::vector<double> &values)
  {
    const std::size_t n_bonds = particles.bonds().size();
    AssertThrow(values.size() == n_bond_history_values() * n_bonds,
                ExcMessage("set_bond_history(): " + std::to_string(values.size()) + " values for " +
                           std::to_string(n_bonds) + " bonds."));
    if (failure != FailureLaw::softening)
      return;
    std::vector<double> per_bond(n_bonds), mu(n_bonds);
    for (unsigned int m = 0; m < 3; ++m)
      {
        for (std::size_t b = 0; b < n_bonds; ++b)
          {
            per_bond[b] = values[4 * b + m];
            mu[b]       = Timoshenko::softening_factor(per_bond[b], softening);
          }
        kernel->blocks.to_lanes(per_bond, kernel->history[m]);
        kernel->blocks.to_lanes(mu, kernel->factor[m]);
      }
    double total = 0.;
    for (std::size_t b = 0; b < n_bonds; ++b)
      {
        per_bond[b] = values[4 * b + 3];
        total += particles.bond_share(b) * per_bond[b];
      }
    kernel->blocks.to_lanes(per_bond, kernel->dissipated);
    kernel->dissipated_reported = total;
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
    return failure == FailureLaw::softening ? s0 * std::sqrt(softening / (softening + 2.)) : s0;
  }

  template <int dim>
  const Timoshenko::Stiffness &
  TimoshenkoBondBased<dim>::stiffness() const
  {
    return bond_stiffness;
  }

  template <int dim>
  typename TimoshenkoBondBased<dim>::FailureLaw
  TimoshenkoBondBased<dim>::failure_law() const
  {
    return failure;
  }

  template <int dim>
  bool
  TimoshenkoBondBased<dim>::has_stiffness_fit() const
  {
    return true;
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
    if (context.surface_correction && context.stiffness_fit)
      out << "; " << fit_report.summary();
    return out.str();
  }

  template class TimoshenkoBondBased<2>;
  template class TimoshenkoBondBased<3>;
} // namespace perideal

PERIDEAL_REGISTER_MATERIAL_MODEL(perideal::TimoshenkoBondBased,
                                 "timoshenko bond based",
                                 "bond-based PD with Timoshenko-beam bonds and particle rotations "
                                 "(seed 003): any nu up to 1/3 (plane stress) or 1/4.")
