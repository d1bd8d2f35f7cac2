// ---------------------------------------------------------------------
// PeriDeal: the stiffness bound and the linearization of the anisotropic bond-based model, for the
// stable step and the quasi-static solvers (compiled without the kernel options).
// ---------------------------------------------------------------------
#include <perideal/pd/anisotropic_bond_based.h>
#include <perideal/pd/linearization_rows.h>

#include <algorithm>
#include <cmath>

namespace perideal
{
  using namespace dealii;
  using namespace LinearizationRows;

  // Anisotropic linearized bond: the block k_b n n^T of PMB with a direction factor that may be
  // negative, so the Gershgorin bound takes |k_b|.
  template <int dim>
  void
  AnisotropicBondBased<dim>::stiffness_bound(const ParticleSystem<dim> &particles,
                                             std::vector<double>       &per_particle) const
  {
    std::vector<double> magnitude(bond_coefficient.size());
    std::transform(bond_coefficient.begin(),
                   bond_coefficient.end(),
                   magnitude.begin(),
                   [](const double k) { return std::abs(k); });
    bond_pair_stiffness_bound(particles, magnitude, dim, per_particle);
  }

  // Anisotropic linearized bond (the model is linear): PMB's rows with k_b = c(n_b) G chi V_i
  // V_j / |xi| and, with a temperature change, the offsets n . alpha . n Delta T_b |xi|.
  template <int dim>
  void
  AnisotropicBondBased<dim>::linearize(const ParticleSystem<dim> &particles,
                                       LinearizedModel           &linearized) const
  {
    linearized.reinit(this->field_layout().n_components(), particles.n_owned());
    const BondList       &bonds   = particles.bonds();
    const ParticleVector *delta_T = this->temperature_change();
    std::vector<double>   offset;
    if (delta_T != nullptr && !bond_expansion.empty())
      {
        offset.assign(bonds.size(), 0.);
        for (unsigned int i = 0; i < particles.n_owned(); ++i)
          for (std::size_t b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
            offset[b] = bond_expansion[b] * bonds.length[b] * 0.5 *
                        (delta_T->local_element(i) + delta_T->local_element(bonds.neighbor[b]));
      }
    add_bond_rows(particles,
                  intact_bond_stiffness(bonds, bond_coefficient),
                  extension_row<dim>(particles),
                  linearized,
                  offset.empty() ? nullptr : &offset);
  }

  template void
  AnisotropicBondBased<2>::stiffness_bound(const ParticleSystem<2> &, std::vector<double> &) const;
  template void
  AnisotropicBondBased<3>::stiffness_bound(const ParticleSystem<3> &, std::vector<double> &) const;
  template void
  AnisotropicBondBased<2>::linearize(const ParticleSystem<2> &, LinearizedModel &) const;
  template void
  AnisotropicBondBased<3>::linearize(const ParticleSystem<3> &, LinearizedModel &) const;
} // namespace perideal
