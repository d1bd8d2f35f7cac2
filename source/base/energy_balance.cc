// ---------------------------------------------------------------------
// PeriDeal: the energy balance of a dynamic run (work, dissipation, error, instability stop).
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>

#include <perideal/base/energy_balance.h>
#include <perideal/base/parameter_utilities.h>

#include <cmath>
#include <string>

namespace perideal
{
  void
  EnergyBalance::record(const unsigned int row_step,
                        const double       row_kinetic,
                        const double       row_strain,
                        const double       work_of_loads,
                        const double       prescribed_kinetic,
                        const double       row_dissipated,
                        const double       row_conversion,
                        const double       row_temperature_work)
  {
    conversion       = row_conversion;
    temperature_work = row_temperature_work;
    step             = row_step;
    kinetic          = row_kinetic;
    strain           = row_strain;
    dissipated       = row_dissipated;
    if (step == 0)
      {
        initial_energy     = kinetic + strain;
        initial_prescribed = prescribed_kinetic;
      }
    total_work = work_of_loads + prescribed_kinetic - initial_prescribed;
  }

  double
  EnergyBalance::work() const
  {
    return total_work;
  }

  double
  EnergyBalance::error() const
  {
    return kinetic + strain + dissipated - total_work - temperature_work - initial_energy -
           conversion;
  }

  void
  EnergyBalance::check_stable(const double time, const double stable_dt) const
  {
    const std::string where = "The run became unstable at step " + std::to_string(step) +
                              " (t = " + ParameterUtilities::format_number(time) + " s): ";
    const std::string advice = " Reduce <Time stepping/Time step> or <Time stepping/Safety "
                               "factor> (stable limit " +
                               ParameterUtilities::format_number(stable_dt) + " s).";
    AssertThrow(std::isfinite(kinetic) && std::isfinite(strain),
                dealii::ExcMessage(where + "non-finite displacement or energy." + advice));
    const double scale = std::abs(total_work) + std::abs(temperature_work) + initial_energy;
    AssertThrow(step < 10 || scale == 0. || kinetic + strain < 1e3 * scale,
                dealii::ExcMessage(where + "the energy grew to " +
                                   ParameterUtilities::format_number(kinetic + strain) +
                                   " J against " + ParameterUtilities::format_number(scale) +
                                   " J put in." + advice));
  }
} // namespace perideal
