// ---------------------------------------------------------------------
// PeriDeal: the temperature the mechanics measures its thermal strain from.
// ---------------------------------------------------------------------
#ifndef perideal_coupling_temperature_source_h
#define perideal_coupling_temperature_source_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/hp/fe_values.h>

#include <perideal/base/linear_algebra.h>
#include <perideal/coupling/physics_exchange.h>
#include <perideal/fem/fe_region.h>
#include <perideal/pd/particle_region.h>

#include <memory>
#include <string>
#include <vector>

namespace perideal
{
  /**
   * @brief The temperature T of the thermal strain alpha (T - T_ref) of the first physics
   * (<Temperature>, doc/architecture/16_multiphysics.md "Thermal strain"): none, a prescribed
   * function T(x, t), or the temperature the heat physics publishes (PhysicsExchange,
   * "temperature"), at the particles and at the quadrature points of the FE cells.
   *
   * It holds the temperature change Delta T = T - T_ref of the local particles (owned and
   * ghost), which the particles' model reads (MaterialModel::set_temperature_change()), and
   * gives the FE region the Delta T of a cell's quadrature points
   * (FERegion::set_temperature_change()). update() brings both to a time.
   */
  template <int dim>
  class TemperatureSource
  {
  public:
    /// Where T comes from (<Temperature/Source>).
    enum class Kind
    {
      none,
      function,
      heat
    };

    /**
     * @brief Declare <Temperature> (top level).
     */
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /**
     * @brief Read <Temperature>: the source, its function and the reference temperature
     * (refused when missing for a source other than none).
     */
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /// The source of T.
    Kind
    kind() const;

    /// Whether there is a source (kind() is not none).
    bool
    active() const;

    /// The reference temperature T_ref of no thermal strain [K].
    double
    reference_temperature() const;

    /// Whether <Temperature/Coupling> = two way (the thermoelastic heating, ThermoelasticHeating).
    bool
    two_way() const;

    /// <Temperature/Absolute reference temperature> T_0 [K] (two way only).
    double
    absolute_reference_temperature() const;

    /**
     * @brief Give the first physics' particles (its model reads the particles' Delta T) and
     * FE region (it reads the cells' Delta T from the source) the temperature, taken from
     * @p exchange for the heat source (published once the other physics are set up: read at
     * update()). Again after the particles change (a conversion of the adaptive region).
     */
    void
    connect(ParticleRegion<dim> &pd, FERegion<dim> &fe, const PhysicsExchange<dim> &exchange);

    /**
     * @brief Delta T of the particles at time @p time (ghosts included) and the time the FE
     * region's Delta T is evaluated at.
     */
    void
    update(const double time);

    /// Delta T = T - T_ref of the local particles (one value per particle).
    const ParticleVector &
    particle_change() const;

    /**
     * @brief Add sum_q @p values[q] psi_k(x_q) to @p heat_vector (the heat's FE numbering;
     * compress(add) after the last cell): the heat's shape functions psi_k at the quadrature
     * points of @p fe_values, a cell of the mechanics' FE region (the heat source: the transpose
     * of the evaluation of cell_change()). Source = heat only.
     */
    void
    add_at_heat_points(const dealii::FEValues<dim> &fe_values,
                       const std::vector<double>   &values,
                       FEVector                    &heat_vector) const;

    /// One line for the log.
    std::string
    summary() const;

  private:
    /// Delta T at the quadrature points of the cell of @p fe_values at @p time.
    void
    cell_change(const dealii::FEValues<dim> &fe_values,
                const double                 time,
                std::vector<double>         &delta_T) const;

    /// The heat's values at the quadrature points of @p fe_values (a cell of the mechanics):
    /// those of the heat's cell of the same CellId (its own triangulation, built and
    /// partitioned alike).
    const dealii::FEValues<dim> &
    heat_cell_values(const dealii::FEValues<dim> &fe_values) const;

    Kind                                         source = Kind::none;
    std::string                                  expression;
    std::unique_ptr<dealii::FunctionParser<dim>> function;
    double                                       reference          = 0.;
    bool                                         two_way_coupling   = false;
    double                                       absolute_reference = 0.;

    const ParticleSystem<dim>  *particles = nullptr;
    const PhysicsExchange<dim> *exchange  = nullptr;
    ParticleVector              delta_T;

    /// The heat's FE temperature with ghost values, and the evaluation of its cells at the
    /// mechanics' points (built again when the points change) with those points.
    ///@{
    FEVector                                           heat_temperature;
    mutable std::unique_ptr<dealii::hp::FEValues<dim>> heat_values;
    mutable std::vector<dealii::Point<dim>>            heat_points;
    ///@}
  };
} // namespace perideal

#endif
