// ---------------------------------------------------------------------
// PeriDeal: the interface of the methods that join an FE region and particles.
// ---------------------------------------------------------------------
#ifndef perideal_coupling_coupling_method_h
#define perideal_coupling_coupling_method_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/la_parallel_vector.h>

#include <perideal/base/linear_algebra.h>
#include <perideal/base/plugin_registry.h>
#include <perideal/base/problem_settings.h>
#include <perideal/coupling/communication_volume.h>
#include <perideal/fem/fe_region.h>
#include <perideal/pd/adaptive_dynamic_relaxation.h>
#include <perideal/pd/material_model.h>
#include <perideal/pd/particle_system.h>
#include <perideal/pd/static_solver.h>

#include <array>
#include <functional>
#include <limits>
#include <ostream>
#include <string>
#include <vector>

namespace perideal
{
  /**
   * @brief What a coupling method works on, owned by CoupledProblem: the FE region, the
   * particles and their model. How the two are joined (e.g. a TransferOperator) is the
   * method's.
   */
  template <int dim>
  struct CoupledRegions
  {
    /// The FE region (a method may prescribe interior dofs, FERegion::set_interior_values()).
    FERegion<dim> *fe = nullptr;
    /// The particles and their material model.
    ///@{
    ParticleSystem<dim> *particles = nullptr;
    MaterialModel<dim>  *material  = nullptr;
    ///@}
    /// The particles' mass density [kg/m^3].
    double density = 0.;
    /// The particles' unknowns: the FE region's, or those followed by rotations.
    FieldLayout layout;
    /// The overlap beta(x) in [0, 1] (1: PD only, 0: FE only).
    std::function<double(const dealii::Point<dim> &)> blending;
    /// The entry that gives it, "<Coupling/Blending function> = <...>", for messages.
    std::string blending_entry;
    /// The run's log (written on rank 0 only), for a method's convergence history.
    std::ostream *log = nullptr;
  };

  /**
   * @brief The strain energy of a coupled system as its two parts [J]: every part of the body
   * counted once, whatever the method does in an overlap.
   */
  struct CoupledEnergy
  {
    /// The part of the FE region.
    double fe = 0.;
    /// The part of the particles.
    double particles = 0.;
  };

  /**
   * @brief How a quasi-static solve finds equilibrium (<Solver>).
   */
  template <int dim>
  struct EquilibriumSettings
  {
    /// static or adaptive dynamic relaxation.
    SolverType type = SolverType::static_linear;
    /// The linear solver of the static type.
    typename StaticSolver<dim>::Settings linear;
    /// Tolerance and iterations of adaptive dynamic relaxation.
    AdaptiveDynamicRelaxation::Settings relaxation;
    /// Safety factor on the fictitious density of adaptive dynamic relaxation.
    double relaxation_safety = 1.;
  };

  /**
   * @brief A method that joins the FE region and the particles of a CoupledProblem
   * (<Coupling/Method>): it owns the coupling. It decides how the two energies share the
   * overlap, which particles are slaved to the FE field and which are free, how the FE field moves
   * the particles slaved to it (P) and how their forces act on the FE dofs (P^T) in explicit runs,
   * the masses, the strain energy of the coupled system, and how a quasi-static load step reaches
   * equilibrium.
   *
   * The solvers and postprocessors of CoupledProblem (the explicit time loop, the quasi-static
   * load stepping with re-solves while bonds break, the statistics, reactions and output) call
   * only this interface (through CoupledState), so a method plugs in through the registry
   * (PERIDEAL_REGISTER_COUPLING_METHOD) without a change to them; it need not use a transfer
   * operator at all. The overlap is given by <Coupling/Blending function> beta(x) (1: PD only,
   * 0: FE only); particles exist where the method's particle weight is positive and within a
   * horizon of such points, FE unknowns where its FE weight is positive.
   *
   * One object per run; the virtual calls are per solve or per time step, never per particle
   * or bond.
   */
  template <int dim>
  class CouplingMethod
  {
  public:
    virtual ~CouplingMethod() = default;

    /// Read the method's subsection <Coupling/name> (entered by the caller); none by default.
    virtual void
    parse_parameters(dealii::ParameterHandler &)
    {}

    /**
     * @brief Stop with a message naming <Solver/Type> if the method cannot run @p type; every
     * type by default.
     */
    virtual void
    check_solver(const SolverType) const
    {}

