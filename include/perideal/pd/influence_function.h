// ---------------------------------------------------------------------
// PeriDeal: influence functions omega(|xi|) of state-based models.
// ---------------------------------------------------------------------
#ifndef perideal_pd_influence_function_h
#define perideal_pd_influence_function_h

#include <deal.II/base/parameter_handler.h>

#include <perideal/base/plugin_registry.h>

namespace perideal
{
  /**
   * @brief Interface of an influence function omega(r) of the bond length r in [0, delta].
   *
   * Evaluated once per bond at set-up and stored, so the force loop makes no call to it.
   */
  class InfluenceFunction
  {
  public:
    virtual ~InfluenceFunction() = default;

    /**
     * @brief omega(r) for a bond of reference length @p r and horizon @p delta.
     */
    virtual double
    value(const double r, const double delta) const = 0;

    /**
     * @brief Nothing to declare by default.
     */
    static void
    declare_parameters(dealii::ParameterHandler &)
    {}
  };

  /**
   * @brief omega = 1 (Silling et al. 2007, J. Elasticity 88, section 15).
   */
  class ConstantInfluence : public InfluenceFunction
  {
  public:
    double
    value(const double r, const double delta) const override;
    using InfluenceFunction::declare_parameters;
  };

  /**
   * @brief omega = delta / r (Madenci & Oterkus 2014; seed 002, eq. 4.113).
   */
  class InverseDistanceInfluence : public InfluenceFunction
  {
  public:
    double
    value(const double r, const double delta) const override;
    using InfluenceFunction::declare_parameters;
  };

  /**
   * @brief omega = exp(-r^2 / delta^2) (Seleson & Parks 2011, Int. J. Multiscale Comput. Eng.).
   */
  class GaussianInfluence : public InfluenceFunction
  {
  public:
    double
    value(const double r, const double delta) const override;
    using InfluenceFunction::declare_parameters;
  };
} // namespace perideal

#endif
