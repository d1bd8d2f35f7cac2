// ---------------------------------------------------------------------
// PeriDeal: the bond rows of the Timoshenko bond model: its linearization, stiffness bound and the
// energy its broken bonds release.
// ---------------------------------------------------------------------
#include <perideal/pd/timoshenko_bond_based.h>
#include <perideal/pd/timoshenko_kernel.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace perideal
{
  using namespace dealii;

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
    std::array<Tensor<1, dim>, dim - 1> e;
    std::array<Tensor<1, 3>, dim - 1>   axis;
    if constexpr (dim == 2)
      {
        e[0][0]    = -n[1];
        e[0][1]    = n[0];
        axis[0][2] = 1.;
      }
    else
      {
        Tensor<1, 3> a;
        a[std::abs(n[0]) < 0.6 ? 0 : 1] = 1.;
        const Tensor<1, 3> normal_to_a  = cross_product_3d(n, a);
        e[0]                            = normal_to_a / normal_to_a.norm();
        e[1]                            = cross_product_3d(n, e[0]);
        axis[0]                         = e[1]; // n x e[0]
        axis[1]                         = cross_product_3d(n, e[1]);
      }
    // A row's entries (at most 2 (dim + rotations) <= 4 dim, the shear rows), no allocation per
    // bond: the stiffness bound of a 3D lattice forms its rows for millions of bonds.
    std::array<Entry, 4 * dim> entries;
    unsigned int               n_entries = 0;
    const auto add = [&](const unsigned int p, const unsigned int c, const double g) {
      entries[n_entries++] = {p, c, g};
    };
    const auto emit_row = [&](const double weight, const unsigned int mode, const double offset) {
      emit(weight, ArrayView<const Entry>(entries.data(), n_entries), mode, offset);
      n_entries = 0;
    };
    // Stretch: n . (u_j - u_i), weight k C_N / |xi|, offset the thermal extension.
    for (unsigned int d = 0; d < dim; ++d)
      {
        add(i, d, -n[d]);
        add(j, d, n[d]);
      }
    const ParticleVector *delta_T = this->temperature_change();
    emit_row(k * C.normal / r,
             0u,
             delta_T != nullptr ? bond_expansion() * 0.5 *
                                    (delta_T->local_element(i) + delta_T->local_element(j)) * r :
                                  0.);
    // Shear strains: e . (u_j - u_i) / |xi| - (n x e) . (theta_i + theta_j) / 2, weight
    // 12 k C_theta / |xi|.
    if (C.shear != 0.)
      for (unsigned int a = 0; a < e.size(); ++a)
        {
          for (unsigned int d = 0; d < dim; ++d)
            {
              add(i, d, -e[a][d] / r);
              add(j, d, e[a][d] / r);
            }
          for (unsigned int q = 0; q < Kernel::n_components - n_trans; ++q)
            {
              const double g = -0.5 * axis[a][dim == 2 ? 2 : q];
              add(i, n_trans + q, g);
              add(j, n_trans + q, g);
            }
          emit_row(12. * k * C.shear / r, 1u, 0.);
        }
    // Bending rotations: e . (theta_j - theta_i) (2D: rz_j - rz_i), weight k C_B / |xi|.
    if (C.bending != 0.)
      for (unsigned int a = 0; a < (dim == 2 ? 1 : 2); ++a)
        {
          for (unsigned int q = 0; q < Kernel::n_components - n_trans; ++q)
            {
              const double g = (dim == 2 ? 1. : e[a][q]);
              add(i, n_trans + q, -g);
              add(j, n_trans + q, g);
            }
          emit_row(k * C.bending / r, 2u, 0.);
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
                      [&](const double       w,
                          const auto        &entries,
                          const unsigned int mode,
                          const double       offset) {
                        const double mu = factor[mode].empty() ? 1. : factor[mode][b];
                        linearized.add_row(w * mu * particles.bond_share(b), entries, offset);
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
    per_particle.assign(std::size_t(n_owned) * nc, 0.);
    for (unsigned int i = 0; i < n_owned; ++i)
      for (std::size_t b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        if (bonds.intact[b])
          bond_rows(particles,
                    i,
                    b,
                    [&](const double w, const auto &entries, unsigned int, double) {
                      // sum_e |g_e| sqrt(rho_c / rho_e) from the sums over the translations and
                      // over the rotations: sqrt(J / rho) = ratio between the two.
                      double translations = 0., rotations = 0.;
                      for (const auto &other : entries)
                        (other.component < unsigned(dim) ? translations : rotations) +=
                          std::abs(other.coefficient);
                      const double of_translation = translations + rotations / ratio,
                                   of_rotation    = rotations + ratio * translations;
                      for (const auto &entry : entries)
                        if (entry.particle < n_owned)
                          per_particle[entry.particle * nc + entry.component] +=
                            w * std::abs(entry.coefficient) *
                            (entry.component < unsigned(dim) ? of_translation : of_rotation);
                    });
    // The sums are forces per volume of the particle.
    for (unsigned int i = 0; i < n_owned; ++i)
      for (unsigned int c = 0; c < nc; ++c)
        per_particle[i * nc + c] /= particles.volumes()[i];
  }

  template <int dim>
  double
  TimoshenkoBondBased<dim>::released_energy(ParticleSystem<dim> &particles, const ParticleVector &u)
  {
    BondList &bonds    = particles.bonds();
    double    released = 0.;
    // The bond energy 1/2 sum_r w_r (G_r u - o_r)^2 of each newly broken bond (factors as they
    // were).
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
        const unsigned int i = bonds.row_of(b);
        bond_rows(
          particles,
          i,
          b,
          [&](const double w, const auto &entries, const unsigned int mode, const double offset) {
            double strain = -offset;
            for (const auto &entry : entries)
              strain += entry.coefficient * u.local_element(entry.particle * nc + entry.component);
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

  template void
  TimoshenkoBondBased<2>::linearize(const ParticleSystem<2> &, LinearizedModel &) const;
  template void
  TimoshenkoBondBased<3>::linearize(const ParticleSystem<3> &, LinearizedModel &) const;
  template void
  TimoshenkoBondBased<2>::stiffness_bound(const ParticleSystem<2> &, std::vector<double> &) const;
  template void
  TimoshenkoBondBased<3>::stiffness_bound(const ParticleSystem<3> &, std::vector<double> &) const;
  template double
  TimoshenkoBondBased<2>::released_energy(ParticleSystem<2> &, const ParticleVector &);
  template double
  TimoshenkoBondBased<3>::released_energy(ParticleSystem<3> &, const ParticleVector &);
} // namespace perideal
