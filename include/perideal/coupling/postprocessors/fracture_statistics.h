// ---------------------------------------------------------------------
// PeriDeal: the load, load-point displacement and crack length of quasi-static runs.
// ---------------------------------------------------------------------
#ifndef perideal_coupling_postprocessors_fracture_statistics_h
#define perideal_coupling_postprocessors_fracture_statistics_h

#include <perideal/coupling/fracture_measures.h>
#include <perideal/coupling/postprocessors/postprocessor.h>

namespace perideal
{
  /**
   * @brief Quasi-static runs with a <Solver/Control/Load point>: the columns load,
   * load_point_displacement and crack_length (FractureMeasures; the load factor is the time
   * column, the broken bonds DisplacementStatistics' column) and, in the summary, the load and
   * the load-point displacement of the last row. Nothing without a load point.
   */
  template <int dim>
  class FractureStatistics : public Postprocessor<dim>
  {
  public:
    /// The statistics of the load point of @p inputs.control.
    void
    set_inputs(const PostprocessorInputs<dim> &inputs) override;

    void
    initialize(const CoupledState<dim> &state) override;

    void
    execute(const CoupledState<dim> &state,
            const StepData          &data,
            StatisticsFile          &statistics) override;

  private:
    QuasiStaticControl    control;
    FractureMeasures<dim> measures;
  };
} // namespace perideal

#endif
