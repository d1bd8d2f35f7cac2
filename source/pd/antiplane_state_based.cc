// ---------------------------------------------------------------------
// PeriDeal: the ordinary state-based peridynamic model of antiplane shear (one scalar per
// particle).
// ---------------------------------------------------------------------
#include <deal.II/base/numbers.h>

#include <perideal/base/parameter_utilities.h>
#include <perideal/pd/antiplane_state_based.h>
#include <perideal/pd/bond_loop.h>
#include <perideal/pd/lattice_fracture.h>
#include <perideal/pd/surface_correction.h>

#include <cmath>
#include <sstream>
#include <type_traits>

namespace perideal
{
  using namespace dealii;

  namespace
  {
    /**
     * @brief Pass 1 of the state-based antiplane kernel as a pair law of for_each_bond_block():
     * breaks bonds by slope (@p Slope: SlopePairLaw, or TwistedSlopePairLaw under torsion),
     * then adds the pair sum
     * k r n = omega (w_b - w_a) n chi V_i V_j (k = delta chi V_i V_j per lane, n = xi/|xi|) to
     * the dim outputs at both ends (r and n change sign together): the shear angles before the
     * factor b g / V_i.
     */
    template <int dim, typename Slope = SlopePairLaw<dim, false>>
    struct ShearAngleLaw : Slope
    {
      static constexpr unsigned int n_outputs = dim;

      template <typename Bond>
      void
      pair(const Bond      &bond,
           const BondSlope &r,
           const typename Slope::Side &,
           const BondLanes   &lanes,
           bond_simd::Vector *to_a,
           bond_simd::Vector *to_b) const
      {
        using namespace bond_simd;
        Vector t = 0.;
        stdx::where(lanes.active, t) =
          Vector(this->coefficient + lanes.first_lane, stdx::element_aligned) * r.value *
          bond.inverse_length;
        for (unsigned int d = 0; d < dim; ++d)
          {
            to_a[d] = t * bond.xi[d];
            to_b[d] = to_a[d];
          }
      }
    };

    /**
     * @brief What pass 2 reads of a bond: the slope (BondSlope) and (s_a + s_b) . n / |xi|, s the
     * force state of a particle (the kernel's unknowns are w and the dim components of s).
     */
    struct StateBondStrain : BondSlope
    {
      bond_simd::Vector state;
    };

    /**
     * @brief Pass 2 of the state-based antiplane kernel as a pair law of for_each_bond_block():
     * the pair force k (s_a + s_b) . n / |xi| = omega (s_a + s_b) . n chi V_i V_j (k = delta
     * chi V_i V_j per lane, @p weight) plus the bond-based term of SlopePairLaw (its coefficient
     * alpha c G chi V_i V_j, and its pair energy if @p with_energy; TwistedSlopePairLaw's if
     * @p twisted) on the particle side, the negative on the neighbour. No breaking (pass 1
     * broke the bonds).
     */
    template <int dim, bool with_energy, bool twisted = false>
    struct StateForceLaw : std::conditional_t<twisted,
                                              TwistedSlopePairLaw<dim, with_energy>,
                                              SlopePairLaw<dim, with_energy>>
    {
      using Slope                        = std::conditional_t<twisted,
                                       TwistedSlopePairLaw<dim, with_energy>,
                                       SlopePairLaw<dim, with_energy>>;
      static constexpr bool breaks_bonds = false;
      /// The first unknown of s: after w (and the twist fields p, q of TwistedSlopePairLaw).
      static constexpr unsigned int first_state = twisted ? 3 : 1;
      /// delta chi V_i V_j per lane.
      const double *weight;

      /// The slope (the unknown 0, twisted by the unknowns 1 and 2 if @p twisted) and
      /// (s_a + s_b) . n / |xi| (the dim unknowns from first_state).
      template <typename Bond>
      StateBondStrain
      strain(const Bond              &bond,
             const std::size_t        first_lane,
             const bond_simd::Vector *u_a,
             const bond_simd::Vector *u_b) const
      {
        StateBondStrain y;
        static_cast<BondSlope &>(y) = Slope::strain(bond, first_lane, u_a, u_b);
        y.state                     = 0.;
        for (unsigned int d = 0; d < dim; ++d)
          y.state += (u_a[first_state + d] + u_b[first_state + d]) * bond.xi[d];
        // n = xi / |xi| and omega = delta / |xi| (delta is in the lane weight)
        y.state *= bond.inverse_length * bond.inverse_length;
        return y;
      }

      template <typename Bond>
      void
      pair(const Bond                 &bond,
           const StateBondStrain      &y,
           const typename Slope::Side &side,
           const BondLanes            &lanes,
           bond_simd::Vector          *to_a,
           bond_simd::Vector          *to_b) const
      {
        using namespace bond_simd;
        Slope::pair(bond, y, side, lanes, to_a, to_b);
        Vector t = 0.;
        stdx::where(lanes.active, t) =
          Vector(weight + lanes.first_lane, stdx::element_aligned) * y.state;
        to_a[0] += t;
        to_b[0] -= t;
      }
    };
  } // namespace

