// ---------------------------------------------------------------------
// PeriDeal: the finite-element region: mesh, FE space, assembly, conditions, output; the
// physics is a plugin (FEPhysics).
// ---------------------------------------------------------------------
#ifndef perideal_fem_fe_region_h
#define perideal_fem_fe_region_h

#include <deal.II/base/data_out_base.h>
#include <deal.II/base/function.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/hp/fe_collection.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <perideal/base/checkpoint_file.h>
#include <perideal/base/convection.h>
#include <perideal/base/elasticity.h>
#include <perideal/base/field_layout.h>
#include <perideal/base/linear_algebra.h>
#include <perideal/fem/fe_physics.h>

#include <functional>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace perideal
{
  /**
   * @brief The FE region of a problem (alone, or coupled to particles) on a distributed mesh;
   * what the field means is its physics (FEPhysics, <Finite elements/Physics>).
   *
   * The mesh comes from a deal.II generator or a gmsh file (boundary ids from the physical
   * curves/surfaces). Each component of the physics' FieldLayout is FE_Q(p); cells where the
   * FE weight 1 - beta(x) vanishes (the PD-only zone of a coupled problem) carry FE_Nothing
   * and no unknowns.
   *
   * Boundary conditions act on sets of boundary ids, on the listed <Components> (names of the
   * layout). Their <Type> depends on the kind of the components: on translations
   * 'displacement' [m], 'velocity' [m/s, explicit dynamics only] or 'traction' [Pa]; on a
   * scalar field 'value', 'rate' (explicit dynamics only) or 'flux' (the boundary flux of the
   * field's equation, e.g. k dw/dn; under torsion the shear traction k (grad w + gamma_t) . n,
   * the twist included, since the twist is a volume load of the energy). A load condition
   * ('traction', 'flux') acts on every component of the field, and with the body force b(x, t)
   * (set_body_force()) it enters the load as int g . v ds and int b . v dx. In 2D forces are per
   * unit thickness times the 'Thickness' (so that they are in N, like the particles' forces). Dofs
   * inside the body can be prescribed too (set_interior_values()).
   *
   * The stiffness K = sum_cells int (1 - beta) a(v, u) dx (a from the physics) and the lumped
   * mass (Gauss-Lobatto nodal quadrature, so positive for every degree) are assembled
   * unconstrained; problems solve through CoupledStaticSolver, which holds the prescribed dofs
   * (prescribed_mask()) with the near-null space component_masks() (one constant mode per
   * component).
   *
   * The implementation is split by algorithm: fe_region.cc (parameters, accessors),
   * fe_region_setup.cc (mesh, FE_Nothing activation, dofs, sparsity), fe_region_assembly.cc
   * (stiffness, lumped mass, loads, stable step), fe_region_thermal.cc (the thermal strain's
   * load and energy), fe_region_conditions.cc (boundary conditions, interior values, reactions)
   * and fe_region_output.cc (summary, field output).
   */
  template <int dim>
  class FERegion
  {
  public:
    /// A boundary condition on a set of boundary ids.
    struct Condition
    {
      /// Its name in <Finite elements/Boundary conditions/Names> and its <Boundary ids>.
      ///@{
      std::string                          name;
      std::set<dealii::types::boundary_id> boundary_ids;
      ///@}
      /// value (displacement, value), rate (velocity, rate) or load (traction, flux,
      /// convection).
      Quantity type = Quantity::value;
      /// The components of the layout it acts on.
      std::vector<unsigned int> components;
      /// Its <Function>, one component per entry of components.
      std::shared_ptr<dealii::Function<dim>> function;
      /// A convection's coefficient and ambient temperature (<Type> 'convection', a load).
      std::optional<Convection<dim>> convection;
    };

    /// The weight 1 - beta(x) of the FE energy; cells where it is 0 everywhere are FE_Nothing.
    using WeightFunction = std::function<double(const dealii::Point<dim> &)>;

    /**
     * The temperature change Delta T = T - T_ref [K] at time @p time at the quadrature points of
     * @p fe_values into @p delta_T (sized by the caller to the number of points). @p fe_values
     * has at least the quadrature points; its cell (get_cell()) is a cell of get_dof_handler()
     * and its quadrature (get_quadrature()) the points in the unit cell, so that a field on
     * another DoFHandler of the same mesh (the heat physics' temperature) can be evaluated there.
     */
    using TemperatureChange = std::function<void(const dealii::FEValues<dim> &fe_values,
                                                 const double                 time,
                                                 std::vector<double>         &delta_T)>;

    /**
     * Values at the quadrature points of @p fe_values (a cell of get_dof_handler()), already
     * multiplied by the weights 1 - beta, the thickness and JxW, for a field on another
     * DoFHandler of the same mesh to integrate against its shape functions there.
     */
    using PointValues = std::function<void(const dealii::FEValues<dim> &fe_values,
                                           const std::vector<double>   &values)>;

    /// @brief An empty region on the ranks of @p comm; parse_parameters() and setup() fill it.
    explicit FERegion(const MPI_Comm comm);

    /**
     * @brief Declare the entries of the subsection "Finite elements" (including its boundary
     * conditions, one subsection per name in @p condition_names).
     */
    static void
    declare_parameters(dealii::ParameterHandler       &prm,
                       const std::vector<std::string> &condition_names);

    /**
     * @brief Declare what a physics of its own has of an FE region, in the current subsection
     * (e.g. <Heat>): <Finite elements> with <Physics>, <Density>, the physics' subsections and
     * the <Boundary conditions> @p condition_names; the mesh is the first physics'
     * (parse_physics_parameters()).
     */
    static void
    declare_physics_parameters(dealii::ParameterHandler       &prm,
                               const std::vector<std::string> &condition_names);

    /**
     * @brief Declare only the mesh entries and the list of boundary-condition names (for a
     * first pass).
     */
    static void
    declare_names(dealii::ParameterHandler &prm);

    /**
     * @brief Declare only <Finite elements/Boundary conditions/Names> in the current
     * subsection (the first pass of a physics of its own).
     */
    static void
    declare_condition_names(dealii::ParameterHandler &prm);

    /**
     * @brief The boundary-condition names listed in a file read after declare_names().
     */
    static std::vector<std::string>
    parse_names(dealii::ParameterHandler &prm);

    /**
     * @brief Read and check every entry of "Finite elements"; needs the planar assumption and
     * the thickness of a 2D problem (read elsewhere). Creates nothing. Without <Mesh file> and
     * <Generator> the problem has no FE region and nothing else of the section is read.
     */
    void
    parse_parameters(dealii::ParameterHandler &prm,
                     const PlanarAssumption    planar,
                     const double              thickness);

    /**
     * @brief Read the entries of declare_physics_parameters() in the current subsection; the
     * mesh (its entries, the planar assumption and the thickness) is @p geometry's, so that
     * setup() makes the same cells, partitioned alike, for this physics' own dofs.
     */
    void
    parse_physics_parameters(dealii::ParameterHandler &prm, const FERegion<dim> &geometry);

    /**
     * @brief Set the body force (the problem's <Body force/Function>, weighted by 1 - beta
     * here; or a manufactured one in a test). Without it there is none. Its first
     * field_layout().n_components() components act on the field's components (a scalar
     * physics reads the source from the first expression).
     */
    void
    set_body_force(const std::shared_ptr<dealii::Function<dim>> &function);

    /**
     * @brief Create the mesh, the FE space (FE_Nothing where @p weight is 0 on a whole cell),
     * the sparsity, the stiffness and the lumped mass. Without @p weight, the weight is 1.
     * Without a mesh (has_mesh()), the FE region is empty: one cell without unknowns.
     */
    void
    setup(const WeightFunction &weight = WeightFunction());

    /**
     * @brief After setup(): the FE space, sparsity, stiffness and mass for the new weight
     * @p weight on the same mesh (an adaptive PD region that grew: cells where it vanishes lose
     * their unknowns). The cells keep their shape functions, so the caller carries dof values
     * over cell by cell (get_dof_values() before, set_dof_values() after).
     */
    void
    reweight(const WeightFunction &weight);

    /**
     * @brief Prescribe the dofs @p dofs (global indices, the same list on every rank; each
     * rank uses the ones it owns) to @p values, like the dofs of a 'displacement' ('value')
     * condition: prescribe() sets them (at every time), prescribed_mask() holds them and
     * interior_reactions() gives their reactions. For Dirichlet data inside the body
     * (overlapping Schwarz). Call after setup(); a call replaces the previous one's dofs; a dof
     * may not be a boundary condition's as well.
     */
    void
    set_interior_values(const std::vector<dealii::types::global_dof_index> &dofs,
                        const std::vector<double>                          &values);

    /**
     * @brief The reactions (the entries of @p residual = K u - f) at the dofs of the last
     * set_interior_values(), in its order, summed over the ranks (collective).
     */
    std::vector<double>
    interior_reactions(const FEVector &residual) const;

    /**
     * @brief The external load f(t): load conditions, body force and the physics' own load
     * (FEPhysics::add_cell_load(): the twist of torsion), each weighted by 1 - beta.
     */
    void
    assemble_load(const double time, FEVector &f) const;

    /**
     * @brief Set the temperature change of the thermal strain (source/fem/fe_region_thermal.cc);
     * an empty function (the default) for none.
     */
    void
    set_temperature_change(const TemperatureChange &delta_T);

    /**
     * @brief Whether the physics has a thermal strain (FEPhysics::has_thermal_strain(): its
     * <Thermal expansion> is not zero) and a temperature change is set.
     */
    bool
    has_thermal_strain() const;

    /**
     * @brief The load of the thermal strain at @p time, f_th,i = int (1 - beta) h eps(phi_i) :
     * C : eps_th (FEPhysics::add_cell_thermal_load(), h the thickness of a 2D problem) into
     * @p f_th (ghosts compressed like assemble_load(); zero without thermal strain), and return
     * the constant c_th = int (1 - beta) h 1/2 eps_th : C : eps_th
     * (FEPhysics::thermal_energy_density()), summed over the ranks (collective), such that the
     * strain energy of the mechanical strain eps(u) - eps_th is 1/2 u.K.u - u.f_th + c_th. The
     * equilibrium is K u = f + f_th with the external load f of assemble_load(): the thermal
     * load is part of the strain energy, not external work.
     */
    double
    assemble_thermal_load(const double time, FEVector &f_th) const;

    /**
     * @brief The temperature change of set_temperature_change() at time @p time at points of a
     * cell given in real coordinates (for the output: FEPhysics::thermal_postprocessor()); an
     * empty function without thermal strain.
     */
    PointTemperatureChange<dim>
    point_temperature_change(const double time) const;

    /**
     * @brief The thermoelastic measure of the field @p u (ghost values current) on each owned
     * cell with unknowns: FEPhysics::cell_thermoelastic_measure() at the quadrature points of
     * the thermal load (assemble_thermal_load()) times its weights, handed to @p add cell by
     * cell. Integrated against the heat's shape functions it is the transpose of the thermal
     * load's coupling (doc/theory/thermoelasticity.md).
     */
    void
    thermoelastic_measure(const FEVector &u, const PointValues &add) const;

    /**
     * @brief Add the cell vector @p cell_vector of @p cell (a cell of get_dof_handler()) to
     * @p vector through the hanging-node constraints (call vector.compress(add) after the
     * last cell).
     */
    void
    add_cell_vector(const typename dealii::DoFHandler<dim>::active_cell_iterator &cell,
                    const dealii::Vector<double>                                 &cell_vector,
                    FEVector                                                     &vector) const;

    /**
     * @brief Set the prescribed components at @p time: of @p u for displacement (value)
     * conditions and interior values, of @p v for velocity (rate) conditions (owned entries;
     * the caller integrates u from v).
     */
    void
    prescribe(const double time, FEVector &u, FEVector &v) const;

    /**
     * @brief Whether the dof is prescribed by a displacement or velocity (value or rate)
     * condition or an interior value (owned dofs, by local index in the owned range).
     */
    const std::vector<bool> &
    prescribed_mask() const;

    /**
     * @brief The largest stable explicit time step: 2 / sqrt(lambda_max(M^-1 K)) of velocity
     * Verlet, or 2 / lambda_max(M^-1 K) of forward Euler for a first-order field (a
     * temperature, M the heat capacity), with the Gershgorin bound lambda_max <= max_i sum_j
     * |K_ij| / M_i, for the lumped mass or @p mass (e.g. with the particles' masses added in a
     * coupled problem).
     */
    double
    stable_time_step(const FEVector *mass = nullptr) const;

    /**
     * @brief Per owned dof, sum_j |K_ij x_j| (with ghost values of @p x), or sum_j |K_ij|
     * without @p x: the Gershgorin row bound, and the size of a nodal force without the
     * cancellation between neighbours.
     */
    std::vector<double>
    absolute_row_sums(const FEVector *x = nullptr) const;

    /**
     * @brief Strain energy 1/2 u^T K u and reactions sum over the dofs of every displacement
     * or velocity (value or rate) condition of (K u - f) (the force the support exerts, per
     * component c of the layout in entry c).
     */
    ///@{
    double
    strain_energy(const FEVector &u) const;
    std::vector<std::vector<double>>
    reactions(const FEVector &residual) const;
    ///@}

    /**
     * @brief The physics' section integrals (FEPhysics::integral_names(), e.g. the torque and
     * strain energy per unit length of torsion) of the field @p u over the FE-carrying cells,
     * weighted by 1 - beta (collective).
     */
    std::vector<double>
    section_integrals(const FEVector &u) const;

    /**
     * @brief Write the field (translations as the vector 'displacement', other components
     * by their names) and the physics' derived quantities of the FE-carrying cells (with
     * thermal strain those of FEPhysics::thermal_postprocessor() at @p time: the stress of the
     * mechanical strain, the temperature change) as
     * `<directory>/<base_name>_<step>.h5` plus `<base_name>.xdmf` (nothing without FE unknowns).
     * @p records holds the XDMF records of the series written so far, to which the step's is
     * added (the caller keeps them: a checkpoint carries them, so that a restarted run continues
     * the record).
     */
    void
    write_output(const std::string              &directory,
                 const std::string              &base_name,
                 const unsigned int              step,
                 const double                    time,
                 const FEVector                 &u,
                 std::vector<dealii::XDMFEntry> &records) const;

    /**
     * @brief Checkpoints (source/fem/fe_region_checkpoint.cc): the bytes section @p name of the
     * FE-carrying owned cells, each its CellId and its dof values of every vector of
     * @p vectors (the mesh is rebuilt from the parameter file, so the CellIds are the same on
     * any number of ranks). Collective.
     */
    void
    save_dof_values(CheckpointWriter                    &writer,
                    const std::string                   &name,
                    const std::vector<const FEVector *> &vectors) const;

    /// Read the values of save_dof_values() into @p vectors (owned entries; every rank reads
    /// the whole section). Collective.
    void
    load_dof_values(CheckpointReader              &reader,
                    const std::string             &name,
                    const std::vector<FEVector *> &vectors) const;

    /// The number of FE-carrying cells (FE_Q, not FE_Nothing), over the ranks. Collective.
    std::uint64_t
    n_cells_with_unknowns() const;

    /// A vector with the layout of the solution (owned + ghosted dofs).
    void
    initialize_vector(FEVector &vector) const;

    /// Whether the parameters give a mesh (<Mesh file> or <Generator>): otherwise the problem
    /// has no FE region.
    bool
    has_mesh() const;

    /// The number of FE unknowns: 0 if no cell carries FE_Q (the empty FE region of a coupled
    /// problem), and then no function of deal.II's DoFTools may be called on get_dof_handler().
    dealii::types::global_dof_index
    n_dofs() const;

    /// Whether the FE-carrying cells have hanging nodes (collective).
    bool
    has_hanging_nodes() const;

    /// The nodal interpolation of @p function (one component per component of the layout) into
    /// @p vector (owned entries).
    void
    interpolate(const dealii::Function<dim> &function, FEVector &vector) const;

    /// Per component of the layout, which owned dofs belong to it (the constant modes: the
    /// translations of elasticity, the constant of a scalar field; the near-null space of AMG).
    std::vector<std::vector<bool>>
    component_masks() const;

    /// One line describing the region, for the log (collective).
    std::string
    summary() const;

    /// @brief The mesh, the dofs, the elements {FE_Q(p)^n, FE_Nothing^n}, the weighted
    /// stiffness K (unconstrained) and the lumped mass.
    ///@{
    const dealii::parallel::distributed::Triangulation<dim> &
    get_triangulation() const;
    const dealii::DoFHandler<dim> &
    get_dof_handler() const;
    const dealii::hp::FECollection<dim> &
    get_fe_collection() const;
    const SparseMatrix &
    stiffness_matrix() const;
    const FEVector &
    lumped_mass() const;
    ///@}
    /// The physics (after parse_parameters()).
    const FEPhysics<dim> &
    physics() const;
    /// The unknowns of a node: the physics' layout.
    const FieldLayout &
    field_layout() const;
    /// <Finite elements/Density> [kg/m^3].
    double
    get_density() const;
    /// The boundary conditions, in the order of their names.
    const std::vector<Condition> &
    conditions() const;
    /// The weight 1 - beta at @p p (1 without coupling).
    double
    weight(const dealii::Point<dim> &p) const;

  private:
    /// A dof of a value or rate condition.
    struct PrescribedDof
    {
      unsigned int       local_index;
      unsigned int       condition;
      unsigned int       function_component;
      dealii::Point<dim> support_point;
    };

    /// The parameter subsection of the region.
    inline static const std::string section = "Finite elements";

    /**
     * @brief Create the mesh: the generator's or the gmsh file's (with the manifolds of
     * <Circular boundaries>), refined; one cell without unknowns if there is no FE region.
     */
    void
    make_mesh();

    /**
     * @brief Declare the entries of declare_physics_parameters() but the condition names.
     */
    static void
    declare_physics_entries(dealii::ParameterHandler       &prm,
                            const std::vector<std::string> &condition_names);

    /**
     * @brief Read <Physics>, and with a mesh <Density>, the physics' entries and the boundary
     * conditions @p names, in <Finite elements> of the current subsection.
     */
    void
    parse_physics(dealii::ParameterHandler &prm, const std::vector<std::string> &names);

    /// The FE space, sparsity, conditions and matrices for the weight @p weight.
    void
    distribute(const WeightFunction &weight);
    /**
     * @brief Declare the entries of the boundary conditions @p names; @p prm is in
     * <Finite elements/Boundary conditions>.
     */
    static void
    declare_condition_parameters(dealii::ParameterHandler       &prm,
                                 const std::vector<std::string> &names);
    /**
     * @brief Read and check the boundary conditions @p names on the field of <Physics> =
     * @p physics_name (layout set); @p prm is in <Finite elements/Boundary conditions>.
     */
    void
    parse_conditions(dealii::ParameterHandler       &prm,
                     const std::vector<std::string> &names,
                     const std::string              &physics_name);
    /**
     * @brief Find the owned dofs of the value and rate conditions (condition, component and
     * support point of each) and forget the interior values of an earlier set-up.
     */
    void
    locate_prescribed_dofs();
    /**
     * @brief Stop, naming the entry, if the physics' held_point() lies outside the mesh.
     */
    void
    check_held_point() const;
    /**
     * @brief Stop, naming the entry, if a boundary condition's ids name no boundary of the
     * mesh or only boundaries of cells without FE unknowns (it would act on nothing).
     */
    void
    check_conditions_act() const;
    /**
     * @brief Call @p work(cell, fe_values, weights) on each owned cell with unknowns, with
     * @p fe_values (values, gradients, points, JxW) at the thermal strain's quadrature points
     * (Gauss, degree + 1: where the heat's temperature is read and the heating integrated) and
     * their weights (quadrature_weights()).
     */
    template <typename Work>
    void
    for_each_thermal_cell(const Work &work) const;

    /// The weights 1 - beta, the thickness and JxW at the quadrature points of @p fe_values.
    void
    quadrature_weights(const dealii::FEValuesBase<dim> &fe_values,
                       std::vector<double>             &weights) const;
    /// The load of the body force, the physics' own load (FEPhysics::add_cell_load()) and the
    /// load conditions on @p cell at @p time.
    void
    assemble_cell_load(const typename dealii::DoFHandler<dim>::active_cell_iterator &cell,
                       const double                                                  time,
                       dealii::FEValues<dim>                                        &fe_values,
                       dealii::FEFaceValues<dim>                                    &fe_face_values,
                       dealii::Vector<double> &cell_rhs) const;
    /**
     * @brief Add h sum_q w_q phi_i phi_j of the convection (Robin) conditions on the boundary
     * faces of @p cell to @p cell_matrix: the part h T of their heat flux h (T_inf - T).
     */
    void
    add_convection_stiffness(const typename dealii::DoFHandler<dim>::active_cell_iterator &cell,
                             dealii::FEFaceValues<dim>  &face_values,
                             dealii::FullMatrix<double> &cell_matrix) const;
    /// The weighted stiffness and the lumped mass (unconstrained).
    void
    assemble_matrices();

    MPI_Comm comm;

    // Parameters.
    std::string                            mesh_file, generator, generator_arguments;
    unsigned int                           global_refinements = 0;
    unsigned int                           degree             = 1;
    double                                 thickness          = 1.;
    PlanarAssumption                       planar             = PlanarAssumption::three_dimensional;
    double                                 density            = 0.;
    std::unique_ptr<FEPhysics<dim>>        physics_model;
    FieldLayout                            layout;
    std::vector<Condition>                 condition_list;
    std::shared_ptr<dealii::Function<dim>> body_force;         // null: none
    TemperatureChange                      temperature_change; // empty: none
    std::vector<std::pair<dealii::types::boundary_id, dealii::Point<2>>> circular_boundaries;

    // State.
    WeightFunction                                    fe_weight;
    dealii::parallel::distributed::Triangulation<dim> triangulation;
    dealii::hp::FECollection<dim>                     fe_collection;
    dealii::DoFHandler<dim>                           dof_handler;
    dealii::IndexSet                                  owned_dofs, relevant_dofs;
    dealii::AffineConstraints<double>                 hanging_constraints;
    SparseMatrix                                      stiffness;
    FEVector                                          mass;
    std::vector<bool>                                 prescribed;
    std::vector<PrescribedDof>                        prescribed_dofs;
    /// The dofs of set_interior_values() (global) and, for those owned, local index and value.
    std::vector<dealii::types::global_dof_index> interior_dofs;
    std::vector<std::pair<unsigned int, double>> interior_values;
    /// The owned dof held at 0 at the physics' held_point() (none if not owned or not held).
    std::optional<unsigned int> held_dof;
  };
} // namespace perideal

#endif
