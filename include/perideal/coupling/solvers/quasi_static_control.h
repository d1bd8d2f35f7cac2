// ---------------------------------------------------------------------
// PeriDeal: how a quasi-static run advances its load (<Solver/Control>).
// ---------------------------------------------------------------------
#ifndef perideal_coupling_solvers_quasi_static_control_h
#define perideal_coupling_solvers_quasi_static_control_h

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace perideal
{
  /// <Solver/Control/Method>: how a quasi-static run advances its load.
  enum class LoadControl
  {
    /// <Solver/Load steps> equal increments of the load factor (LoadStepping).
    load_steps,
    /// Event by event: the load scaled so that the most critical bond just breaks
    /// (SequentiallyLinear); passes snap-back, the load factor may fall.
    sequentially_linear
  };

  /// <Solver/Control/Load history>: how the conditions depend on the load factor.
  enum class LoadHistory
  {
    /// The conditions at <Time stepping/End time>, scaled by the load factor.
    proportional,
    /// The conditions evaluated at t = load factor x End time, unscaled (any load path).
    time
  };

  /**
   * @brief The entries of <Solver/Control>: the control of a quasi-static run, the load point
   * whose load and displacement the statistics report (and whose load decides when the body has
   * separated), and the thresholds of the event-by-event control. Declared and read in one
   * place; checked when the file is read (ranges), the names against the problem by
   * FractureMeasures::initialize().
   */
  struct QuasiStaticControl
  {
    /// Declare the subsection <Solver/Control>.
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /// Read and check the entries of <Solver/Control> (the ranges, naming the entry).
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /// <Method> and <Load history>.
    ///@{
    LoadControl method  = LoadControl::load_steps;
    LoadHistory history = LoadHistory::proportional;
    ///@}
    /// The displacement condition (particle or FE) whose reaction is the load; empty: none.
    std::string load_point;
    /// The component (layout name) of the load and the load-point displacement.
    std::string load_component;
    /// Bonds whose critical load factor is within (1 + tolerance) of the smallest break in the
    /// same event.
    double event_tolerance = 1e-6;
    /// The body has separated once the load falls below this fraction of its peak.
    double separation_fraction = 0.05;
    /// Largest number of events of one run.
    unsigned int max_events = 100000;
    /// Load steps: a step that breaks more bonds than this is cut (0: never).
    unsigned int cut_threshold = 0;
    /// Load steps: largest number of successive cuts of one step.
    unsigned int max_cuts = 10;
  };
} // namespace perideal

#endif