  template <int dim>
  struct AntiplaneStateBased<dim>::Kernel
  {
    /// The bonds in SIMD blocks; state_coefficient and bond_coefficient per lane.
    BondBlocks<dim>                 blocks;
    typename BondBlocks<dim>::Array lane_weight, lane_coefficient;
    /// Kernel-order work fields: w, the force state s (dim components), the shear-angle sums
    /// of pass 1 (dim components), force and energy density.
    typename BondBlocks<dim>::Array w_field, s_field, r_field, f_field, e_field;
    /// Torsion: the fixed fields p = psi (x - x0), q = psi (y - y0) of TwistedSlopePairLaw
    /// (empty without a twist).
    typename BondBlocks<dim>::Array twist_field;

    /**
     * @brief Pass 1 (ShearAngleLaw): breaks bonds whose slope exceeds @p critical_slope and
     * sums the shear angles into r_field.
     */
    void
    angle_loop(BondList &bonds, const double critical_slope)
    {
      std::fill(r_field.begin(), r_field.end(), 0.);
      std::array<double *, dim> out;
      for (unsigned int d = 0; d < dim; ++d)
        out[d] = blocks.component(r_field, d);
      if (twist_field.empty())
        for_each_bond_block<1>(blocks,
                               {{blocks.component(w_field, 0)}},
                               out,
                               ShearAngleLaw<dim>{{lane_weight.data()}},
                               bonds,
                               critical_slope);
      else
        for_each_bond_block<3>(blocks,
                               {{blocks.component(w_field, 0),
                                 blocks.component(twist_field, 0),
                                 blocks.component(twist_field, 1)}},
                               out,
                               ShearAngleLaw<dim, TwistedSlopePairLaw<dim, false>>{
                                 {{lane_weight.data()}}},
                               bonds,
                               critical_slope);
    }

    /**
     * @brief Pass 2 (StateForceLaw) into f_field (and e_field if @p with_energy).
     */
    template <bool with_energy>
    void
    force_loop(BondList &bonds)
    {
      std::fill(f_field.begin(), f_field.end(), 0.);
      std::array<double *, StateForceLaw<dim, with_energy>::n_outputs> out;
      out[0] = blocks.component(f_field, 0);
      if constexpr (with_energy)
        {
          std::fill(e_field.begin(), e_field.end(), 0.);
          out[1] = blocks.component(e_field, 0);
        }
      // The unknowns of pass 2: w (the twist fields under torsion) and the components of s.
      if (twist_field.empty())
        {
          std::array<const double *, dim + 1> u;
          u[0] = blocks.component(w_field, 0);
          for (unsigned int d = 0; d < dim; ++d)
            u[1 + d] = blocks.component(s_field, d);
          const StateForceLaw<dim, with_energy> law{{lane_coefficient.data()}, lane_weight.data()};
          for_each_bond_block<dim + 1>(blocks, u, out, law, bonds, 0.);
        }
      else
        {
          std::array<const double *, dim + 3> u;
          u[0] = blocks.component(w_field, 0);
          u[1] = blocks.component(twist_field, 0);
          u[2] = blocks.component(twist_field, 1);
          for (unsigned int d = 0; d < dim; ++d)
            u[3 + d] = blocks.component(s_field, d);
          const StateForceLaw<dim, with_energy, true> law{{{lane_coefficient.data()}},
                                                          lane_weight.data()};
          for_each_bond_block<dim + 3>(blocks, u, out, law, bonds, 0.);
        }
    }
  };

