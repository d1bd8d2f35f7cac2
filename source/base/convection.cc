// ---------------------------------------------------------------------
// PeriDeal: a convection condition on a temperature, for particles and finite elements alike.
// ---------------------------------------------------------------------
#include <deal.II/base/function_parser.h>

#include <perideal/base/convection.h>
#include <perideal/base/parameter_utilities.h>

namespace perideal
{
  using namespace dealii;

  template <int dim>
  void
  Convection<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Heat transfer coefficient",
                      "0",
                      Patterns::Double(0.),
                      "Type 'convection' (a temperature): the heat transfer coefficient h "
                      "[W/m^2/K] of the heat flux h (T_inf - T) into the body; > 0.");
    prm.declare_entry("Ambient temperature",
                      "",
                      Patterns::Anything(),
                      "Type 'convection' (a temperature): the ambient temperature T_inf [K], an "
                      "expression of x, y, (z) and t; required.");
  }

  template <int dim>
  Convection<dim>
  Convection<dim>::parse(ParameterHandler &prm, const std::string &prefix)
  {
    Convection<dim>   result;
    const std::string ambient = prm.get("Ambient temperature");
    AssertThrow(!ambient.empty(),
                ExcMessage("The parameter <" + prefix + "Type> is 'convection', but <" + prefix +
                           "Ambient temperature> is empty: a convection h (T_inf - T) needs both "
                           "<" +
                           prefix + "Heat transfer coefficient> (h > 0 [W/(m^2 K)]) and <" +
                           prefix + "Ambient temperature> (an expression of x, y, (z), t [K])."));
    result.coefficient = prm.get_double("Heat transfer coefficient");
    ParameterUtilities::require_positive(result.coefficient, prefix + "Heat transfer coefficient");
    result.ambient =
      ParameterUtilities::make_function<dim>(ambient, 1, prefix + "Ambient temperature");
    return result;
  }

  template struct Convection<2>;
  template struct Convection<3>;
} // namespace perideal
