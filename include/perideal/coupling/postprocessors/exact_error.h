// ---------------------------------------------------------------------
// PeriDeal: the error of a quasi-static run against an exact displacement field.
// ---------------------------------------------------------------------
#ifndef perideal_coupling_postprocessors_exact_error_h
#define perideal_coupling_postprocessors_exact_error_h

#include <deal.II/base/function.h>

#include <perideal/coupling/postprocessors/postprocessor.h>

#include <memory>

namespace perideal
{
  /**
   * @brief Verification of quasi-static runs against <Coupling/Exact displacement>: after the
   * last load step, the largest error at the FE nodes and at the particles relative to the
   * largest exact value (with a verdict against <Coupling/Exact displacement tolerance> if it
   * is not 0), and the force residual of the exact field in the coupling method's model (FE
   * nodes and particles set to it): for a state the uncoupled models reproduce, the ghost force
   * of the coupling.
   */
  template <int dim>
  class ExactError : public Postprocessor<dim>
  {
  public:
    /// Compare with @p inputs.exact_displacement (one component per field component; nothing
    /// without it); no verdict if @p inputs.exact_tolerance is 0.
    void
    set_inputs(const PostprocessorInputs<dim> &inputs) override;

    void
    execute(const CoupledState<dim> &state,
            const StepData          &data,
            StatisticsFile          &statistics) override;

  private:
    std::shared_ptr<const dealii::Function<dim>> exact;
    double                                       tolerance = 0.;
    /// The physics' method, which evaluates the forces of the exact field
    /// (PostprocessorInputs::method).
    CouplingMethod<dim> *method = nullptr;
  };
} // namespace perideal

#endif
