// ---------------------------------------------------------------------
// PeriDeal: the stiffness bound and the linearization of the bond-based conduction model, for the
// stable step and the static (steady) and implicit solves (compiled without the kernel options).
// ---------------------------------------------------------------------
#include <perideal/pd/bond_based_conduction.h>
#include <perideal/pd/linearization_rows.h>

namespace perideal
{
  using namespace dealii;
  using namespace LinearizationRows;

  // Conduction: the bond b couples T_i and T_j through k_b = kappa G chi V_j / |xi| as the
  // antiplane bonds do w, hence the same bound and rows (the conductance matrix of K T = Q).
  template <int dim>
  void
  BondBasedConduction<dim>::stiffness_bound(const ParticleSystem<dim> &particles,
                                            std::vector<double>       &per_particle) const
  {
    bond_pair_stiffness_bound(particles, bond_coefficient, 1, per_particle);
  }

  template <int dim>
  void
  BondBasedConduction<dim>::linearize(const ParticleSystem<dim> &particles,
                                      LinearizedModel           &linearized) const
  {
    const BondList &bonds = particles.bonds();
    linearized.reinit(1, particles.n_owned());
    add_bond_rows(particles,
                  intact_bond_stiffness(bonds, bond_coefficient),
                  slope_row(bonds),
                  linearized);
  }

  template void
  BondBasedConduction<2>::stiffness_bound(const ParticleSystem<2> &, std::vector<double> &) const;
  template void
  BondBasedConduction<3>::stiffness_bound(const ParticleSystem<3> &, std::vector<double> &) const;
  template void
  BondBasedConduction<2>::linearize(const ParticleSystem<2> &, LinearizedModel &) const;
  template void
  BondBasedConduction<3>::linearize(const ParticleSystem<3> &, LinearizedModel &) const;
} // namespace perideal