  template <int dim>
  AntiplaneStateBased<dim>::AntiplaneStateBased()
    : kernel(std::make_unique<Kernel>())
  {}

  template <int dim>
  AntiplaneStateBased<dim>::~AntiplaneStateBased() = default;

  template <int dim>
  void
  AntiplaneStateBased<dim>::declare_parameters(ParameterHandler &prm)
  {
    AntiplaneModel<dim>::declare_antiplane_parameters(prm);
    prm.declare_entry("Stabilization",
                      "0.1",
                      Patterns::Double(0.),
                      "The fraction alpha in [0, 1) of the bond-based antiplane energy in the "
                      "energy density, W = (1 - alpha) W_state + alpha W_bond. Both equal "
                      "mu |grad w|^2 / 2 for a uniform gradient; alpha > 0 removes the "
                      "zero-energy (odd-even) modes of the state-based energy, which spoil "
                      "pointwise fields (benchmarks 8.1, 8.2, 8.5 in doc/benchmarks). 0: the "
                      "model of Oterkus & Madenci (2015).");
  }

  template <int dim>
  void
  AntiplaneStateBased<dim>::parse_parameters(ParameterHandler &prm)
  {
    this->parse_antiplane_parameters(prm, "antiplane state based");
    alpha = prm.get_double("Stabilization");
    AssertThrow(alpha >= 0. && alpha < 1.,
                ExcMessage("The parameter <Material/antiplane state based/Stabilization> is " +
                           ParameterUtilities::format_number(alpha) +
                           "; accepted: 0 <= alpha < 1 (the fraction of the bond-based energy)."));
  }

  template <int dim>
  double
  AntiplaneStateBased<dim>::shear_angle_constant() const
  {
    return b_state;
  }

  template <int dim>
  double
  AntiplaneStateBased<dim>::stabilization() const
  {
    return alpha;
  }

  template <int dim>
  const ParticleVector &
  AntiplaneStateBased<dim>::shear_angles() const
  {
    return angles;
  }

