// ---------------------------------------------------------------------
// PeriDeal: damage models (when bonds break) and the damage index.
// ---------------------------------------------------------------------
#ifndef perideal_pd_damage_model_h
#define perideal_pd_damage_model_h

#include <deal.II/base/parameter_handler.h>

#include <perideal/base/plugin_registry.h>
#include <perideal/pd/material_model.h>
#include <perideal/pd/particle_system.h>

#include <vector>

namespace perideal
{
  /**
   * @brief Interface of a damage model: the stretch at which a bond breaks irreversibly.
   */
  template <int dim>
  class DamageModel
  {
  public:
    virtual ~DamageModel() = default;

    /**
     * @brief Read the model's own subsection (the caller has entered it).
     */
    virtual void
    parse_parameters(dealii::ParameterHandler &prm) = 0;

    /**
     * @brief The critical stretch for @p material (infinite: bonds never break).
     */
    virtual double
    critical_stretch(const MaterialModel<dim> &material) const = 0;

    /**
     * @brief Whether the material model is to calibrate its critical values on the actual
     * lattice (ModelContext::lattice_fracture): false by default.
     */
    virtual bool
    calibrated_on_lattice() const;

    /**
     * @brief How the bonds fail beyond their elastic limit (ModelContext::softening): brittle
     * by default.
     */
    virtual BondSoftening
    softening() const;
  };

  /**
   * @brief Bonds never break.
   */
  template <int dim>
  class NoDamage : public DamageModel<dim>
  {
  public:
    /// Nothing to declare.
    static void
    declare_parameters(dealii::ParameterHandler &)
    {}
    void
    parse_parameters(dealii::ParameterHandler &) override
    {}
    double
    critical_stretch(const MaterialModel<dim> &material) const override;
  };

  /**
   * @brief A bond breaks for good once its stretch exceeds s0 (Silling & Askari 2005), with s0
   * given directly or from the fracture energy through the material model's calibration: the
   * continuum's formula, or the actual lattice's (<Fracture energy calibration> = lattice).
   * With <Failure law> = linear softening the bond softens instead, from s0 / sqrt(n) to
   * s0 sqrt(n) with the brittle bond's work to break (BondSoftening; for a model whose
   * capabilities() say bond_softening, under the sequentially linear control).
   */
  template <int dim>
  class CriticalStretch : public DamageModel<dim>
  {
  public:
    /// Declare "Fracture energy" and "Critical stretch".
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm) override;
    double
    critical_stretch(const MaterialModel<dim> &material) const override;
    bool
    calibrated_on_lattice() const override;
    BondSoftening
    softening() const override;

  private:
    double        fracture_energy = 0.;
    double        given_stretch   = 0.;
    bool          on_lattice      = false;
    BondSoftening law;
  };

  /**
   * @brief Damage index of each owned particle: phi_i = 1 - sum_j mu_ij V_j chi / sum_j V_j chi
   * with mu_ij = 1 for intact bonds (seed note 002, sec. 4.2).
   */
  template <int dim>
  std::vector<double>
  damage_index(const ParticleSystem<dim> &particles);

  /**
   * @brief Number of broken bonds on all ranks, each bond counted once.
   */
  template <int dim>
  std::uint64_t
  n_broken_bonds(const ParticleSystem<dim> &particles);

  /**
   * @brief For the re-solves of a quasi-static load step (PD or coupled): whether no bond broke
   * in re-solve @p pass of load step @p step (@p broken_before bonds were broken before it) and
   * the bonds' damage did not otherwise change (@p damage_changed:
   * MaterialModel::damage_changed()). Throws ExcNotConverged (unstable crack growth: more
   * <Solver/Load steps> or step cutting) after 100 re-solves.
   */
  template <int dim>
  bool
  breaking_settled(const ParticleSystem<dim> &particles,
                   const std::uint64_t        broken_before,
                   const bool                 damage_changed,
                   const unsigned int         step,
                   const unsigned int         pass);

#define PERIDEAL_REGISTER_DAMAGE_MODEL(classname, name, description)                    \
  PERIDEAL_REGISTER_PLUGIN(::perideal::DamageModel<2>, classname<2>, name, description) \
  PERIDEAL_REGISTER_PLUGIN(::perideal::DamageModel<3>, classname<3>, name, description)
} // namespace perideal

#endif
