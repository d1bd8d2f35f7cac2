// ---------------------------------------------------------------------
// PeriDeal: the particle region of a problem.
// ---------------------------------------------------------------------
#ifndef perideal_pd_particle_region_h
#define perideal_pd_particle_region_h

#include <deal.II/base/parameter_handler.h>

#include <perideal/base/checkpoint_file.h>
#include <perideal/base/field_layout.h>
#include <perideal/base/linear_algebra.h>
#include <perideal/base/region.h>
#include <perideal/pd/boundary_conditions.h>
#include <perideal/pd/damage_model.h>
#include <perideal/pd/material_model.h>
#include <perideal/pd/particle_system.h>

#include <functional>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace perideal
{
  /**
   * @brief The particle region of a problem: its parameters (<Discretization>, <Regions>,
   * <Pre-cracks>, <Material> with the material and damage model, <Boundary conditions>), the
   * particles with their bonds, the model's constants and the critical stretch. The state (the
   * particles' displacement, velocity and forces) is the driver's (CoupledState), which reads
   * what it needs through the accessors here.
   *
   * An empty <Discretization/Body> gives no particles (an FE-only problem): only the entries the
   * FE region shares are read then (<Material/Planar assumption>, <Discretization/Thickness>).
   *
   * Use: declare_parameters() with the region and boundary-condition names of a first pass,
   * parse the file, parse_parameters() (checks every entry), setup() (particles, bonds, model
   * constants, stable time step).
   */
  template <int dim>
  class ParticleRegion
  {
  public:
    /**
     * @brief A particle region on @p comm that prints its log to @p log (rank 0 only).
     */
    ParticleRegion(const MPI_Comm comm, std::ostream &log);

    /**
     * @brief Declare the region's entries; the subsections of regions and boundary conditions
     * are those named in @p region_names and @p condition_names.
     */
    static void
    declare_parameters(dealii::ParameterHandler       &prm,
                       const std::vector<std::string> &region_names,
                       const std::vector<std::string> &condition_names);

    /**
     * @brief Declare what a physics of its own has of a particle region, in the current
     * subsection (e.g. <Heat>): <Material> (Model, Density and the models' subsections) and the
     * <Boundary conditions> @p condition_names; its geometry is the first physics'
     * (parse_physics_parameters()).
     */
    static void
    declare_physics_parameters(dealii::ParameterHandler       &prm,
                               const std::vector<std::string> &condition_names);

    /**
     * @brief Read and check the region's parameters; creates nothing on disk.
     */
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /**
     * @brief Read the entries of declare_physics_parameters() in the current subsection
     * (@p section, e.g. "Heat", names them in messages); the geometry (discretization,
     * regions, body, pre-cracks, no-fail regions, planar assumption) and the particles with
     * their one bond list are those of @p geometry: a bond broken there is broken here. Bonds
     * break by @p geometry's damage model only (this region's is none).
     */
    void
    parse_physics_parameters(dealii::ParameterHandler  &prm,
                             const std::string         &section,
                             const ParticleRegion<dim> &geometry);

    /**
     * @brief Generate the particles and bonds, initialize the model, find the stable time step.
     * Particles fill the lattice points of the body that also satisfy @p keep (if given; a
     * coupled problem keeps only the PD region); @p energy_weight (if given) weights each
     * particle's energy (ParticleSystem::set_energy_weights()). Writes the summary lines
     * (particles, bonds, material, critical stretch) to the log if @p log_summary. May be called
     * again (a PD region that grew): everything is rebuilt, the bonds intact but pre-cracks.
     * A region that shares another's particles (parse_physics_parameters()) generates none:
     * call setup() of the owner first; @p keep and @p energy_weight are the owner's then.
     */
    void
    setup(const std::function<bool(const dealii::Point<dim> &)>   &keep          = {},
          const std::function<double(const dealii::Point<dim> &)> &energy_weight = {},
          const bool                                               log_summary   = true);

    /// Whether a point lies in the body (<Discretization/Body>; after parse_parameters()).
    bool
    in_body(const dealii::Point<dim> &x) const;

    /// Whether <Discretization/Body> names regions (otherwise there are no particles).
    bool
    has_body() const;

    /// The unknowns of a particle (the material model's FieldLayout).
    FieldLayout
    field_layout() const;

    /// The particles and bonds (after setup()).
    ParticleSystem<dim> &
    particles();

    /// The particles and bonds (after setup()).
    const ParticleSystem<dim> &
    particles() const;

    /// The material model (after parse_parameters()).
    MaterialModel<dim> &
    material();

    /// The material model (after parse_parameters()).
    const MaterialModel<dim> &
    material() const;

    /// The boundary conditions of the particles.
    BoundaryConditions<dim> &
    boundary_conditions();

    /// The boundary conditions of the particles.
    const BoundaryConditions<dim> &
    boundary_conditions() const;

    /// The mass density rho [kg/m^3].
    double
    density() const;

    /// The critical stretch of the damage model (after setup()).
    double
    critical_stretch() const;

    /// The stable explicit time step of the particles alone (after setup()) [s].
    double
    stable_time_step() const;

    /// The lattice spacing, horizon, thickness and partial-volume rule.
    const typename ParticleSystem<dim>::Settings &
    discretization() const;

    /// The planar assumption (<Material/Planar assumption>; three_dimensional in 3D).
    PlanarAssumption
    planar_assumption() const;

    /**
     * @brief Checkpoints (source/pd/particle_region_checkpoint.cc): the records section @p name
     * of the owned particles at their ParticleSystem::invariant_index() (so that any number of
     * ranks reads them), each the @p n_components values of every vector of @p vectors, then
     * the value of every per-particle array of @p per_particle. Collective.
     */
    void
    save_particle_records(CheckpointWriter                               &writer,
                          const std::string                              &name,
                          const std::vector<const ParticleVector *>      &vectors,
                          const unsigned int                              n_components,
                          const std::vector<const std::vector<double> *> &per_particle) const;

    /// Read the records of save_particle_records() into @p vectors and @p per_particle (owned
    /// entries).
    void
    load_particle_records(CheckpointReader                         &reader,
                          const std::string                        &name,
                          const std::vector<ParticleVector *>      &vectors,
                          const unsigned int                        n_components,
                          const std::vector<std::vector<double> *> &per_particle) const;

    /**
     * @brief The bytes section @p name of the broken bonds (state 0) as pairs of invariant
     * indices, each bond once (pre-cracks and no-fail bonds are rebuilt by the set-up). The
     * bond list is shared by the physics: the particles' owner writes it. Collective.
     */
    void
    save_bond_states(CheckpointWriter &writer, const std::string &name) const;

    /// Break the bonds of save_bond_states() (every rank reads them all); stops if they do not
    /// join particles of this run. Collective.
    void
    load_bond_states(CheckpointReader &reader, const std::string &name);

    /**
     * @brief The bytes section @p name of the model's bond histories
     * (MaterialModel::bond_history()): records (pair of invariant indices, values) of the bonds
     * with a non-zero history, each bond once. Nothing for a model without them. Collective.
     */
    void
    save_bond_histories(CheckpointWriter &writer, const std::string &name) const;

    /// Restore the histories of save_bond_histories() (every rank reads them all). Collective.
    void
    load_bond_histories(CheckpointReader &reader, const std::string &name);

  private:
    /**
     * @brief Read <Material> (model, density; with @p with_geometry also the planar
     * assumption, the no-fail regions and the damage model) and <Boundary conditions>;
     * @p section prefixes the entries in messages ("" or e.g. "Heat/").
     */
    void
    parse_material(dealii::ParameterHandler &prm,
                   const std::string        &section,
                   const bool                with_geometry);

    /**
     * @brief Once generate() has estimated the particles, @p n_particles, before anything per
     * particle takes memory: warn (MemoryEstimate::warning()) if the bonds, half an interior
     * particle's family per particle, would not fit in the memory the nodes of the run have
     * available. Collective.
     */
    void
    warn_if_bonds_exceed_memory(const std::uint64_t n_particles) const;

    MPI_Comm      communicator;
    std::ostream &log;
    bool          is_root;

    // Parameters.
    typename ParticleSystem<dim>::Settings settings;
    double                                 horizon_factor     = 0.;
    bool                                   surface_correction = true;
    bool                                   stiffness_fit      = false;
    PlanarAssumption                       planar             = PlanarAssumption::three_dimensional;
    RegionCollection<dim>                  regions;
    std::vector<std::string>               body_regions;
    /// The union of the body regions (empty without a body).
    std::function<bool(const dealii::Point<dim> &)> body;
    std::vector<std::string>                        no_fail_regions;
    std::vector<PreCrack<dim>>                      pre_cracks;
    std::unique_ptr<MaterialModel<dim>>             model;
    std::unique_ptr<DamageModel<dim>>               damage;
    double                                          rho = 0.;
    BoundaryConditions<dim>                         conditions;

    // What setup() computes: the particles, shared with the physics of
    // parse_physics_parameters() (owns_particles false there).
    std::shared_ptr<ParticleSystem<dim>> particle_system;
    bool                                 owns_particles = true;
    double                               s_critical     = 0.;
    double                               stable_dt      = 0.;
  };
} // namespace perideal

#endif