    /// The weight of the FE energy density at a point whose overlap value is @p beta.
    virtual double
    fe_weight(const double beta) const = 0;

    /// The weight of a particle's energy (and mass) at a point whose overlap value is @p beta.
    virtual double
    particle_weight(const double beta) const = 0;

    /**
     * @brief Build what the method needs (e.g. the transfer operator P) once the FE region (set
     * up with fe_weight()) and the particles (with particle_weight() as energy weights) exist.
     * First check what the method needs of the overlap and stop, naming
     * CoupledRegions::blending_entry, if it does not hold (collective).
     */
    virtual void
    initialize(const CoupledRegions<dim> &regions) = 0;

    /// What initialize() did, for the log line "Coupling: <name>, <summary>".
    virtual std::string
    summary() const = 0;

    /**
     * @brief The exchanges between the ranks that interpolate_to_particles() and
     * add_particle_forces() make (once each per explicit step), read from their communication
     * patterns (communication_volume.h); none by default. For the run's communication summary,
     * not called during the steps.
     */
    virtual std::vector<ExchangeVolume>
    transfer_exchanges() const
    {
      return {};
    }

    /**
     * @brief After initialize(): per owned particle, whether it is slaved to the FE field (its
     * values come from interpolate_to_particles(), its forces act on the FE dofs through
     * add_particle_forces()) or is free (it moves by its own forces and conditions).
     */
    virtual const std::vector<bool> &
    slaved_particles() const = 0;

    /**
     * @brief P: overwrite the owned entries of @p u of the particles slaved to the FE field
     * with their values from the FE field @p U (ghost values current); the free particles keep
     * theirs. Call update_ghost_values() on @p u afterwards.
     */
    virtual void
    interpolate_to_particles(const FEVector &U, ParticleVector &u) const = 0;

    /**
     * @brief P^T: add to @p F (FE dofs) the nodal forces of the particles slaved to the FE
     * field, from the particles' nodal forces @p f [N] (owned entries; those of free particles
     * are ignored).
     */
    virtual void
    add_particle_forces(const ParticleVector &f, FEVector &F) const = 0;

    /**
     * @brief The strain energy of the coupled system in the state whose FE displacement is
     * @p U and whose particles store @p particle_energy [J] (the model's
     * energy with the particle weights, summed over the ranks), each part of the body counted
     * once. Collective.
     */
    virtual CoupledEnergy
    strain_energy(const FEVector &U, const double particle_energy) const = 0;

    /**
     * @brief Explicit dynamics: the lumped masses of the FE dofs (@p fe_mass, sized like the FE
     * vectors) and of the owned particles (@p particle_mass, used for free particles).
     */
    virtual void
    lumped_masses(FEVector &fe_mass, std::vector<double> &particle_mass) const = 0;

    /**
     * @brief Quasi-static runs: prepare the equilibrium solves. @p particle_prescribed holds
     * 1 on the prescribed components of owned free particles; the prescribed FE dofs are
     * FERegion::prescribed_mask().
     */
    virtual void
    initialize_equilibrium(const ParticleVector           &particle_prescribed,
                           const EquilibriumSettings<dim> &settings,
                           const std::string              &conditions) = 0;

    /// Number of unknowns of the equilibrium solves (all ranks), for the log.
    virtual dealii::types::global_dof_index
    n_unknowns() const = 0;

    /**
     * @brief The accuracy of the method's equilibrium relative to the largest force, beyond
     * the solver's (ProblemSettings::solution_accuracy()): 0 for a method solved in one system;
     * an iteration between the parts stops at its own tolerance.
     */
    virtual double
    solution_accuracy() const
    {
      return 0.;
    }

    /**
     * @brief The equilibrium of the FE load @p f_fe (FERegion::assemble_load()) and the particle
     * force density @p f_pd [N/m^3]. On entry @p U and @p u hold the prescribed values and the
     * initial guess (owned entries); on exit the solution with ghost values, slaved particles
     * included. Bonds may break on the way. Returns the number of iterations.
     */
    virtual unsigned int
    solve_equilibrium(const FEVector       &f_fe,
                      const ParticleVector &f_pd,
                      FEVector             &U,
                      ParticleVector       &u) = 0;

