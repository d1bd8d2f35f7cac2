// ---------------------------------------------------------------------
// PeriDeal: checkpoints of a run and the restart from them.
// ---------------------------------------------------------------------
#ifndef perideal_coupling_checkpoint_h
#define perideal_coupling_checkpoint_h

#include <perideal/base/checkpoint_file.h>
#include <perideal/base/problem_settings.h>
#include <perideal/coupling/coupled_state.h>
#include <perideal/coupling/postprocessors/postprocessor.h>

#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace perideal
{
  /**
   * @brief Where a run is, besides its state: what a solver needs to continue it.
   */
  struct RunPosition
  {
    /// The last step done (time step or load step; 0: the initial state).
    unsigned int step = 0;
    /// Its time [s] or load factor.
    double time = 0.;
    /// The index of the next field output.
    unsigned int next_output = 1;
  };

  /**
   * @brief Checkpoints of a run every <Output/Checkpoint interval> steps and at each multiple of
   * <Output/Checkpoint time interval> of simulated time (the load factor of a quasi-static run),
   * and the restart from the newest one (perideal-solid --restart).
   *
   * The checkpoint `<Output/Directory>/checkpoint` holds the complete state of the run, of every
   * physics of the problem: each state's vectors and partial sums (CoupledState::save(): its
   * particle records, bond histories and FE dof values through its regions), the broken bonds
   * once (the physics share one bond list), the position (step, time, next output index) and
   * the postprocessors' state of every physics (the statistics table so far, the energy
   * balance, the records of the XDMF/PVD files). The state is restored exactly, so a restarted
   * run gives the numbers of the uninterrupted run bit for bit on the same number of ranks; on
   * another number of ranks the partial sums are added on rank 0, so the run continues to
   * round-off.
   *
   * This class decides when a checkpoint is written and what goes into it; the regions write
   * and read their own sections, and the file format is CheckpointWriter's and
   * CheckpointReader's (base/checkpoint_file.h).
   *
   * The file is written as `checkpoint.tmp` and renamed by rank 0 after every rank has closed
   * it, so a run killed while writing leaves the previous checkpoint complete. A restart checks,
   * before it writes anything, that the file exists, is complete (its size and end mark) and
   * belongs to this problem (dimension, physics, models, unknowns, numbers of particles, bonds,
   * FE cells and dofs, the solver type and its number and size of steps); otherwise it stops
   * naming the file and what differs. The settings that only decide how well a step is solved
   * (<Solver/Tolerance>, <Solver/Maximum iterations>, <Solver/Linear solver>, <Solver/Density
   * safety factor>) are not part of it: a quasi-static run that stopped without convergence
   * continues from the checkpoint of its last converged load step (keep(), write_kept()) with
   * other values of them.
   */
  template <int dim>
  class Checkpoint
  {
  public:
    /// No step: the run does not stop early.
    static constexpr unsigned int no_step = std::numeric_limits<unsigned int>::max();

    /**
     * @brief Checkpoints of a run with @p settings whose models are described by
     * @p problem_lines ("key = value" lines of the fingerprint); continue from the checkpoint if
     * @p restart; end the run after the checkpoint of step @p stop_step (tests of the restart).
     */
    Checkpoint(const ProblemSettings<dim> &settings,
               const std::string          &problem_lines,
               const bool                  restart,
               const unsigned int          stop_step);

    /// The checkpoint file.
    const std::string &
    filename() const;

    /**
     * @brief A physics of <Physics/List> besides the first one (whose state the solver passes):
     * its @p name, its @p problem_lines for the fingerprint and its @p state, whose sections
     * are named "<name>/..." (its postprocessors are the first physics' ones through
     * Postprocessors::add_physics()). Call before the run.
     */
    void
    add_physics(const std::string &name,
                const std::string &problem_lines,
                CoupledState<dim> &state);

    /**
     * @brief A part of the run besides the physics' states whose records the checkpoint holds
     * too (the two-way coupling's measure, ThermoelasticHeating): its fingerprint line @p line
     * ("key = value"), @p save writing its sections, @p load reading them at a restart. Call
     * before the run.
     */
    void
    add_part(const std::string                             &line,
             const std::function<void(CheckpointWriter &)> &save,
             const std::function<void(CheckpointReader &)> &load);

    /**
     * @brief The solver's run: @p description (e.g. its number and size of steps) is part of the
     * fingerprint; @p n_steps is its last step (no checkpoint after it). Call before load()
     * and after_step().
     */
    void
    set_run(const std::string &description, const unsigned int n_steps);

    /// Whether the run continues from the checkpoint.
    bool
    restarting() const;

    /**
     * @brief Restore @p state and @p postprocessors from the checkpoint (after the checks of
     * the class description) and return the position to continue from. Collective.
     */
    RunPosition
    load(CoupledState<dim> &state, Postprocessors<dim> &postprocessors);

    /**
     * @brief After the step of @p position: write a checkpoint if one is due (every
     * <Output/Checkpoint interval> steps, or the first step at or after each multiple of
     * <Output/Checkpoint time interval>, before the last step; and at the stop step); return
     * whether the run ends here (the stop step). Call after every step. Collective.
     */
    bool
    after_step(CoupledState<dim>         &state,
               const Postprocessors<dim> &postprocessors,
               const RunPosition         &position);

    /**
     * @brief Keep in memory what a checkpoint of @p position would hold (each state keeps its
     * own, CoupledState::keep(): @p state's and every physics' of add_physics(); here the
     * broken bonds and the postprocessors' state): a quasi-static run keeps each converged load
     * step before it (and the other physics) advance to the next one. Collective.
     */
    void
    keep(CoupledState<dim>         &state,
         const Postprocessors<dim> &postprocessors,
         const RunPosition         &position);

    /**
     * @brief Put the state of the last keep() back into @p state (which loses what it held) and
     * write its checkpoint; return its position. For a run that stops without convergence: the
     * checkpoint is that of the last converged step. Collective.
     */
    RunPosition
    write_kept(CoupledState<dim> &state);

    /**
     * @brief Put the state of the last keep() back into @p state (which loses what it held),
     * without writing; return its position. For a load step that is cut (LoadStepping).
     */
    RunPosition
    restore_kept(CoupledState<dim> &state) const;

  private:
    /// Write the checkpoint of @p position (to the temporary name, then renamed), with the
    /// postprocessors' state @p postprocessor_state (Postprocessors::save_state()).
    void
    write(const CoupledState<dim> &state,
          const std::string       &postprocessor_state,
          const RunPosition       &position) const;

    /// Whether a checkpoint is due after the step of @p position by the intervals.
    bool
    due(const RunPosition &position) const;

    /// The fingerprint of the problem of @p state and the other physics: "key = value" lines.
    std::string
    fingerprint(const CoupledState<dim> &state) const;

    /// Every physics' state: @p state (the first one's) and those of add_physics().
    std::vector<CoupledState<dim> *>
    all_states(CoupledState<dim> &state) const;

    /// What keep() keeps besides the states (CoupledState::keep()): the bond states, the
    /// postprocessors.
    struct Kept
    {
      std::vector<std::uint8_t> intact;
      std::string               postprocessors;
      RunPosition               position;
      bool                      valid = false;
    };

    /// A part of add_part(): fingerprint line, writer, reader.
    struct Part
    {
      std::string                             line;
      std::function<void(CheckpointWriter &)> save;
      std::function<void(CheckpointReader &)> load;
    };

    /// The physics of add_physics(): name, fingerprint lines, state.
    struct OtherPhysics
    {
      std::string        name;
      std::string        problem_lines;
      CoupledState<dim> *state;
    };

    std::string  file;
    std::string  problem_lines;
    unsigned int interval;
    double       time_interval;
    bool         restart;
    unsigned int stop_step;
    std::string  run_description;
    unsigned int n_steps = 0;
    /// The time of the step before (the restart's or 0 at first): the time interval's reference.
    double                    previous_time = 0.;
    Kept                      kept;
    std::vector<OtherPhysics> others;
    std::vector<Part>         parts;
  };
} // namespace perideal

#endif
