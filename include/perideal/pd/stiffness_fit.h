// ---------------------------------------------------------------------
// PeriDeal: the stiffness fit, a surface correction that restores each particle's whole
// elasticity tensor.
// ---------------------------------------------------------------------
#ifndef perideal_pd_stiffness_fit_h
#define perideal_pd_stiffness_fit_h

#include <deal.II/base/tensor.h>

#include <perideal/pd/particle_system.h>

#include <functional>
#include <string>
#include <vector>

namespace perideal
{
  /**
   * @brief What apply_stiffness_fit() achieved: the largest and the root-mean-square deviation
   * of a particle's elasticity tensor from the interior's before and after (relative to the
   * interior's largest entry), the range of the bond factors and the bonds held at a bound.
   */
  struct StiffnessFitReport
  {
    /// The factor of the interior, the model's C_1111 over the lattice's.
    double interior_scale = 1.;
    /// The largest and the root-mean-square deviation before and after the fit.
    ///@{
    double largest_before = 0.;
    double largest_after  = 0.;
    double rms_before     = 0.;
    double rms_after      = 0.;
    ///@}
    /// The smallest and the largest bond factor.
    ///@{
    double smallest_factor = 1.;
    double largest_factor  = 1.;
    ///@}
    /// The bonds held at a bound of the factors.
    unsigned long held = 0;

    /// One line for a model's summary.
    std::string
    summary() const;
  };

  /**
   * @brief The energy of a bond under a homogeneous strain e at one of its ends, per unit
   * chi V_i V_j (partial-volume factor and volumes): e:H:e / 2 with
   * H = axial a a^T + shear sum_k r_k^T r_k in Voigt notation, i.e. axial (n.e.n)^2 / 2 +
   * shear |e.n|^2 / 2 (n = xi/|xi|); a function of the bond vector xi (its length, and its
   * direction for an anisotropic micromodulus) that sets axial and shear.
   */
  template <int dim>
  using BondStiffnessLaw = std::function<void(const dealii::Tensor<1, dim> &, double &, double &)>;

  /**
   * @brief Set BondList::surface_factor by the stiffness fit (doc/theory/models.md, "Surface
   * correction: the stiffness fit").
   *
   * The elasticity tensor of particle i is D_i V_i = sum_j G_b beta_b V_i V_j H_b (@p law of
   * the bond vector); the interior's D is that of the lattice family
   * (ParticleSystem::lattice_family(): chi V_j per neighbour).
   * The factors G_b = 1 + h_b . (lambda_i + lambda_j), h_b the entries of H_b, are the
   * smallest change of the bonds that gives every owned particle the interior's D, in the
   * least-squares sense rho sum_b (G_b - 1)^2 + sum_i |D_i - D|^2 with rho = 1e-2 of the mean
   * diagonal of the normal equations (a corner's family lacks whole directions and cannot
   * reach D); the multipliers, one symmetric Voigt matrix per particle, solve the normal
   * equations by conjugate gradients. A factor outside [0.2, 5] is held at the bound it crossed
   * and the others are fitted again, so every bond keeps a positive stiffness. At the end every
   * factor is multiplied by @p modulus / D_11 (the model's target C_1111 over the interior
   * lattice's, 1 for a lattice-calibrated model), the interior rescaling of the energy method,
   * which restores C_aaaa of the model's target (the lattice's family misses the volume the book
   * partial volumes leave out). Every bond takes part, broken or not: the fit describes the
   * uncracked geometry.
   */
  template <int dim>
  StiffnessFitReport
  apply_stiffness_fit(ParticleSystem<dim>         &particles,
                      const BondStiffnessLaw<dim> &law,
                      const double                 modulus);
} // namespace perideal

#endif