    /**
     * @brief Implicit time stepping of a first-order field (ThetaScheme) and particle
     * convection: after initialize_equilibrium(), the diagonal D that the following
     * solve_equilibrium() calls add to their system, (D + K) z = F (the lumped capacities over
     * theta dt, a particle convection's conductance h V / d), @p fe_diagonal on the
     * FE dofs and @p particle_diagonal [N per unit of the field] on the components of the
     * particles that are not slaved to the FE field (owned entries). equilibrium_forces() keeps
     * K alone. A method that solves in one linear system supports it; by default the run stops,
     * naming <Solver/Type> (check_solver() should refuse the type before).
     */
    virtual void
    set_equilibrium_diagonal(const FEVector &fe_diagonal, const ParticleVector &particle_diagonal);

    /**
     * @brief The particles' strain energies [J] of the displacements @p u_0 and @p u_1 (ghost
     * values updated) in the method's model of equilibrium, at the temperature change the
     * particles' model reads now and with its present bonds (a linear static solve is
     * linearized anew for it): the work of a changing temperature
     * (CoupledState::accumulate_temperature_work()) is their change from one temperature to
     * another. Collective. By default the run stops, naming <Coupling/Method>.
     */
    virtual std::array<double, 2>
    equilibrium_particle_energies(const ParticleVector &u_0, const ParticleVector &u_1);

    /**
     * @brief The forces of the state (@p U, @p u) under the loads @p f_fe, @p f_pd, in the
     * method's model of equilibrium: @p fe_residual = K_FE U - f_FE - P^T (particle forces) on
     * the FE dofs (on prescribed dofs the force the supports exert, as FERegion::reactions()
     * expects), @p pd_force the particles' internal force density (owned entries). Returns the
     * particles' strain energy [J].
     */
    virtual double
    equilibrium_forces(const FEVector       &U,
                       const ParticleVector &u,
                       const FEVector       &f_fe,
                       const ParticleVector &f_pd,
                       FEVector             &fe_residual,
                       ParticleVector       &pd_force) = 0;
  };

  /**
   * @brief The strain energy of the particles' model @p material at the displacements @p u
   * (ghost values updated; no bond breaks; @p force and @p energy_density are scratch), summed
   * over the owned particles that @p counted flags (all if it is empty) [J]: the energy of a
   * method whose model of equilibrium is the model itself, and of explicit steps. Collective.
   */
  template <int dim>
  double
  model_strain_energy(MaterialModel<dim>      &material,
                      ParticleSystem<dim>     &particles,
                      const ParticleVector    &u,
                      ParticleVector          &force,
                      std::vector<double>     &energy_density,
                      const std::vector<bool> &counted = {})
  {
    material.compute_forces(particles,
                            u,
                            force,
                            &energy_density,
                            std::numeric_limits<double>::infinity());
    const auto &volume = particles.volumes();
    double      energy = 0.;
    for (unsigned int i = 0; i < particles.n_owned(); ++i)
      if (counted.empty() || counted[i])
        energy += energy_density[i] * volume[i];
    return dealii::Utilities::MPI::sum(energy, particles.get_communicator());
  }

  template <int dim>
  std::array<double, 2>
  CouplingMethod<dim>::equilibrium_particle_energies(const ParticleVector &, const ParticleVector &)
  {
    AssertThrow(false,
                dealii::ExcMessage("A quasi-static run with a temperature (<Temperature>) needs a "
                                   "coupling method that gives its particles' energies; accepted "
                                   "<Coupling/Method>: blended, overlapping schwarz."));
    return {};
  }

  template <int dim>
  void
  CouplingMethod<dim>::set_equilibrium_diagonal(const FEVector &, const ParticleVector &)
  {
    AssertThrow(false,
                dealii::ExcMessage("<Solver/Type> = implicit, and a particle 'convection' "
                                   "condition of <Boundary conditions> in a static solve, need a "
                                   "coupling method that solves both regions in one linear "
                                   "system; accepted <Coupling/Method>: blended."));
  }
} // namespace perideal

/**
 * Register the coupling method @p classname (a template in dim) under @p name.
 */
#define PERIDEAL_REGISTER_COUPLING_METHOD(classname, name, description)                    \
  PERIDEAL_REGISTER_PLUGIN(::perideal::CouplingMethod<2>, classname<2>, name, description) \
  PERIDEAL_REGISTER_PLUGIN(::perideal::CouplingMethod<3>, classname<3>, name, description)

#endif