  template <int dim>
  void
  AntiplaneStateBased<dim>::initialize(ParticleSystem<dim> &particles,
                                       const ModelContext  &model_context)
  {
    context                                = model_context;
    const std::vector<double> twist_values = this->twist_fields(particles);
    const double              delta = context.horizon, pi = numbers::PI;
    // b delta int_H n_a^2 dV = 1: int_H n_a^2 dV = pi h delta^2 / 2 in 2D, 4 pi delta^3 / 9 in 3D.
    b_state = (dim == 2) ? 2. / (pi * context.thickness * std::pow(delta, 3)) :
                           9. / (4. * pi * std::pow(delta, 4));
    c       = AntiplaneShear::micromodulus(dim, mu, delta, context.thickness);

    const BondList    &bonds   = particles.bonds();
    const auto        &volume  = particles.volumes();
    const auto        &x       = particles.positions();
    const unsigned int n_owned = particles.n_owned();
    state_modulus.resize(n_owned);
    for (unsigned int i = 0; i < n_owned; ++i)
      state_modulus[i] = (1. - alpha) * region_moduli.at(x[i], mu);
    state_coefficient.resize(bonds.size());
    for (unsigned int i = 0; i < n_owned; ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        state_coefficient[b] =
          delta * bonds.volume_factor(b) * volume[i] * volume[bonds.neighbor[b]];

    Kernel &k = *kernel;
    k.twist_field.clear();
    k.blocks.reinit(particles);
    k.blocks.to_lanes(state_coefficient, k.lane_weight);
    k.blocks.reinit_field(k.w_field, 1);
    k.blocks.reinit_field(k.s_field, dim);
    k.blocks.reinit_field(k.r_field, dim);
    k.blocks.reinit_field(k.f_field, 1);
    k.blocks.reinit_field(k.e_field, 1);
    particles.reinit_vector(angles, dim);
    particles.reinit_vector(force_state, dim);

    // Per-point correction (seed eqs. 50-54): g_i,a = 1 / (b sum_j omega x_a n_a V_j chi), one
    // over the shear angle of w = x_a without correction (omega x_a n_a = delta n_a^2), over
    // the intact bonds of the family: the faces of a pre-crack are free faces like the outer
    // ones (bonds broken later do not change it). angle_factor holds b g.
    angle_factor.assign(std::size_t(n_owned) * dim, b_state);
    if (context.surface_correction)
      {
        std::vector<double> sum(std::size_t(n_owned) * dim, 0.);
        for (unsigned int i = 0; i < n_owned; ++i)
          for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
            if (bonds.intact[b] != 0)
              {
                const unsigned int j = bonds.neighbor[b];
                for (unsigned int a = 0; a < dim; ++a)
                  {
                    const double n_a = (x[j][a] - x[i][a]) / bonds.length[b];
                    const double p   = state_coefficient[b] * n_a * n_a;
                    sum[i * dim + a] += p / volume[i];
                    if (j < n_owned)
                      sum[j * dim + a] += p / volume[j];
                  }
              }
        for (std::size_t q = 0; q < sum.size(); ++q)
          angle_factor[q] = 1. / sum[q];
      }

    // The bond-based term: the shared surface correction (surface_correction_law()), then its
    // fraction alpha.
    apply_surface_correction<dim>(*this, particles, context);
    set_bond_coefficients(particles, alpha * c, true);
    // The twist enters after the surface correction, which describes the untwisted geometry.
    if (twist.active())
      {
        k.blocks.reinit_field(k.twist_field, 2);
        k.blocks.gather(twist_values.data(), 2, k.twist_field);
      }
    this->fracture_factor = 1.;
    if (context.lattice_fracture)
      {
        // The energy is not a sum of bond energies: a cleave of a box of the same lattice
        // measures what the continuum's critical slope of 1 J/m^2 dissipates (a model of the
        // same mu and alpha, without region moduli and twist: the ratio does not depend on mu).
        AntiplaneStateBased<dim> probe;
        probe.mu                       = mu;
        probe.alpha                    = alpha;
        ModelContext probe_context     = context;
        probe_context.lattice_fracture = false;
        const double r0                = this->critical_stretch(1.);
        this->fracture_factor =
          1. / std::sqrt(cleave_fracture_energy<dim>(particles.settings(),
                                                     probe,
                                                     probe_context,
                                                     r0,
                                                     particles.get_communicator()));
      }
  }

  template <int dim>
  std::unique_ptr<SurfaceCorrectionLaw<dim>>
  AntiplaneStateBased<dim>::surface_correction_law(ParticleSystem<dim> &particles)
  {
    // The bond-based term only (the state term has its per-point correction): the energy
    // method of AntiplaneBondBased on its own energy (pass 2 with s = 0 and the full
    // micromodulus); the model then takes its fraction alpha.
    if (!(alpha > 0.))
      return nullptr;
    auto law                      = std::make_unique<SurfaceCorrectionLaw<dim>>();
    law->uncorrected_coefficients = [this, &particles]() {
      set_bond_coefficients(particles, c, false);
    };
    law->energy_density = [this, &particles](const ParticleVector &w,
                                             std::vector<double>  &density) {
      Kernel &k = *kernel;
      k.blocks.sync_state(particles.bonds());
      k.blocks.gather(w.begin(), 1, k.w_field);
      std::fill(k.s_field.begin(), k.s_field.end(), 0.);
      k.template force_loop<true>(particles.bonds());
      density.resize(particles.n_owned());
      k.blocks.scatter_owned(k.e_field, 1, particles.volumes().data(), density.data());
    };
    law->modulus.fill(mu);
    return law;
  }

  template <int dim>
  void
  AntiplaneStateBased<dim>::set_bond_coefficients(const ParticleSystem<dim> &particles,
                                                  const double               micromodulus,
                                                  const bool                 with_surface_factor)
  {
    bond_pair_coefficients(particles, micromodulus, with_surface_factor, bond_coefficient);
    if (with_surface_factor)
      region_moduli.scale_bonds(particles, mu, bond_coefficient);
    kernel->blocks.to_lanes(bond_coefficient, kernel->lane_coefficient);
  }

  template <int dim>
  void
  AntiplaneStateBased<dim>::compute_forces(ParticleSystem<dim>  &particles,
                                           const ParticleVector &w,
                                           ParticleVector       &force,
                                           std::vector<double>  *energy_density,
                                           const double          critical_slope)
  {
    Kernel            &k       = *kernel;
    BondList          &bonds   = particles.bonds();
    const double      *volume  = particles.volumes().data();
    const auto        &beta    = particles.energy_weights();
    const unsigned int n_owned = particles.n_owned();
    k.blocks.sync_state(bonds);
    k.blocks.gather(w.begin(), 1, k.w_field);

    // Pass 1: break bonds, then the shear angles r = b g (.) sum / V_i and the force states
    // s = (1 - alpha) mu_i beta_i r (.) b g (beta_i the energy weight of a blended coupling).
    k.angle_loop(bonds, critical_slope);
    double *r = angles.begin();
    k.blocks.scatter_owned(k.r_field, dim, volume, r);
    for (unsigned int i = 0; i < n_owned; ++i)
      for (unsigned int a = 0; a < dim; ++a)
        {
          const std::size_t q = std::size_t(i) * dim + a;
          r[q] *= angle_factor[q];
          force_state.local_element(q) = state_modulus[i] * beta[i] * angle_factor[q] * r[q];
        }
    force_state.update_ghost_values();
    k.blocks.gather(force_state.begin(), dim, k.s_field);

    // Pass 2: forces (and energy), summed per particle and divided by V_i.
    if (energy_density != nullptr)
      {
        k.template force_loop<true>(bonds);
        energy_density->resize(n_owned);
        k.blocks.scatter_owned(k.e_field, 1, volume, energy_density->data());
        for (unsigned int i = 0; i < n_owned; ++i)
          {
            double r2 = 0.;
            for (unsigned int a = 0; a < dim; ++a)
              r2 += r[i * dim + a] * r[i * dim + a];
            (*energy_density)[i] += 0.5 * state_modulus[i] * beta[i] * r2;
          }
      }
    else
      k.template force_loop<false>(bonds);
    k.blocks.scatter_owned(k.f_field, 1, volume, force.begin());
  }

  template <int dim>
  unsigned int
  AntiplaneStateBased<dim>::force_reach() const
  {
    return 2;
  }

  template <int dim>
  std::string
  AntiplaneStateBased<dim>::summary() const
  {
    std::ostringstream out;
    out << "antiplane state based: mu = " << mu << " Pa, b = " << b_state << " 1/m^4"
        << ", stabilization alpha = " << alpha;
    if (alpha > 0.)
      out << " (bond-based micromodulus c = " << c << " N/m^6)";
    else
      out << " (the seed's model: its zero-energy modes make pointwise fields oscillate; "
             "<Stabilization> = 0.1 removes them, doc/theory/models.md)";
    out << this->antiplane_summary();
    return out.str();
  }

  template class AntiplaneStateBased<2>;
  template class AntiplaneStateBased<3>;
} // namespace perideal

PERIDEAL_REGISTER_MATERIAL_MODEL(perideal::AntiplaneStateBased,
                                 "antiplane state based",
                                 "ordinary state-based antiplane shear (seed 000): one scalar w "
                                 "per particle; shear modulus mu, optional stabilization by a "
                                 "fraction of the bond-based energy.")
