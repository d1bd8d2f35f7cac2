// ---------------------------------------------------------------------
// PeriDeal: energies, the work of the loads and the energy balance of a run.
// ---------------------------------------------------------------------
#include <perideal/coupling/postprocessors/energy_statistics.h>

#include <algorithm>
#include <cmath>
#include <iomanip>

namespace perideal
{
  using namespace dealii;

  template <int dim>
  void
  EnergyStatistics<dim>::execute(const CoupledState<dim> &state,
                                 const StepData          &data,
                                 StatisticsFile          &statistics)
  {
    if (!data.write_statistics)
      return;
    const double work = state.external_work();
    // The energy of the broken bonds, for runs that can break them.
    const bool    breaks = state.pd().has_body() && std::isfinite(state.pd().critical_stretch());
    const double  dissipated = state.dissipated_energy();
    std::ostream &log        = state.log();
    const auto    flags      = log.flags();
    log << std::scientific << std::setprecision(6);

    if (data.quasi_static)
      {
        const CoupledEnergy energy = state.strain_energy(data.pd_energy);
        const double        strain = energy.fe + energy.particles;
        // The work of a changing temperature beside that of the loads.
        const bool   heated           = state.has_temperature();
        const double temperature_work = heated ? state.temperature_work() : 0.;
        const double energy_error     = work + temperature_work - strain - dissipated;
        // What the error is relative to: the work of the loads, and the temperature's or the
        // energy it moved.
        const double work_done = heated ? std::max(std::abs(work) + std::abs(temperature_work),
                                                   state.temperature_energy_scale()) :
                                          work;
        // Relative to the work, unless the energies are below 1e-10 of the force scale times the
        // displacement (a rigid motion: round-off); relative to the strain energy if no load
        // works (a model's prestrain, the twist of PD torsion, is the only load).
        state.U.update_ghost_values();
        const double scale = state.fe_force_scale();
        const double max_u = state.max_particle_displacement();
        const double relative_error =
          std::max(std::abs(work_done), strain) > 1e-10 * scale * max_u ?
            energy_error / (work_done != 0. ? work_done : strain) :
            0.;
        statistics.add_value("strain_energy", strain);
        statistics.add_value("fe_strain_energy", energy.fe);
        statistics.add_value("pd_strain_energy", energy.particles);
        statistics.add_value("external_work", work);
        if (heated)
          statistics.add_value("temperature_work", temperature_work);
        if (breaks)
          statistics.add_value("dissipated_energy", dissipated);
        statistics.add_value("energy_error", energy_error);
        if (state.is_root() && data.final_row)
          {
            log << "Strain energy: " << strain << " J";
            if (state.is_coupled())
              log << " (FE " << energy.fe << " J, particles " << energy.particles << " J)";
            log << "\n"
                << "External work: " << work << " J\n";
            if (heated)
              log << "Work of the temperature change: " << temperature_work << " J\n";
            if (breaks)
              log << "Dissipated energy: " << dissipated << " J\n";
            // The particles' twist does no tracked work (in a coupled run the FE twist load
            // does, against only part of the energy): no balance.
            if (state.pd().has_body() && state.pd().material().has_prestrain())
              log << "Energy error: not defined (the twist of torsion is a prestrain, not a "
                     "load whose work is tracked; check T psi = 2E of the section integrals)\n";
            else
              {
                // To the solution's accuracy (multiples of it, relative to the energy).
                const double accuracy = state.solution_accuracy();
                const double unit     = accuracy * std::max(std::abs(work_done), strain);
                log << "Energy error: " << to_accuracy(energy_error, unit) << " J (relative "
                    << to_accuracy(relative_error, accuracy) << ")\n";
              }
          }
      }
    else if (state.layout().has_temperature())
      {
        // The thermal balance of the time steps: the change of the heat stored in the body
        // (free particles and FE dofs) against the heat in through the conditions
        // (CoupledState::accumulate_heat(), weighted as the step), equal to round-off (forward
        // Euler) or to the solver tolerance (theta scheme); less the change the conversions of
        // an adaptive PD region made (CoupledState::conversion_energy).
        const double stored     = state.stored_heat() - state.initial_stored_heat();
        const double heat       = state.heat_in();
        const bool   converts   = state.adaptation_interval() > 0;
        const double conversion = state.conversion_energy;
        statistics.add_value("stored_heat", stored);
        statistics.add_value("heat_in", heat);
        if (converts)
          statistics.add_value("conversion_heat", conversion);
        statistics.add_value("heat_error", stored - heat - conversion);
        if (state.is_root() && data.final_row)
          {
            // Printed to the accuracy of the steps (relative to the heat exchanged): round-off
            // for forward Euler, the solution's accuracy for the theta scheme (0, not -0, when
            // it rounds to nothing).
            const double accuracy = state.settings().solver_type == SolverType::explicit_dynamics ?
                                      1e-12 :
                                      state.solution_accuracy();
            const double scale = std::max({std::abs(stored), std::abs(heat), std::abs(conversion)});
            const double error = to_accuracy(stored - heat - conversion, accuracy * scale);
            const double relative =
              to_accuracy(scale > 0. ? (stored - heat - conversion) / scale : 0., accuracy);
            log << "Stored heat (change): " << stored << " J\n"
                << "Heat in through the conditions: " << heat << " J\n";
            if (converts)
              log << "Heat change of the conversions: " << conversion << " J\n";
            log << "Heat error: " << (error == 0. ? 0. : error)
                << " J (relative to the heat exchanged " << (relative == 0. ? 0. : relative)
                << ")\n";
          }
      }
    else
      {
        // Kinetic energy of the FE dofs and the components not slaved to the FE field;
        // that of prescribed dofs and components separately (EnergyBalance counts it as work).
        const auto          kinetic          = state.kinetic_energy();
        const CoupledEnergy energy           = state.strain_energy();
        const double        strain           = energy.fe + energy.particles;
        const bool          heated           = state.has_temperature();
        const double        temperature_work = heated ? state.temperature_work() : 0.;
        balance.record(data.step,
                       kinetic.total,
                       strain,
                       work,
                       kinetic.prescribed,
                       dissipated,
                       state.conversion_energy,
                       temperature_work);
        balance.check_stable(data.time, state.stable_dt);
        statistics.add_value("kinetic_energy", kinetic.total);
        statistics.add_value("strain_energy", strain);
        statistics.add_value("external_work", balance.work());
        if (heated)
          statistics.add_value("temperature_work", temperature_work);
        if (breaks)
          statistics.add_value("dissipated_energy", dissipated);
        if (state.has_adaptive_region())
          statistics.add_value("conversion_energy", state.conversion_energy);
        statistics.add_value("energy_error", balance.error());
        if (state.is_root() && data.final_row)
          {
            log << "Kinetic energy: " << kinetic.total << " J\n"
                << "Strain energy: " << strain << " J\n"
                << "External work: " << balance.work() << " J\n";
            if (heated)
              log << "Work of the temperature change: " << temperature_work << " J\n";
            if (breaks)
              log << "Dissipated energy: " << dissipated << " J\n";
            if (state.has_adaptive_region())
              log << "Energy change of the conversions: " << state.conversion_energy << " J\n";
            log << "Energy error: " << balance.error() << " J\n";
          }
      }
    log.flags(flags);
  }

  template <int dim>
  std::string
  EnergyStatistics<dim>::save_state(const CoupledState<dim> &) const
  {
    const std::vector<char> packed = Utilities::pack(balance, false);
    return std::string(packed.begin(), packed.end());
  }

  template <int dim>
  void
  EnergyStatistics<dim>::load_state(const CoupledState<dim> &, const std::string &packed)
  {
    balance =
      Utilities::unpack<EnergyBalance>(std::vector<char>(packed.begin(), packed.end()), false);
  }

  template class EnergyStatistics<2>;
  template class EnergyStatistics<3>;
} // namespace perideal

PERIDEAL_REGISTER_POSTPROCESSOR(
  perideal::EnergyStatistics,
  "energy statistics",
  "kinetic and strain energies, the work of the loads, the dissipated energy, the energy error and its instability stop (always run).")
