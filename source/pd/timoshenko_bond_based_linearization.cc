// ---------------------------------------------------------------------
// PeriDeal: the bond rows of the Timoshenko bond model: its linearization, stiffness bound and the
// energy its broken bonds release.
// ---------------------------------------------------------------------
#include <perideal/pd/timoshenko_bond_based.h>
#include <perideal/pd/timoshenko_kernel.h>

#include <algorithm>
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
    // Stretch: n . (u_j - u_i), weight k C_N / |xi|, offset the thermal extension.
    for (unsigned int d = 0; d < dim; ++d)
      {
        entries.push_back({i, d, -n[d]});
        entries.push_back({j, d, n[d]});
      }
    const ParticleVector *delta_T = this->temperature_change();
    emit(k * C.normal / r,
         entries,
         0u,
         delta_T != nullptr ?
           bond_expansion() * 0.5 * (delta_T->local_element(i) + delta_T->local_element(j)) * r :
           0.);
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
          for (unsigned int q = 0; q < Kernel::n_components - n_trans; ++q)
            {
              const double g = -0.5 * axis[a][dim == 2 ? 2 : q];
              entries.push_back({i, n_trans + q, g});
              entries.push_back({j, n_trans + q, g});
            }
          emit(12. * k * C.shear / r, entries, 1u, 0.);
        }
    // Bending rotations: e . (theta_j - theta_i) (2D: rz_j - rz_i), weight k C_B / |xi|.
    if (C.bending != 0.)
      for (unsigned int a = 0; a < (dim == 2 ? 1 : 2); ++a)
        {
          entries.clear();
          for (unsigned int q = 0; q < Kernel::n_components - n_trans; ++q)
            {
              const double g = (dim == 2 ? 1. : e[a][q]);
              entries.push_back({i, n_trans + q, -g});
              entries.push_back({j, n_trans + q, g});
            }
          emit(k * C.bending / r, entries, 2u, 0.);
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
    const auto         scale = [&](const unsigned int c, const unsigned int e) {
      const bool rc = c >= unsigned(dim), re = e >= unsigned(dim);
      return rc == re ? 1. : (rc ? ratio : 1. / ratio);
    };
    per_particle.assign(std::size_t(n_owned) * nc, 0.);
    for (unsigned int i = 0; i < n_owned; ++i)
      for (std::size_t b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        if (bonds.intact[b])
          bond_rows(particles,
                    i,
                    b,
                    [&](const double w, const auto &entries, unsigned int, double) {
                      for (const auto &entry : entries)
                        if (entry.particle < n_owned)
                          {
                            double sum = 0.;
                            for (const auto &other : entries)
                              sum += std::abs(other.coefficient) *
                                     scale(entry.component, other.component);
                            per_particle[entry.particle * nc + entry.component] +=
                              w * std::abs(entry.coefficient) * sum /
                              particles.volumes()[entry.particle];
                          }
                    });
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
