// ---------------------------------------------------------------------
// PeriDeal: the fracture energy of the particles' actual lattice, for the lattice calibration of
// the critical stretch.
// ---------------------------------------------------------------------
#ifndef perideal_pd_lattice_fracture_h
#define perideal_pd_lattice_fracture_h

#include <perideal/pd/particle_system.h>

#include <functional>
#include <vector>

namespace perideal
{
  /**
   * @brief The fracture energy [J/m^2] of the actual lattice of @p particles when bond b holds
   * the energy @p bond_energy[b] [J] (bond-list order, owned rows) as it breaks: the energy of
   * the bonds that a plane of normal m cuts, per unit area, averaged over the plane's offset,
   *   G(m) = sum_i 1/2 sum_j |xi_ij . m| E_ij / sum_i V_i,
   * over the interior particles i, averaged over m along the coordinate axes (those of the
   * plane in 2D). On a regular lattice it is the energy of the bonds across a plane between two
   * lattice planes, sum_{xi . m > 0} (xi . m) E(xi) / V; on a perturbed lattice the mean over
   * the cuts. Interior: the particle, its neighbours and their neighbours have at least 0.8 of a
   * complete family's volume (ParticleSystem::lattice_family()), so that its bonds join
   * particles with complete families and the surface factors of the interior; this leaves out
   * about 2.4 horizons along the boundary. Collective; throws if no particle is interior.
   */
  template <int dim>
  double
  lattice_fracture_energy(const ParticleSystem<dim> &particles,
                          const std::vector<double> &bond_energy);

  /**
   * @brief The factor on a model's critical measure (stretch, slope, a mode's limit) that makes
   * its actual lattice dissipate the fracture energy of its continuum calibration:
   * 1 / sqrt(lattice_fracture_energy() / (1 J/m^2)) for the bond energies
   * E_b = @p coefficient[b] @p energy(|xi_b|) that the bonds hold at the critical measure the
   * continuum calibration gives for 1 J/m^2 (the bond energies are quadratic in the measure).
   * @p coefficient: the model's pair coefficients (bond_pair_coefficients(), surface factors
   * included).
   */
  template <int dim>
  double
  lattice_fracture_factor(const ParticleSystem<dim>           &particles,
                          const std::vector<double>           &coefficient,
                          const std::function<double(double)> &energy);
} // namespace perideal

#endif
