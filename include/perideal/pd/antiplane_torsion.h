// ---------------------------------------------------------------------
// PeriDeal: what the antiplane models need for Saint-Venant torsion (the warping as unknown).
// ---------------------------------------------------------------------
#ifndef perideal_pd_antiplane_torsion_h
#define perideal_pd_antiplane_torsion_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/tensor.h>

#include <perideal/base/linear_algebra.h>
#include <perideal/base/torsion.h>
#include <perideal/pd/particle_system.h>

#include <string>
#include <vector>

namespace perideal
{
  /**
   * @brief The parts of Saint-Venant torsion (Torsion) that do not depend on the antiplane
   * model: the fixed twist fields of the pair law, the check that the section holds the
   * horizon, and the stresses, torque and energy of a warping field (doc/theory/models.md,
   * "Torsion").
   */
  namespace AntiplaneTorsion
  {
    /**
     * @brief The extent in x and y of the particles' lattice cells (their positions widened by
     * half a lattice spacing), over all ranks (collective).
     */
    template <int dim>
    dealii::BoundingBox<2>
    section_box(const ParticleSystem<dim> &particles);

    /**
     * @brief Stop, naming <Discretization/Horizon factor> and <Discretization/Lattice
     * spacing>, unless the particles' section (section_box()) is at least two horizons wide in
     * x and in y (collective). The twist axis is checked against the whole body
     * (Torsion::check_axis()), not here: a PD region away from the axis is accepted.
     */
    template <int dim>
    void
    check_section(const ParticleSystem<dim> &particles);

    /**
     * @brief The fixed fields of TwistedSlopePairLaw per local (owned and ghost) particle, two
     * per particle: p = psi (x - x0), q = psi (y - y0).
     */
    template <int dim>
    std::vector<double>
    twist_fields(const ParticleSystem<dim> &particles, const Torsion &torsion);

    /**
     * @brief The gradient of the scalar field @p w (ghost values current) at each owned
     * particle by least squares over its intact bonds (weights chi V_j):
     *   grad w_i = K_i^-1 sum_j chi V_j xi (w_j - w_i),  K_i = sum_j chi V_j xi (x) xi,
     * exact for linear fields at every particle whose intact bonds span the plane, boundary
     * particles included (the shape tensor of correspondence models, Silling et al. 2007,
     * J. Elasticity 88, eq. 15, with influence 1). Zero where K_i is singular.
     */
    template <int dim>
    void
    scalar_gradient(const ParticleSystem<dim>           &particles,
                    const ParticleVector                &w,
                    std::vector<dealii::Tensor<1, dim>> &gradient);

    /**
     * @brief The shear stresses tau_i = mu (grad w_i + psi (-(y_i - y0), x_i - x0)) of the owned
     * particles, grad w by scalar_gradient().
     */
    template <int dim>
    void
    shear_stresses(const ParticleSystem<dim>           &particles,
                   const ParticleVector                &w,
                   const Torsion                       &torsion,
                   const double                         shear_modulus,
                   std::vector<dealii::Tensor<1, dim>> &tau);

    /**
     * @brief The names of section_integrals(): "torque", "torsion_energy".
     */
    std::vector<std::string>
    integral_names();

    /**
     * @brief The torque per unit length T = sum_i beta_i ((x_i - x0) tau_yz - (y_i - y0)
     * tau_xz) V_i / h (midpoint rule, tau of shear_stresses(), beta_i the coupling's energy
     * weight) and the strain energy per unit length @p strain_energy / h (collective).
     */
    template <int dim>
    std::vector<double>
    section_integrals(const ParticleSystem<dim> &particles,
                      const ParticleVector      &w,
                      const Torsion             &torsion,
                      const double               shear_modulus,
                      const double               strain_energy);
  } // namespace AntiplaneTorsion
} // namespace perideal

#endif
