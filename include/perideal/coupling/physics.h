// ---------------------------------------------------------------------
// PeriDeal: one physics of a problem (its field, particle part, FE part, coupling and state).
// ---------------------------------------------------------------------
#ifndef perideal_coupling_physics_h
#define perideal_coupling_physics_h

#include <deal.II/base/parameter_handler.h>

#include <perideal/base/field_layout.h>
#include <perideal/base/problem_settings.h>
#include <perideal/coupling/coupled_state.h>
#include <perideal/coupling/coupling_method.h>
#include <perideal/coupling/postprocessors/postprocessor.h>
#include <perideal/coupling/solvers/solver.h>
#include <perideal/fem/fe_region.h>
#include <perideal/pd/particle_region.h>

#include <map>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace perideal
{
  /**
   * @brief One physics of a problem (doc/architecture/16_multiphysics.md): a field (its
   * FieldLayout) with its particle part (ParticleRegion: model, density, conditions), its FE
   * part (FERegion: its own dofs, FE physics and conditions), its coupling method through the
   * problem's overlap (the same beta), its state (CoupledState), its solver and its
   * postprocessors.
   *
   * The first physics of a problem is the one of the top-level sections and owns the shared
   * geometry: the particles with their one bond list, and the mesh entries. Each physics of
   * <Physics/List> reads a subsection of its own (section(), e.g. <Heat>) and shares the first
   * one's particles (a bond broken by the mechanics conducts no heat) and mesh (the same cells,
   * partitioned alike). CoupledProblem wires the physics; no physics reads another's parts but
   * through PhysicsExchange.
   */
  template <int dim>
  class Physics
  {
  public:
    /// The boundary-condition names of a physics' particle and FE parts (a first pass).
    struct ConditionNames
    {
      /// <Boundary conditions/Names> and <Finite elements/Boundary conditions/Names>.
      ///@{
      std::vector<std::string> particles, fe;
      ///@}
    };

    /// @brief The physics @p name ("mechanics" for the first one) on the ranks of @p comm.
    Physics(const std::string &name, const MPI_Comm comm, std::ostream &log);

    /// @brief The physics <Physics/List> accepts, in the order their subsections are declared.
    static const std::vector<std::string> &
    names();

    /// @brief The subsection of the physics @p name: its name capitalized ("Heat").
    static std::string
    section(const std::string &name);

    /**
     * @brief Declare <Physics/List> and, for every physics of names(), the boundary-condition
     * names of its subsection (a first pass).
     */
    static void
    declare_names(dealii::ParameterHandler &prm);

    /**
     * @brief The physics of <Physics/List>, in order, each with its boundary-condition names,
     * read after declare_names() (or declare_parameters()). An unknown name or a name given
     * twice stops, naming the entry and the accepted values.
     */
    static std::vector<std::pair<std::string, ConditionNames>>
    parse_names(dealii::ParameterHandler &prm);

    /**
     * @brief Declare <Physics/List> and the subsection of every physics of names(): its
     * <Material>, <Boundary conditions>, <Finite elements> (physics, density and conditions),
     * <Initial conditions>, <Body force> and <Coupling/Method>; the boundary conditions are
     * those of @p condition_names (none for a physics it does not hold).
     */
    static void
    declare_parameters(dealii::ParameterHandler                    &prm,
                       const std::map<std::string, ConditionNames> &condition_names);

    /**
     * @brief Read this physics' subsection: its entries, with the problem's @p problem_settings
     * (solver, time stepping, output) and the geometry of the first physics @p first (its
     * particles and mesh are shared). Creates nothing.
     */
    void
    parse_parameters(dealii::ParameterHandler   &prm,
                     const ProblemSettings<dim> &problem_settings,
                     const Physics<dim>         &first);

    /// The message of @p exc with the entries of this physics' subsections prefixed.
    std::string
    named_in_section(const dealii::ExceptionBase &exc) const;

    /**
     * @brief What every physics reads the same way once its regions are read, in the current
     * subsection (the top level or its own; @p prefix, "" or e.g. "Heat/", names the entries
     * in messages): the layout (the same on particles and FE nodes, or FE translations and
     * particle rotations), the initial conditions, the body force and the model lines of the
     * checkpoint's fingerprint.
     */
    void
    parse_field(dealii::ParameterHandler &prm, const std::string &prefix);

    /**
     * @brief Read <Coupling/Method> and the method's subsection in the current subsection and
     * check it against this physics' solver type.
     */
    void
    parse_method(dealii::ParameterHandler &prm);

    /**
     * @brief Run @p work, which reads or sets up this physics, so that the refusals it throws
     * name the entries of this physics' own subsections with their full path: the parsers of
     * the regions, models and conditions name "<Material/...>", "<Boundary conditions/...>"
     * (they read the current subsection, whichever it is), which become "<Heat/Material/...>".
     * Entries of the problem's sections (<Discretization/...>, <Regions/...>) keep their names.
     * For the physics after the first (the first one's entries are the top-level ones).
     */
    template <typename Work>
    void
    with_entry_names(Work &&work) const
    {
      try
        {
          work();
        }
      catch (const dealii::ExceptionBase &exc)
        {
          AssertThrow(false, dealii::ExcMessage(named_in_section(exc)));
        }
    }

    /// Its name in <Physics/List> ("mechanics" for the first physics).
    const std::string name;
    /// The problem's settings with this physics' initial conditions and body force (for a
    /// physics of its own also its output base name, <Output/Base name>_<name>).
    ProblemSettings<dim> settings;
    /// The unknowns of a point (the particles' and the FE nodes').
    FieldLayout layout;
    /// The particle part (sharing the first physics' particles if not the first).
    ParticleRegion<dim> pd;
    /// The FE part (on the first physics' mesh if not the first).
    FERegion<dim> fe;
    /// <Coupling/Method>.
    std::string method_name;
    /// The fingerprint's lines of the models (Checkpoint).
    std::string model_lines;

    /// @name The parts this physics owns
    /// Each behind an accessor pair (a const Physics gives const parts); an accessor of a part
    /// not made yet stops (in debug mode).
    ///@{

    /// The coupling method of <Coupling/Method> (made by parse_method()).
    ///@{
    const CouplingMethod<dim> &
    method() const;

    CouplingMethod<dim> &
    method();
    ///@}

    /// The state, the solver and the postprocessors (made by CoupledProblem::check()).
    ///@{
    const CoupledState<dim> &
    state() const;

    CoupledState<dim> &
    state();

    const Solver<dim> &
    solver() const;

    Solver<dim> &
    solver();

    const Postprocessors<dim> &
    postprocessors() const;

    Postprocessors<dim> &
    postprocessors();
    ///@}

    /// Take the state, the solver and the postprocessors CoupledProblem::check() makes.
    ///@{
    void
    set_state(std::unique_ptr<CoupledState<dim>> new_state);

    void
    set_solver(std::unique_ptr<Solver<dim>> new_solver);

    void
    set_postprocessors(std::unique_ptr<Postprocessors<dim>> new_postprocessors);
    ///@}
    ///@}

  private:
    std::unique_ptr<CouplingMethod<dim>> coupling_method;
    std::unique_ptr<CoupledState<dim>>   coupled_state;
    std::unique_ptr<Solver<dim>>         physics_solver;
    std::unique_ptr<Postprocessors<dim>> physics_postprocessors;
  };
} // namespace perideal

#endif
