// ---------------------------------------------------------------------
// PeriDeal: the energy balance of a dynamic run (work, dissipation, error, instability stop).
// ---------------------------------------------------------------------
#ifndef perideal_base_energy_balance_h
#define perideal_base_energy_balance_h

namespace perideal
{
  /**
   * @brief Kinetic + strain + dissipated energy against the work done on the body, for the
   * statistics of a time-stepping run.
   *
   * The work is that of the loads (external forces, and on prescribed components the force
   * the constraint balances), accumulated by the caller, plus the change of the kinetic energy
   * of the prescribed components (the constraints also accelerate them; it telescopes over the
   * steps). The dissipated energy is the strain energy the broken bonds took with them,
   * accumulated by the caller (MaterialModel::released_energy()). The error is kinetic + strain
   * + dissipated - work - the work of a changing temperature - initial energy - the energy
   * change of the conversions of an adaptive PD region (FE cells become particles; measured and
   * reported on their own): the time-integration error, in a fracture run too.
   */
  class EnergyBalance
  {
  public:
    /**
     * @brief Record the totals (summed over all ranks) of a statistics row; the row of step 0
     * fixes the initial energy and the initial kinetic energy of the prescribed components.
     * @p conversion is the energy change of the conversions so far (0 without an adaptive PD
     * region), @p temperature_work the work of a changing temperature so far (0 without one).
     */
    void
    record(const unsigned int step,
           const double       kinetic,
           const double       strain,
           const double       work_of_loads,
           const double       prescribed_kinetic,
           const double       dissipated,
           const double       conversion       = 0.,
           const double       temperature_work = 0.);

    /// The work done on the body up to the recorded row [J].
    double
    work() const;

    /// kinetic + strain + dissipated - work - temperature work - initial energy - conversion at
    /// the recorded row [J].
    double
    error() const;

    /**
     * @brief Throw, naming the step, the time and the stable time step @p stable_dt, if the
     * energies are not finite or, after 10 steps, have grown beyond 1000 times the energy put
     * in: the run became unstable.
     */
    void
    check_stable(const double time, const double stable_dt) const;

    /// Read or write the recorded totals (boost serialization; a checkpoint keeps them).
    template <class Archive>
    void
    serialize(Archive &archive, const unsigned int)
    {
      archive &step &kinetic &strain &dissipated &total_work &initial_energy &initial_prescribed;
    }

  private:
    unsigned int step               = 0;
    double       kinetic            = 0.;
    double       strain             = 0.;
    double       dissipated         = 0.;
    double       total_work         = 0.;
    double       initial_energy     = 0.;
    double       initial_prescribed = 0.;
    /// Set by every record(): not part of a checkpoint.
    ///@{
    double conversion       = 0.;
    double temperature_work = 0.;
    ///@}
  };
} // namespace perideal

#endif
