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
   * @brief The heat source -T_0 beta : d eps/dt of the mechanics' deformation in the heat
   * physics (<Temperature/Coupling> = two way; doc/theory/thermoelasticity.md).
   *
   * The mechanics' thermoelastic measure m = beta : eps is taken at the end of each of its
   * steps: at the particles from the model (MaterialModel::thermoelastic_measure(), a density
   * per particle), in the FE region integrated against the heat's shape functions at the
   * quadrature points of the thermal load (FERegion::thermoelastic_measure(),
   * TemperatureSource::add_at_heat_points()), so that the FE source is the transpose of the
   * coupling that the thermal load applies. Over the step of length dt that took the measure
   * from m_n to m_{n+1}, the heat's CoupledState::physics_source is -T_0 (m_{n+1} - m_n) / dt:
   * the heat's sub-steps add -T_0 (m_{n+1} - m_n) in all, so that the entropy
   * sum (C_i T_i / T_0) + sum m (in weighted volume) of an insulated body is kept to round-off.
   *
   * The mechanics does not wait for the heat to see that heating: at each of its force
   * evaluations (CoupledState::update_temperature()) predict() takes the measure of the present
   * deformation and the temperature change the heating of the step will make, -T_0 (m - m_n)
   * V / C at the heat's free particles and dofs (C their heat capacities), which
   * TemperatureSource adds to the heat's temperature it hands the mechanics. So the thermal
   * force at t_{n+1} is that of the adiabatic temperature of u_{n+1}: the coupling is a stiffness
   * of the step, not one lagging a step behind (which made a PD bar unstable in the adiabatic
   * limit: a lagging stiffness is a negative damping); only the conduction lags.
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
     * @brief The measure of the mechanics' present deformation (the displacement of a force
     * evaluation) and the temperature change its heating will make: particle_change() and
     * fe_change().
     */
    void
    predict();

    /// The temperature change of the last predict() at the local particles (ghosts included;
    /// one value per particle) and on the heat's FE dofs (ghost values current).
    ///@{
    const ParticleVector &
    particle_change() const;

    const FEVector &
    fe_change() const;
    ///@}

    /**
     * @brief The heat's source over a step of length @p dt of the mechanics, from the measure
     * of its last predict() (at the step's end): -T_0 (m_{n+1} - m_n) / dt into the heat's
     * physics_source and fe_physics_source; the present measure becomes the previous one.
     */
    void
    heat_step(const double dt);

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
    /// The temperature changes of predict().
    ///@{
    ParticleVector particle_temperature_change;
    FEVector       fe_temperature_change;
    ///@}
    /// predict()'s work vectors: the heat of the step on the FE dofs, the heat of the particles
    /// slaved to them (and then their temperature change).
    ///@{
    FEVector       fe_heating;
    ParticleVector slaved_heating;
    ///@}
    /// This rank's part of heat().
    double local_heat = 0.;
  };
} // namespace perideal

#endif
