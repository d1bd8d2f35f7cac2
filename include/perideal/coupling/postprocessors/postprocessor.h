// ---------------------------------------------------------------------
// PeriDeal: what a postprocessor of a run provides, and the ordered set a run executes.
// ---------------------------------------------------------------------
#ifndef perideal_coupling_postprocessors_postprocessor_h
#define perideal_coupling_postprocessors_postprocessor_h

#include <deal.II/base/function.h>
#include <deal.II/base/parameter_handler.h>

#include <perideal/base/plugin_registry.h>
#include <perideal/base/statistics_file.h>
#include <perideal/coupling/coupled_state.h>
#include <perideal/coupling/solvers/quasi_static_control.h>

#include <memory>
#include <string>
#include <tuple>
#include <vector>

namespace perideal
{
  /**
   * @brief What a solver tells the postprocessors about the step it has just finished.
   */
  struct StepData
  {
    /// Time step or load step (0: the initial state).
    unsigned int step = 0;
    /// Time [s] (explicit) or load factor (quasi-static).
    double time = 0.;
    /// Whether the run is quasi-static (load steps) rather than explicit dynamics.
    bool quasi_static = false;
    /// Whether to write a row of statistics.csv, and whether it is the last row.
    ///@{
    bool write_statistics = false, final_row = false;
    ///@}
    /// Whether to write the particle and FE fields, and the index of that output.
    ///@{
    bool         write_fields = false;
    unsigned int output_index = 0;
    ///@}
    /// Quasi-static: the step stopped without convergence; the fields written are of its last
    /// iterate, to files of their own (FieldOutput); no statistics row, no summary.
    bool not_converged = false;
    /// Quasi-static: iterations of the step's solves, and the particles' strain energy in the
    /// coupling method's model of equilibrium (CouplingMethod::equilibrium_forces()) [J].
    ///@{
    unsigned int iterations = 0;
    double       pd_energy  = 0.;
    ///@}
  };

  /**
   * @brief What a postprocessor may read of the problem's entries besides the state, given to
   * it before initialize() (Postprocessor::set_inputs()).
   */
  template <int dim>
  struct PostprocessorInputs
  {
    /// <Solver/Control>: its load point (FractureStatistics).
    QuasiStaticControl control;
    /// <Coupling/Exact displacement> (nullptr if not given) and <Coupling/Exact displacement
    /// tolerance> (ExactError).
    ///@{
    std::shared_ptr<const dealii::Function<dim>> exact_displacement;
    double                                       exact_tolerance = 0.;
    ///@}
    /**
     * @brief The physics' coupling method, for a postprocessor that evaluates the forces of a
     * field of its own (ExactError: the residual of the exact field). A force evaluation
     * changes the method's work vectors, which the const state does not allow: this is the
     * one way to it, and it is never the state's unknowns.
     */
    CouplingMethod<dim> *method = nullptr;
  };

  /**
   * @brief A postprocessor of a run (in the manner of ASPECT's Postprocess::Interface): it
   * reads the state after a step and adds its columns to the one statistics table, its lines to
   * the final summary, or its files to the output directory. A plugin
   * (PERIDEAL_REGISTER_POSTPROCESSOR): <Postprocess/List> names the ones a run executes.
   */
  template <int dim>
  class Postprocessor
  {
  public:
    virtual ~Postprocessor() = default;

    /**
     * @brief Declare the postprocessor's own entries: none by default (the registry's
     * interface; the shipped ones read the entries of PostprocessorInputs).
     */
    static void
    declare_parameters(dealii::ParameterHandler &)
    {}

    /**
     * @brief Take what the postprocessor reads of the problem's entries (before initialize());
     * nothing by default.
     */
    virtual void
    set_inputs(const PostprocessorInputs<dim> &)
    {}

    /**
     * @brief Once at the end of the set-up, before anything is written: checks (stopping with
     * a message that names the entry) and what does not change during the run; nothing on
     * disk. Collective.
     */
    virtual void
    initialize(const CoupledState<dim> &)
    {}

    /**
     * @brief Act on the step @p data: add columns to the current row of @p statistics if
     * data.write_statistics, print summary lines (rank 0) if data.final_row, write files if
     * data.write_fields. Collective.
     */
    virtual void
    execute(const CoupledState<dim> &state, const StepData &data, StatisticsFile &statistics) = 0;

