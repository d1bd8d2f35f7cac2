// ---------------------------------------------------------------------
// PeriDeal: a convection condition on a temperature, for particles and finite elements alike.
// ---------------------------------------------------------------------
#ifndef perideal_base_convection_h
#define perideal_base_convection_h

#include <deal.II/base/function.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <memory>
#include <string>

namespace perideal
{
  /**
   * @brief Convection (Newton's law of cooling) on a temperature T: the heat flux into the body
   * q = h (T_inf(x, t) - T) [W/m^2], with the heat transfer coefficient h [W/(m^2 K)] and the
   * ambient temperature T_inf [K] of a boundary condition whose <Type> is 'convection'.
   *
   * Its entries, <Heat transfer coefficient> and <Ambient temperature>, are declared in the
   * subsection of every boundary condition (particles and finite elements alike,
   * declare_parameters()); parse() reads them for a convection condition and refuses a missing
   * ambient temperature, naming both entries.
   */
  template <int dim>
  struct Convection
  {
    /// The heat transfer coefficient h [W/(m^2 K)].
    double coefficient = 0.;
    /// The ambient temperature T_inf(x, t) [K] (one component).
    std::shared_ptr<dealii::Function<dim>> ambient;

    /// @brief Declare <Heat transfer coefficient> and <Ambient temperature> in the current
    /// subsection (a boundary condition's).
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /**
     * @brief Read the entries of the current subsection of a convection condition whose entries
     * are named <@p prefix ...>: h must be positive and the ambient temperature given (each
     * refusal names the entries and the accepted values).
     */
    static Convection
    parse(dealii::ParameterHandler &prm, const std::string &prefix);

    /// @brief The heat flux into the body h (T_inf(x) - T) at the ambient's current time.
    double
    flux(const dealii::Point<dim> &x, const double temperature) const
    {
      return coefficient * (ambient->value(x) - temperature);
    }
  };
} // namespace perideal

#endif
