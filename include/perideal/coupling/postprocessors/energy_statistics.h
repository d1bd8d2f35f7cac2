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
   * particles' energy. Explicit runs: kinetic energy (FE lumped masses, particles not
   * slaved to the FE field), strain energy (the particles' from the model's energy density), the
   * work of the loads and the energy error KE + SE + D - W - E_0 (EnergyBalance, which also
   * stops a run whose energy grows without bound). Quasi-static runs: the strain energy with
   * the particles' in the coupling method's model of equilibrium, the work of the loads, that of
   * a changing temperature W_T (CoupledState::temperature_work()) and the error
   * W + W_T - SE - D, relative to the work (with a temperature: |W| + |W_T| or the energy the
   * temperature moved, whichever is larger) where the energies are not round-off.
   *
   * D, the dissipated energy, is the strain energy the broken bonds took with them since the
   * start (CoupledState::dissipated_energy()): per force evaluation that broke bonds, the drop
   * of the model's energy at the displacement of that evaluation, E(u, bonds before) - E(u,
   * bonds after) (MaterialModel::released_energy(): for a bond-based model the energy
   * k s^2 |xi| / 2 of each broken bond, k = c G chi V_i V_j with its surface-correction,
   * partial-volume and blending weights; for LPS the change of the dilatation terms of both
   * ends as well). An explicit run then closes KE + SE + D = W + E_0 to the time-integration
   * error. A quasi-static run breaks bonds at a converged state and solves again at the same
   * load: the energy the re-solve releases (kinetic energy in a dynamic run) stays in its error.
   *
   * Columns kinetic_energy (explicit), strain_energy, fe_strain_energy and pd_strain_energy
   * (quasi-static), external_work, temperature_work (quasi-static runs with a temperature),
   * dissipated_energy (runs whose damage model can break bonds), energy_error.
   */
  template <int dim>
  class EnergyStatistics : public Postprocessor<dim>
  {
  public:
    void
    execute(const CoupledState<dim> &state,
            const StepData          &data,
            StatisticsFile          &statistics) override;

    /// The energy balance's totals.
    std::string
    save_state(const CoupledState<dim> &state) const override;

    void
    load_state(const CoupledState<dim> &state, const std::string &packed) override;

  private:
    EnergyBalance balance;
  };
} // namespace perideal

#endif