    /**
     * @brief What the postprocessor carried over the steps so far (totals, the records of the
     * files written), packed for a checkpoint; empty if nothing. Collective; rank 0's is kept.
     */
    virtual std::string
    save_state(const CoupledState<dim> &) const
    {
      return {};
    }

    /**
     * @brief Continue from save_state()'s @p packed (the same on every rank), before the first
     * execute() of a restarted run. Collective.
     */
    virtual void
    load_state(const CoupledState<dim> &, const std::string &)
    {}
  };

  /**
   * @brief The postprocessors of a run, executed in the order of <Postprocess/List> (by default
   * energies, displacements, reactions, fracture statistics, section integrals, the error
   * against an exact field, probes, field output). They share the statistics table
   * <Output/Directory>/statistics.csv, whose rows start with the step and the time (or the load
   * factor and the iterations), and the final summary, which starts with the time or the load
   * factor.
   */
  template <int dim>
  class Postprocessors
  {
  public:
    /// The name of the postprocessor every run executes, first if <Postprocess/List> omits it:
    /// its energy balance stops an unstable explicit run.
    static constexpr const char *mandatory = "energy statistics";

    /**
     * @brief Declare <Postprocess/List> (in the current section: the problem's top level).
     */
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /**
     * @brief The names of <Postprocess/List>, in order, with the mandatory one first if it is
     * not listed; a name listed twice stops, naming the entry. Unknown names are refused by the
     * entry's pattern, which lists the registered ones.
     */
    static std::vector<std::string>
    parse_parameters(dealii::ParameterHandler &prm);

    /**
     * @brief The registered postprocessors @p names, in this order, each given @p inputs.
     */
    Postprocessors(const std::vector<std::string> &names, const PostprocessorInputs<dim> &inputs);

    /**
     * @brief Initialize every postprocessor (their checks, nothing on disk). Collective.
     */
    void
    initialize(const CoupledState<dim> &state);

    /**
     * @brief Execute every postprocessor for the step @p data; the first call creates the
     * output directory and the statistics table. Collective.
     */
    void
    execute(const CoupledState<dim> &state, const StepData &data);

    /**
     * @brief Execute @p others' postprocessors on @p other_state too, after each execute():
     * the physics @p name of <Physics/List>, its statistics columns prefixed "<name>." in the
     * same rows, its summary after a line "Physics <name>:", its fields in files of its own
     * (ProblemSettings::field_suffix). The objects must outlive this one.
     */
    void
    add_physics(const std::string       &name,
                const CoupledState<dim> &other_state,
                Postprocessors<dim>     &others);

    /**
     * @brief The statistics table written so far and every postprocessor's save_state(), those
     * of the physics of add_physics() after the own ones, packed for a checkpoint (complete on
     * rank 0). Collective.
     */
    std::string
    save_state(const CoupledState<dim> &state) const;

    /**
     * @brief Continue from save_state()'s @p packed (the same on every rank): rewrite the
     * statistics table with the rows it kept (rows written after it are dropped) and restore
     * every postprocessor, those of add_physics() too. Instead of the first execute() of a
     * restarted run. Collective.
     */
    void
    load_state(const CoupledState<dim> &state, const std::string &packed);

  private:
    /// Create the output directory and the statistics table (not its file).
    void
    create_statistics(const CoupledState<dim> &state);

    std::vector<std::unique_ptr<Postprocessor<dim>>> postprocessors;
    std::unique_ptr<StatisticsFile>                  statistics;
    /// The physics of add_physics(): name, state, postprocessors.
    std::vector<std::tuple<std::string, const CoupledState<dim> *, Postprocessors<dim> *>> physics;
  };
} // namespace perideal

/**
 * Register class @p classname (a Postprocessor<dim> for dim = 2 and 3) as a value of
 * <Postprocess/List> named @p name.
 */
#define PERIDEAL_REGISTER_POSTPROCESSOR(classname, name, description)                     \
  PERIDEAL_REGISTER_PLUGIN(::perideal::Postprocessor<2>, classname<2>, name, description) \
  PERIDEAL_REGISTER_PLUGIN(::perideal::Postprocessor<3>, classname<3>, name, description)

#endif
