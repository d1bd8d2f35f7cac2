// ---------------------------------------------------------------------
// PeriDeal: the fracture energy of the particles' actual lattice, for the lattice calibration of
// the critical stretch.
// ---------------------------------------------------------------------
#ifndef perideal_pd_lattice_fracture_h
#define perideal_pd_lattice_fracture_h

#include <perideal/pd/material_model.h>
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
   * about 2.4 horizons along the boundary. In a blended FE-PD coupling E_ij is taken without
   * the coupling's energy weight (ParticleSystem::bond_energy_weight(), which @p bond_energy
   * carries: the models' pair coefficients include it), and the interior particles are those
   * of energy weight above zero: the energy of the lattice, the same as without coupling.
   * Collective; throws if no particle is interior.
   */
  template <int dim>
  double
  lattice_fracture_energy(const ParticleSystem<dim> &particles,
                          const std::vector<double> &bond_energy);

  /**
   * @brief The factor on a model's critical measure (stretch, slope, a mode's limit) that makes
   * its actual lattice dissipate the fracture energy of its continuum calibration:
   * 1 / sqrt(lattice_fracture_energy() / (1 J/m^2)) for the bond energies
   * E_b = @p coefficient(i, b) @p energy(|xi_b|) that the bonds hold at the critical measure
   * the continuum calibration gives for 1 J/m^2 (the bond energies are quadratic in the
   * measure). @p coefficient: the model's pair coefficient of bond @p b of owned particle @p i
   * (bond_pair_coefficients(), surface factors included).
   */
  template <int dim>
  double
  lattice_fracture_factor(
    const ParticleSystem<dim>                                          &particles,
    const std::function<double(const unsigned int, const std::size_t)> &coefficient,
    const std::function<double(double)>                                &energy);

  /**
   * @brief The fracture energy [J/m^2] that @p model dissipates, on the lattice of @p settings,
   * when a cleave breaks the bonds across a plane at the critical value @p critical: for a model
   * whose energy is not a sum of bond energies (antiplane state based, LPS), so that the energy a
   * broken bond releases depends on the field.
   *
   * On a box of the lattice (n + 2 ceil(2 delta/dx)) dx wide, n = 12 in 2D and 4 in 3D, with
   * @p model initialized on it (@p context), the half beyond the middle plane normal to the
   * last axis jumps rigidly by Delta: the scalar of a one-component layout (mode III: a bond
   * across the plane reaches the critical slope at Delta = r_c |xi|), else the translation
   * along that axis (mode I: the stretch reaches s_c at Delta = sqrt(xi_n^2 + (2 s_c + s_c^2)
   * |xi|^2) - |xi_n|). Delta is raised through these jumps (binned to 1e-4 relative), each
   * breaking its bonds just above their critical value; the drops of the model's energy of the
   * particles of the middle n dx window (families complete), E(bonds before) - E(bonds after),
   * are summed and divided by the window's area. Collective on @p communicator.
   */
  template <int dim>
  double
  cleave_fracture_energy(const typename ParticleSystem<dim>::Settings &settings,
                         MaterialModel<dim>                           &model,
                         const ModelContext                           &context,
                         const double                                  critical,
                         const MPI_Comm                                communicator);
} // namespace perideal

#endif
