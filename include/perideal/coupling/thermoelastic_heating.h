// ---------------------------------------------------------------------
// PeriDeal: the thermoelastic heating of a two-way coupling: the mechanics' deformation heats
// the temperature it is strained by.
// ---------------------------------------------------------------------
#ifndef perideal_coupling_thermoelastic_heating_h
#define perideal_coupling_thermoelastic_heating_h

#include <perideal/base/checkpoint_file.h>
#include <perideal/base/linear_algebra.h>
#include <perideal/coupling/coupled_state.h>
#include <perideal/coupling/temperature_source.h>
#include <perideal/fem/fe_region.h>
#include <perideal/pd/particle_region.h>

#include <vector>

namespace perideal
{
  /**
   * @brief The heating -T_0 beta : d eps/dt of the mechanics' deformation in the heat physics
   * (<Temperature/Coupling> = two way; doc/theory/thermoelasticity.md).
   *
   * The mechanics' thermoelastic measure m = beta : eps is taken at the particles from the model
   * (MaterialModel::thermoelastic_measure(), a density per particle) and in the FE region
   * integrated against the heat's shape functions at the quadrature points of the thermal load
   * (FERegion::thermoelastic_measure(), TemperatureSource::add_at_heat_points()), so that the FE
   * heating is the transpose of the coupling that the thermal load applies.
   *
   * The step is the adiabatic split of Armero and Simo (1992): within the mechanics' step, once
   * its displacements reached u_{n+1} and before its forces there are computed, heat_step()
   * changes the heat's temperature at constant entropy by the heating of the step, -T_0 (m_{n+1}
   * - m_n) V / C at the heat's free particles and dofs (C their heat capacities; the particles
   * slaved to the FE dofs through P^T, as the explicit step adds their forces), all at once; then
   * the heat conducts over the step at that configuration, and the mechanics' forces at u_{n+1}
   * read the temperature of t_{n+1}. So nothing of the coupling lags a step behind: the entropy
   * sum (C_i T_i / T_0) + sum m (in weighted volume) of an insulated body is kept to round-off,
   * and the step is stable up to velocity Verlet's limit at the adiabatic frequency.
   */
  template <int dim>
  class ThermoelasticHeating
  {
  public:
    /**
     * @brief Heat the state @p heat by the deformation of the mechanics: its particle region
     * @p pd and FE region @p fe with the displacements @p u (particles, owned values read) and @p U
     * (FE), with the temperature @p temperature (Source = heat, two way: T_0 and the heat's shape
     * functions). The references must outlive this object.
     */
    void
    connect(ParticleRegion<dim>          &pd,
            const FERegion<dim>          &fe,
            const ParticleVector         &u,
            const FEVector               &U,
            const TemperatureSource<dim> &temperature,
            CoupledState<dim>            &heat);

    /// Whether connect() was called (a two-way coupling).
    bool
    active() const;

    /// @brief The measure of the mechanics' present state, from which the next step's heating is
    /// taken (at the start of a run).
    void
    start();

    /**
     * @brief The adiabatic phase of a step of the mechanics (its displacements at the step's end,
     * before its forces there): the measure of the present deformation, and the heat's
     * temperature changed by its heating since the last step, -T_0 (m_{n+1} - m_n) V / C at the
     * heat's free particles and FE dofs (ghost values updated; the heat's balance counts it as
     * heat in, CoupledState::add_heat_in()). The present measure becomes the previous one. The
     * heat's rates are to be renewed after it (Solver::renew_rates()).
     */
    void
    heat_step();

    /**
     * @brief Write the measure the next step heats from (particles and the heat's FE dofs) and
     * the heat so far into @p writer's sections "<prefix>...": a checkpoint of a two-way run
     * (Checkpoint::add_part()). Collective.
     */
    void
    save(CheckpointWriter &writer, const std::string &prefix) const;

    /// Read what save() wrote (a restart, on any number of ranks). Collective.
    void
    load(CheckpointReader &reader, const std::string &prefix);

    /// The heat the deformation gave so far, -T_0 sum (m_{n+1} - m_n) over the steps [J] (summed
    /// over the ranks; collective).
    double
    heat() const;

  private:
    /// The measure of the present state: per owned particle, and the FE vector of the heat's
    /// dofs.
    void
    measure(std::vector<double> &particle_measure, FEVector &fe_measure);

    ParticleRegion<dim>          *pd          = nullptr;
    const FERegion<dim>          *fe          = nullptr;
    const ParticleVector         *u           = nullptr;
    const FEVector               *U           = nullptr;
    const TemperatureSource<dim> *temperature = nullptr;
    CoupledState<dim>            *heat_state  = nullptr;
    /// The temperature's component in the heat's particle layout.
    unsigned int component = 0;
    /// The FE and the particles' displacement with ghost values.
    FEVector       displacement;
    ParticleVector particle_displacement;
    /// The measures of the previous and of the present state.
    ///@{
    std::vector<double> previous_particles, present_particles;
    FEVector            previous_fe, present_fe;
    ///@}
    /// heat_step()'s work vectors: the heat of the step on the FE dofs, the heat of the particles
    /// slaved to them.
    ///@{
    FEVector       fe_heating;
    ParticleVector slaved_heating;
    ///@}
    /// This rank's part of heat().
    double local_heat = 0.;
  };
} // namespace perideal

#endif
