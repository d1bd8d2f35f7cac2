// ---------------------------------------------------------------------
// PeriDeal: the stiffness bound and the linearization of the linear peridynamic solid (LPS), for
// the stable step and the quasi-static solvers (compiled without the kernel options).
// ---------------------------------------------------------------------
#include <perideal/pd/linear_peridynamic_solid.h>
#include <perideal/pd/linearization_rows.h>

#include <cmath>

namespace perideal
{
  using namespace dealii;
  using namespace LinearizationRows;

  // LPS: the Gershgorin estimate behind stable_time_step() (direct deviatoric stiffness plus the
  // dilatation coupling), doubled for the block Gershgorin bound.
  template <int dim>
  void
  LinearPeridynamicSolid<dim>::stiffness_bound(const ParticleSystem<dim> &particles,
                                               std::vector<double>       &per_particle) const
  {
    const BondList     &bonds   = particles.bonds();
    const auto         &volume  = particles.volumes();
    const unsigned int  n_owned = particles.n_owned();
    const double        n       = dim;
    const double        alpha_m = shear_modulus * n * (n + 2.);
    const double        kappa   = std::abs(n * bulk_modulus - (n + 2.) * shear_modulus);
    const auto         &beta    = particles.energy_weights();
    std::vector<double> direct(n_owned, 0.), moment(n_owned, 0.);
    for (unsigned int i = 0; i < n_owned; ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        {
          if (!bonds.intact[b])
            continue;
          const unsigned int j = bonds.neighbor[b];
          const double       k = (beta[i] * alpha_m / weighted_volume.local_element(i) +
                            beta[j] * alpha_m / weighted_volume.local_element(j)) *
                           pair_weight[b];
          const double r = pair_weight[b] * bonds.length[b];
          direct[i] += k / volume[i];
          moment[i] += r / volume[i];
          if (j < n_owned)
            {
              direct[j] += k / volume[j];
              moment[j] += r / volume[j];
            }
        }
    per_particle.assign(std::size_t(n_owned) * dim, 0.);
    for (unsigned int i = 0; i < n_owned; ++i)
      {
        const double m_i = weighted_volume.local_element(i);
        for (unsigned int d = 0; d < dim; ++d)
          per_particle[i * dim + d] =
            2. * (direct[i] + 2. * n * kappa * beta[i] * moment[i] * moment[i] / (m_i * m_i));
      }
  }

  // LPS linearized (doc/theory/models.md): W_i = (n k - (n+2) mu)/(2 n) theta_i^2
  // + (alpha_i / 2) sum_j omega e^2 V_j chi, because the deviatoric sum expands to
  // sum omega e^2 V - theta_i^2 m_i / n^2 and alpha_i m_i = mu n (n + 2). Hence, with the
  // energy weights b_i of a blended coupling (E = sum_i b_i W_i V_i) and e_b = n_b . (u_j - u_i):
  // one row e_b per intact bond with weight k_b = (b_i alpha_i + b_j alpha_j) omega chi V_i V_j,
  // and one row theta_i = sum_{b at i} g_b^(i) e_b per owned particle with weight
  // w_i = b_i V_i (n k - (n+2) mu) / n, g_b^(i) = (n / m_i) omega chi |xi| V_j. theta_i collects
  // the bonds stored in row i and those stored in the row of an owned neighbour. With a
  // temperature change the same identity holds for the mechanical extensions e_b - o_b,
  // o_b = a |xi| DeltaT_b (doc/theory/thermal_strain_state_based.md): the bond row's offset is
  // o_b, the dilatation row's sum_b g_b^(i) o_b.
  template <int dim>
  void
  LinearPeridynamicSolid<dim>::linearize(const ParticleSystem<dim> &particles,
                                         LinearizedModel           &linearized) const
  {
    const BondList                                  &bonds   = particles.bonds();
    const auto                                      &volume  = particles.volumes();
    const unsigned int                               n_owned = particles.n_owned();
    const double                                     n       = dim;
    const double                                     alpha_m = shear_modulus * n * (n + 2.);
    const auto                                      &beta    = particles.energy_weights();
    std::vector<double>                              k(bonds.size(), 0.);
    std::vector<std::vector<LinearizedModel::Entry>> theta(n_owned);
    const ParticleVector                            *delta_T = this->temperature_change();
    std::vector<double>                              offset(bonds.size(), 0.);
    std::vector<double>                              theta_offset(n_owned, 0.);
    for (unsigned int i = 0; i < n_owned; ++i)
      {
        const double m_i = weighted_volume.local_element(i);
        for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
          {
            if (!bonds.intact[b])
              continue;
            const unsigned int j   = bonds.neighbor[b];
            const double       m_j = weighted_volume.local_element(j);
            k[b]             = (beta[i] * alpha_m / m_i + beta[j] * alpha_m / m_j) * pair_weight[b];
            const double r   = n * pair_weight[b] * bonds.length[b];
            const double g_i = r / m_i / volume[i], g_j = r / m_j / volume[j];
            if (delta_T != nullptr)
              offset[b] = planar_expansion * bonds.length[b] * 0.5 *
                          (delta_T->local_element(i) + delta_T->local_element(j));
            if (g_i != 0.)
              {
                add_extension(particles, i, b, g_i, theta[i]);
                theta_offset[i] += g_i * offset[b];
              }
            if (j < n_owned && g_j != 0.)
              {
                add_extension(particles, i, b, g_j, theta[j]);
                theta_offset[j] += g_j * offset[b];
              }
          }
      }
    linearized.reinit(this->field_layout().n_components(), n_owned);
    add_bond_rows(particles, k, extension_row<dim>(particles), linearized, &offset);
    for (unsigned int i = 0; i < n_owned; ++i)
      linearized.add_row(beta[i] * volume[i] * (n * bulk_modulus - (n + 2.) * shear_modulus) / n,
                         theta[i],
                         theta_offset[i]);
  }

  template void
  LinearPeridynamicSolid<2>::stiffness_bound(const ParticleSystem<2> &,
                                             std::vector<double> &) const;
  template void
  LinearPeridynamicSolid<3>::stiffness_bound(const ParticleSystem<3> &,
                                             std::vector<double> &) const;
  template void
  LinearPeridynamicSolid<2>::linearize(const ParticleSystem<2> &, LinearizedModel &) const;
  template void
  LinearPeridynamicSolid<3>::linearize(const ParticleSystem<3> &, LinearizedModel &) const;
} // namespace perideal
