// ---------------------------------------------------------------------
// PeriDeal: interface of peridynamic material models.
// ---------------------------------------------------------------------
#ifndef perideal_pd_material_model_h
#define perideal_pd_material_model_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>

#include <perideal/base/elasticity.h>
#include <perideal/base/field_layout.h>
#include <perideal/base/linear_algebra.h>
#include <perideal/base/plugin_registry.h>
#include <perideal/pd/particle_system.h>

#include <string>
#include <vector>

namespace perideal
{
  /**
   * @brief Data every material model needs besides its own parameters.
   */
  struct ModelContext
  {
    /// Horizon delta [m].
    double horizon = 0.;
    /// Thickness h of a 2D body [m].
    double thickness = 1.;
    /// Planar assumption in 2D; three_dimensional in 3D.
    PlanarAssumption planar = PlanarAssumption::three_dimensional;
    /// Whether to apply the model's surface correction.
    bool surface_correction = true;
  };

  /**
   * @brief The small-displacement linearization of a model about the reference configuration,
   * written as a sum of squares (what a model gives to assemble its stiffness matrix).
   *
   * With the linearized bond extension e_b = n_b . (u_j - u_i), n_b = xi/|xi| for the bond b
   * from i to j (the same for both ends), the linearized strain energy is
   *   E = 1/2 sum_b k_b e_b^2 + 1/2 sum_i w_i theta_i^2,
   *   theta_i = sum_{b at i} g_b^(i) e_b,
   * so that the nodal force (force density times V_i) is -dE/du. The per-bond arrays follow the
   * BondList; a bond to a ghost particle is stored on both ranks and counts with
   * ParticleSystem::bond_share(). theta_i of an owned particle i collects the coefficient of row
   * i (bonds stored in row i) and that of column i (bonds stored in the row of an owned j < i).
   */
  struct LinearizedModel
  {
    /// k_b [N/m] per bond (0 for a broken bond).
    std::vector<double> bond_stiffness;
    /// w_i [N m] per owned particle; empty for a model without a dilatation term.
    std::vector<double> dilatation_weight;
    /// g_b^(i) [1/m] per bond for the end i that stores the bond (row end).
    std::vector<double> dilatation_row;
    /// g_b^(j) [1/m] per bond for the other end j (used when j is owned).
    std::vector<double> dilatation_column;
  };

  /**
   * @brief Interface of a peridynamic material model (a plugin, chosen per region by name).
   *
   * The plugin boundary is per region: one virtual call computes the forces of all particles
   * with a tight loop over the bonds inside; no call per bond. The unknowns of a particle are
   * the model's field_layout().
   */
  template <int dim>
  class MaterialModel
  {
  public:
    virtual ~MaterialModel() = default;

    /**
     * @brief Read the model's own subsection (the caller has entered it).
     */
    virtual void
    parse_parameters(dealii::ParameterHandler &prm) = 0;

    /**
     * @brief Compute the per-bond and per-particle constants (micromoduli, weighted volumes,
     * surface corrections); called once the particles and bonds exist.
     */
    virtual void
    initialize(ParticleSystem<dim> &particles, const ModelContext &context) = 0;

    /**
     * @brief The unknowns of a particle (FieldLayout): the displacement x, y(, z) unless the
     * model says otherwise (a scalar antiplane field, translations and rotations).
     */
    virtual FieldLayout
    field_layout() const
    {
      return FieldLayout::displacement(dim);
    }

    /**
     * @brief Force density on each owned particle [N/m^3] for the displacement @p u (ghost
     * values must be current). Bonds stretched beyond @p critical_stretch break first. If
     * @p energy_density is given, it receives the strain-energy density of each owned particle
     * [J/m^3].
     */
    virtual void
    compute_forces(ParticleSystem<dim>  &particles,
                   const ParticleVector &u,
                   ParticleVector       &force,
                   std::vector<double>  *energy_density,
                   const double          critical_stretch) = 0;

    /**
     * @brief The largest stable explicit time step for density @p density [kg/m^3]: the
     * Silling–Askari bound dt = min_i sqrt(2 rho / sum_j V_j C_ij) (Silling & Askari 2005,
     * Comput. Struct. 83, eq. 31) with the model's bond stiffness C_ij, i.e.
     * sqrt(4 rho / max_i stiffness_bound_i). Same on every rank.
     */
    double
    stable_time_step(const ParticleSystem<dim> &particles, const double density) const;

    /**
     * @brief Gershgorin bound of the linearized operator per particle: @p per_particle[i] is
     * an upper bound of sum_j |K_ij| over the rows of owned particle i, K the derivative of the
     * force density [N/m^3] by the displacement [m] (block rows, spectral norms of the dim x dim
     * blocks). It is twice the stiffness sum of stable_time_step(), so that
     * dt_stable = sqrt(4 rho / max_i bound_i). Broken bonds do not count.
     */
    virtual void
    stiffness_bound(const ParticleSystem<dim> &particles,
                    std::vector<double>       &per_particle) const = 0;

    /**
     * @brief The linearization of the model about the reference configuration (intact bonds
     * only), see LinearizedModel.
     */
    virtual void
    linearize(const ParticleSystem<dim> &particles, LinearizedModel &linearized) const;

    /**
     * @brief The classical elasticity tensor the model reproduces for homogeneous deformation.
     */
    virtual dealii::SymmetricTensor<4, dim>
    elasticity_tensor() const = 0;

    /**
     * @brief The critical stretch that dissipates @p fracture_energy [J/m^2] per unit crack area.
     */
    virtual double
    critical_stretch(const double fracture_energy) const = 0;

    /**
     * @brief A few lines for the log: the model's constants, including implied ones.
     */
    virtual std::string
    summary() const = 0;
  };

  /**
   * @brief Register a material model for dim = 2 and 3.
   */
#define PERIDEAL_REGISTER_MATERIAL_MODEL(classname, name, description)                    \
  PERIDEAL_REGISTER_PLUGIN(::perideal::MaterialModel<2>, classname<2>, name, description) \
  PERIDEAL_REGISTER_PLUGIN(::perideal::MaterialModel<3>, classname<3>, name, description)
} // namespace perideal

#endif
