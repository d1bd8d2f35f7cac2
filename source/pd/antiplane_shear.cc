// ---------------------------------------------------------------------
// PeriDeal: what the antiplane shear models (one scalar w per particle) share.
// ---------------------------------------------------------------------
#include <deal.II/base/numbers.h>

#include <perideal/base/parameter_utilities.h>
#include <perideal/pd/antiplane_shear.h>

#include <cmath>

namespace perideal
{
  namespace AntiplaneShear
  {
    void
    declare_shear_modulus(dealii::ParameterHandler &prm)
    {
      prm.declare_entry("Shear modulus",
                        "0",
                        dealii::Patterns::Double(0.),
                        "Shear modulus mu [Pa] of antiplane shear (the field w is the "
                        "out-of-plane displacement, its stresses tau_xz, tau_yz = mu grad w).");
    }

    double
    parse_shear_modulus(dealii::ParameterHandler &prm, const std::string &model_name)
    {
      const double mu = prm.get_double("Shear modulus");
      ParameterUtilities::require_positive(mu, "Material/" + model_name + "/Shear modulus");
      return mu;
    }

    double
    micromodulus(const unsigned int dim,
                 const double       shear_modulus,
                 const double       horizon,
                 const double       thickness)
    {
      const double pi = dealii::numbers::PI;
      return (dim == 2) ? 6. * shear_modulus / (pi * thickness * std::pow(horizon, 3)) :
                          6. * shear_modulus / (pi * std::pow(horizon, 4));
    }

    double
    critical_slope(const unsigned int dim,
                   const double       fracture_energy,
                   const double       shear_modulus,
                   const double       horizon)
    {
      const double G = fracture_energy, mu = shear_modulus, pi = dealii::numbers::PI;
      return (dim == 2) ? std::sqrt(2. * pi * G / (3. * mu * horizon)) :
                          std::sqrt(5. * G / (3. * mu * horizon));
    }
  } // namespace AntiplaneShear
} // namespace perideal
