// ---------------------------------------------------------------------
// PeriDeal: the finite-element region, linear elasticity on a distributed mesh.
// ---------------------------------------------------------------------
#ifndef perideal_fem_fe_solid_h
#define perideal_fem_fe_solid_h

#include <deal.II/base/data_out_base.h>
#include <deal.II/base/function.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/hp/fe_collection.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <perideal/base/elasticity.h>
#include <perideal/base/field_layout.h>
#include <perideal/base/linear_algebra.h>

#include <functional>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace perideal
{
  /**
   * @brief Linear elasticity with finite elements on a distributed mesh: the FE region of a
   * problem (alone, or coupled to particles).
   *
   * The mesh comes from a deal.II generator or a gmsh file (boundary ids from the physical
   * curves/surfaces). Displacements are FE_Q(p)^dim; cells where the FE weight 1 - beta(x)
   * vanishes (the PD-only zone of a coupled problem) carry FE_Nothing and no unknowns.
   *
   * Boundary conditions act on sets of boundary ids:
   * - 'displacement': u_c(x, t) = g_c(x, t) for the listed components c;
   * - 'velocity' (explicit dynamics only): v_c(x, t) = g_c(x, t);
   * - 'traction': the traction vector T(x, t) [Pa] on the boundary faces.
   * and a body force b(x, t) [N/m^3] (set_body_force()) acts everywhere. In 2D forces are per unit
   * thickness times the 'Thickness' (so that they are in N, like the particles' forces).
   *
   * The stiffness K = sum_cells int (1 - beta) B^T C B dx and the lumped mass (Gauss-Lobatto
   * nodal quadrature, so positive for every degree) are assembled unconstrained; the static
   * solve condenses the displacement conditions (AffineConstraints) and solves with CG + AMG
   * (Trilinos ML), with the rigid-body modes as near-null space.
   */
  template <int dim>
  class FESolid
  {
  public:
    enum class ConditionType
    {
      displacement,
      velocity,
      traction
    };

    /// A boundary condition on a set of boundary ids.
    struct Condition
    {
      std::string                            name;
      std::set<dealii::types::boundary_id>   boundary_ids;
      ConditionType                          type = ConditionType::displacement;
      std::vector<unsigned int>              components;
      std::shared_ptr<dealii::Function<dim>> function;
    };

    /// The weight 1 - beta(x) of the FE energy; cells where it is 0 everywhere are FE_Nothing.
    using WeightFunction = std::function<double(const dealii::Point<dim> &)>;

    explicit FESolid(const MPI_Comm comm);

    /**
     * @brief Declare the entries of the subsection "Finite elements" (including its boundary
     * conditions, one subsection per name in @p condition_names).
     */
    static void
    declare_parameters(dealii::ParameterHandler       &prm,
                       const std::vector<std::string> &condition_names);

    /**
     * @brief Declare only the list of boundary-condition names (for a first pass).
     */
    static void
    declare_names(dealii::ParameterHandler &prm);

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
     * @brief Set the body force (the problem's <Body force/Function>, weighted by 1 - beta
     * here; or a manufactured one in a test). Without it there is none.
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
     * @brief Solve K u = f(t) with the displacement conditions at @p time, CG + AMG to the
     * relative residual @p tolerance (the FE region alone, e.g. in its validation tests;
     * problems solve through CoupledStaticSolver).
     * @return The number of CG iterations.
     */
    unsigned int
    solve_static(const double time, const double tolerance = 1e-10);

    /**
     * @brief The external load f(t): tractions and body force.
     */
    void
    assemble_load(const double time, dealii::LinearAlgebra::distributed::Vector<double> &f) const;

    /**
     * @brief Set the prescribed components at @p time: of @p u for displacement conditions, of
     * @p v for velocity conditions (owned entries; the caller integrates u from v).
     */
    void
    prescribe(const double                                        time,
              dealii::LinearAlgebra::distributed::Vector<double> &u,
              dealii::LinearAlgebra::distributed::Vector<double> &v) const;

    /**
     * @brief Whether the dof is prescribed by a displacement or velocity condition (owned
     * dofs, by local index in the owned range).
     */
    const std::vector<bool> &
    prescribed_mask() const;

    /**
     * @brief The largest stable explicit time step 2 / sqrt(lambda_max(M^-1 K)), with the
     * Gershgorin bound lambda_max <= max_i sum_j |K_ij| / M_i, for the lumped mass or
     * @p mass (e.g. with the particles' masses added in a coupled problem).
     */
    double
    stable_time_step(
      const dealii::LinearAlgebra::distributed::Vector<double> *mass = nullptr) const;

    /**
     * @brief Per owned dof, sum_j |K_ij x_j| (with ghost values of @p x), or sum_j |K_ij|
     * without @p x: the Gershgorin row bound, and the size of a nodal force without the
     * cancellation between neighbours.
     */
    std::vector<double>
    absolute_row_sums(const dealii::LinearAlgebra::distributed::Vector<double> *x = nullptr) const;

    /**
     * @brief Strain energy 1/2 u^T K u and reactions sum over the dofs of every displacement
     * or velocity condition of (K u - f) (the force the support exerts, per component).
     */
    double
    strain_energy(const dealii::LinearAlgebra::distributed::Vector<double> &u) const;
    std::vector<dealii::Tensor<1, dim>>
    reactions(const dealii::LinearAlgebra::distributed::Vector<double> &residual) const;

    /**
     * @brief Write displacement, (velocity), strain, stress and von Mises stress of the
     * FE-carrying cells as `<directory>/<base_name>_<step>.h5` plus `<base_name>.xdmf`
     * (nothing without FE unknowns).
     */
    void
    write_output(const std::string                                        &directory,
                 const std::string                                        &base_name,
                 const unsigned int                                        step,
                 const double                                              time,
                 const dealii::LinearAlgebra::distributed::Vector<double> &u);

    /// A vector with the layout of the solution (owned + ghosted dofs).
    void
    initialize_vector(dealii::LinearAlgebra::distributed::Vector<double> &vector) const;

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

    /// The nodal interpolation of @p function (dim components) into @p vector (owned entries).
    void
    interpolate(const dealii::Function<dim>                        &function,
                dealii::LinearAlgebra::distributed::Vector<double> &vector) const;

    /// Per component, which owned dofs belong to it (the translations, the near-null space of
    /// AMG).
    std::vector<std::vector<bool>>
    component_masks() const;

    /// The unknowns of an FE node: the displacement x, y(, z).
    FieldLayout
    field_layout() const;

    /// One line describing the region, for the log (collective).
    std::string
    summary() const;

    // Accessors.
    const dealii::parallel::distributed::Triangulation<dim> &
    get_triangulation() const;
    const dealii::DoFHandler<dim> &
    get_dof_handler() const;
    const dealii::hp::FECollection<dim> &
    get_fe_collection() const;
    const SparseMatrix &
    stiffness_matrix() const;
    const dealii::LinearAlgebra::distributed::Vector<double> &
    lumped_mass() const;
    const dealii::LinearAlgebra::distributed::Vector<double> &
    solution() const;
    const dealii::SymmetricTensor<4, dim> &
    elasticity_tensor() const;
    double
    get_density() const;
    const std::vector<Condition> &
    conditions() const;
    /// The weight 1 - beta at @p p (1 without coupling).
    double
    weight(const dealii::Point<dim> &p) const;

  private:
    /// A dof of a displacement or velocity condition.
    struct PrescribedDof
    {
      unsigned int       local_index;
      unsigned int       condition;
      unsigned int       function_component;
      dealii::Point<dim> support_point;
    };

    void
    make_mesh();
    /**
     * @brief Stop, naming the entry, if a boundary condition's ids name no boundary of the
     * mesh or only boundaries of cells without FE unknowns (it would act on nothing).
     */
    void
    check_conditions_act() const;
    void
    assemble_cell_matrix(dealii::FEValues<dim>      &fe_values,
                         dealii::FullMatrix<double> &cell_matrix) const;
    void
    assemble_cell_load(const typename dealii::DoFHandler<dim>::active_cell_iterator &cell,
                       const double                                                  time,
                       dealii::FEValues<dim>                                        &fe_values,
                       dealii::FEFaceValues<dim>                                    &fe_face_values,
                       dealii::Vector<double> &cell_rhs) const;
    void
    make_constraints(const double time, dealii::AffineConstraints<double> &constraints) const;
    void
    assemble_matrices();

    MPI_Comm comm;

    // Parameters.
    std::string                            mesh_file, generator, generator_arguments;
    unsigned int                           global_refinements = 0;
    unsigned int                           degree             = 1;
    PlanarAssumption                       planar             = PlanarAssumption::three_dimensional;
    double                                 thickness          = 1.;
    double                                 density            = 0.;
    ElasticMaterial                        material;
    dealii::SymmetricTensor<4, dim>        C;
    std::vector<Condition>                 condition_list;
    std::shared_ptr<dealii::Function<dim>> body_force; // null: none
    std::vector<std::pair<dealii::types::boundary_id, dealii::Point<2>>> circular_boundaries;

    // State.
    WeightFunction                                     fe_weight;
    dealii::parallel::distributed::Triangulation<dim>  triangulation;
    dealii::hp::FECollection<dim>                      fe_collection;
    dealii::DoFHandler<dim>                            dof_handler;
    dealii::IndexSet                                   owned_dofs, relevant_dofs;
    dealii::AffineConstraints<double>                  hanging_constraints;
    SparseMatrix                                       stiffness, system_matrix;
    dealii::LinearAlgebra::distributed::Vector<double> mass, displacement;
    std::vector<bool>                                  prescribed;
    std::vector<PrescribedDof>                         prescribed_dofs;
    std::vector<dealii::XDMFEntry>                     xdmf_entries;
  };
} // namespace perideal

#endif
