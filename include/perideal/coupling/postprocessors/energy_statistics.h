// ---------------------------------------------------------------------
// PeriDeal: energies, the work of the loads and the energy balance of a run.
// ---------------------------------------------------------------------
#ifndef perideal_coupling_postprocessors_energy_statistics_h
#define perideal_coupling_postprocessors_energy_statistics_h

#include <perideal/base/energy_balance.h>
#include <perideal/coupling/postprocessors/postprocessor.h>

namespace perideal
{
  /**
   * @brief The energies of a run and their balance against the work of the loads.
   *
   * The strain energy is the coupled system's, each part of the body counted once, as the
   * coupling method reports it (CouplingMethod::strain_energy()) from the FE field and the
   * particles' energy. Explicit runs: kinetic energy (FE lumped masses, particles that do not
   * follow the FE field), strain energy (the particles' from the model's energy density), the
   * work of the loads and the energy error KE + SE - W - E_0 (EnergyBalance, which also stops a
   * run whose energy grows without bound). Quasi-static runs: the strain energy with the
   * particles' in the coupling method's model of equilibrium, the work of the loads and their
   * difference, relative to the work where the energies are not round-off.
   * Columns kinetic_energy (explicit), strain_energy, fe_strain_energy and pd_strain_energy
   * (quasi-static), external_work, energy_error.
   */
  template <int dim>
  class EnergyStatistics : public Postprocessor<dim>
  {
  public:
    void
    execute(const CoupledState<dim> &state,
            const StepData          &data,
            StatisticsFile          &statistics) override;

  private:
    EnergyBalance balance;
  };
} // namespace perideal

#endif
