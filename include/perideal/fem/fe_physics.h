// ---------------------------------------------------------------------
// PeriDeal: interface of the physics of the FE region (plugins).
// ---------------------------------------------------------------------
#ifndef perideal_fem_fe_physics_h
#define perideal_fem_fe_physics_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <perideal/base/elasticity.h>
#include <perideal/base/field_layout.h>
#include <perideal/base/plugin_registry.h>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace perideal
{
  /**
   * @brief The temperature change Delta T = T - T_ref [K] at points of a cell, for the output
   * of a physics with a thermal strain (FEPhysics::thermal_postprocessor()): given a cell of the
   * region's DoFHandler and points of it (real coordinates), fill @p delta_T (sized by the
   * caller) with Delta T at each point (FERegion::point_temperature_change()).
   */
  template <int dim>
  using PointTemperatureChange =
    std::function<void(const typename dealii::DoFHandler<dim>::cell_iterator &cell,
                       const std::vector<dealii::Point<dim>>                 &points,
                       std::vector<double>                                   &delta_T)>;

  /**
   * @brief What a physics of the FE region (FERegion) supplies: only what differs between
   * physics. The region owns the mesh, the FE space (one FE_Q(p) per component of
   * field_layout(), FE_Nothing where the FE weight vanishes), the assembly (it multiplies by
   * the FE weight 1 - beta, the thickness of a 2D problem and JxW), the lumped mass (density of
   * <Finite elements/Density> times mass_factor()), the loads (body source and the load conditions,
   * integrated against the shape functions of their components), the constraints, the reactions and
   * the output. The near-null space of AMG is one constant mode per component of the layout (the
   * translations of elasticity, the constant of a scalar field).
   *
   * A physics is chosen by <Finite elements/Physics> (registered with
   * PERIDEAL_REGISTER_FE_PHYSICS) and declares its own subsection inside <Finite elements>.
   */
  template <int dim>
  class FEPhysics
  {
  public:
    virtual ~FEPhysics() = default;

    /**
     * @brief Declare the physics' own subsection; @p prm is in <Finite elements>.
     */
    virtual void
    declare_parameters(dealii::ParameterHandler &prm) const = 0;

    /**
     * @brief Read and check the physics' own subsection (@p prm is in <Finite elements>);
     * @p planar is the problem's planar assumption (three_dimensional in 3D).
     */
    virtual void
    parse_parameters(dealii::ParameterHandler &prm, const PlanarAssumption planar) = 0;

    /**
     * @brief The unknowns of an FE node: their number, kinds (which condition types they
     * take) and the names <Components> entries and the output use.
     */
    virtual FieldLayout
    field_layout() const = 0;

    /**
     * @brief Add sum_q @p weights[q] a(phi_i, phi_j)(x_q) to @p cell_matrix (zeroed by the
     * caller): the bilinear form of the physics at the quadrature points of @p fe_values (which
     * has update_gradients) on a cell of material id @p material_id. The weights already hold
     * the FE weight, the thickness and JxW.
     */
    virtual void
    add_cell_stiffness(const dealii::FEValues<dim>     &fe_values,
                       const dealii::types::material_id material_id,
                       const std::vector<double>       &weights,
                       dealii::FullMatrix<double>      &cell_matrix) const = 0;

    /**
     * @brief Whether add_cell_load() adds anything (false by default).
     */
    virtual bool
    has_cell_load() const;

    /**
     * @brief Add the physics' own load sum_q @p weights[q] l(phi_i)(x_q) to @p cell_rhs: a
     * volume load that is part of its energy, not of the problem's body force (the twist of
     * torsion: l(phi_i) = -k grad phi_i . gamma_t from the energy k/2 |grad w + gamma_t|^2).
     * @p fe_values has values, gradients and quadrature points; the weights hold the FE weight
     * 1 - beta, the thickness and JxW, so the load is that of the blended energy. None by
     * default.
     */
    virtual void
    add_cell_load(const dealii::FEValues<dim>     &fe_values,
                  const dealii::types::material_id material_id,
                  const std::vector<double>       &weights,
                  dealii::Vector<double>          &cell_rhs) const;

    /**
     * @brief Whether the physics has a thermal strain eps_th = alpha Delta T (its
     * <Thermal expansion> is not zero): then add_cell_thermal_load(), thermal_energy_density()
     * and thermal_postprocessor() take a temperature change into account (false by default).
     */
    virtual bool
    has_thermal_strain() const;

    /**
     * @brief Add the load of the thermal strain, sum_q @p weights[q] eps(phi_i) : C : eps_th(x_q)
     * with eps_th = alpha Delta T_q (in 2D the reduced expansion of the planar assumption), to
     * @p cell_rhs, for the temperature change @p delta_T [K] at the quadrature points of
     * @p fe_values (values, gradients, quadrature points) on a cell of material id
     * @p material_id. The weights hold the FE weight 1 - beta, the thickness and JxW. It is part
     * of the strain energy of the mechanical strain eps - eps_th (not an external load): that
     * energy, of the 3D body, is 1/2 u.K.u - u.f_th + int thermal_energy_density()
     * (doc/theory/thermal_strain_fe.md). None by default.
     */
    virtual void
    add_cell_thermal_load(const dealii::FEValues<dim>     &fe_values,
                          const dealii::types::material_id material_id,
                          const std::vector<double>       &weights,
                          const std::vector<double>       &delta_T,
                          dealii::Vector<double>          &cell_rhs) const;

    /**
     * @brief The strain-energy density [J/m^3] of the thermal strain alone, 1/2 eps_th : C :
     * eps_th for the temperature change @p delta_T [K] in material @p material_id: the energy
     * of a body held at u = 0 (in plane strain with its held out-of-plane strain), the constant
     * of the energy of the mechanical strain (see add_cell_thermal_load()). 0 by default.
     */
    virtual double
    thermal_energy_density(const dealii::types::material_id material_id,
                           const double                     delta_T) const;

    /**
     * @brief The thermoelastic measure beta : eps(u) [Pa] at the quadrature points of
     * @p fe_values (values, gradients) into @p measure (sized by the caller), for the cell's
     * values @p cell_values (in the order of the cell's dofs) in material @p material_id:
     * beta = C : alpha, the stress of a unit temperature change at no strain (in 2D that of the
     * reduced expansion of the planar assumption, the transpose of add_cell_thermal_load()'s),
     * whose rate heats a two-way coupled temperature (doc/theory/thermoelasticity.md). Zero by
     * default.
     */
    virtual void
    cell_thermoelastic_measure(const dealii::FEValues<dim>     &fe_values,
                               const dealii::types::material_id material_id,
                               const dealii::Vector<double>    &cell_values,
                               std::vector<double>             &measure) const;

    /**
     * @brief The thermoelastic coupling modulus beta : alpha [Pa/K^2] of the deformation that
     * cell_thermoelastic_measure() measures (in 2D beta_2D : alpha_2D of the planar assumption):
     * with T_0 / (rho c) of a two-way coupled heat it is the coupling number delta by which the
     * adiabatic stiffness exceeds the isothermal one, C_ad <= (1 + delta) C, which lowers the
     * stable explicit step (doc/theory/thermoelasticity.md, "The stable time step"). Zero by
     * default.
     */
    virtual double
    thermoelastic_coupling_modulus() const;

    /**
     * @brief The postprocessor of the output when a temperature change is set: the derived
     * quantities of postprocessor() from the mechanical strain, with the temperature change
     * @p delta_T at the points of a cell. postprocessor() by default (no thermal strain).
     */
    virtual std::unique_ptr<dealii::DataPostprocessor<dim>>
    thermal_postprocessor(const PointTemperatureChange<dim> &delta_T) const;

    /**
     * @brief A point of the section where the field is held at 0 when no condition prescribes
     * its value (a problem loaded on free faces only, defined up to a constant: torsion), with
     * the entry that gives it; none by default. The region holds the vertex nearest to it and
     * stops, naming the entry, if the point lies outside the mesh.
     */
    virtual std::optional<std::pair<dealii::Point<dim>, std::string>>
    held_point() const;

    /**
     * @brief The names of the section integrals the physics computes from the solution (the
     * statistics columns fe_<name>); none by default.
     */
    virtual std::vector<std::string>
    integral_names() const;

    /**
     * @brief Add the integrands of integral_names() times @p weights[q] (FE weight and JxW)
     * over the quadrature points of @p fe_values (values, gradients, quadrature points) of a
     * cell of material id @p material_id with the dof values @p cell_values to @p integrals.
     */
    virtual void
    add_cell_integrals(const dealii::FEValues<dim>     &fe_values,
                       const dealii::types::material_id material_id,
                       const std::vector<double>       &weights,
                       const dealii::Vector<double>    &cell_values,
                       std::vector<double>             &integrals) const;

    /**
     * @brief The factor of <Finite elements/Density> rho in the lumped mass of the region: 1 by
     * default (the inertia rho of a displacement); the specific heat c of a temperature field,
     * whose lumped "mass" is the heat capacity rho c [J/(m^3 K)].
     */
    virtual double
    mass_factor() const;

    /**
     * @brief The derived quantities written with the solution (strains and stresses, fluxes),
     * from the solution's gradients.
     */
    virtual std::unique_ptr<dealii::DataPostprocessor<dim>>
    postprocessor() const = 0;

    /**
     * @brief The material for the region's summary line ("material ...").
     */
    virtual std::string
    summary() const = 0;

    /**
     * @brief Whether the physics took its constants from the particles' material subsection
     * (false by default): the particles must then have one set of constants
     * (MaterialModel::nonuniform_constants(), checked by the coupled problem).
     */
    virtual bool
    shares_particle_material() const;
  };

  template <int dim>
  bool
  FEPhysics<dim>::has_cell_load() const
  {
    return false;
  }

  template <int dim>
  void
  FEPhysics<dim>::add_cell_load(const dealii::FEValues<dim> &,
                                const dealii::types::material_id,
                                const std::vector<double> &,
                                dealii::Vector<double> &) const
  {}

  template <int dim>
  bool
  FEPhysics<dim>::has_thermal_strain() const
  {
    return false;
  }

  template <int dim>
  void
  FEPhysics<dim>::add_cell_thermal_load(const dealii::FEValues<dim> &,
                                        const dealii::types::material_id,
                                        const std::vector<double> &,
                                        const std::vector<double> &,
                                        dealii::Vector<double> &) const
  {}

  template <int dim>
  double
  FEPhysics<dim>::thermal_energy_density(const dealii::types::material_id, const double) const
  {
    return 0.;
  }

  template <int dim>
  void
  FEPhysics<dim>::cell_thermoelastic_measure(const dealii::FEValues<dim> &,
                                             const dealii::types::material_id,
                                             const dealii::Vector<double> &,
                                             std::vector<double> &measure) const
  {
    std::fill(measure.begin(), measure.end(), 0.);
  }

  template <int dim>
  double
  FEPhysics<dim>::thermoelastic_coupling_modulus() const
  {
    return 0.;
  }

  template <int dim>
  std::unique_ptr<dealii::DataPostprocessor<dim>>
  FEPhysics<dim>::thermal_postprocessor(const PointTemperatureChange<dim> &) const
  {
    return postprocessor();
  }

  template <int dim>
  double
  FEPhysics<dim>::mass_factor() const
  {
    return 1.;
  }

  template <int dim>
  bool
  FEPhysics<dim>::shares_particle_material() const
  {
    return false;
  }

  template <int dim>
  std::optional<std::pair<dealii::Point<dim>, std::string>>
  FEPhysics<dim>::held_point() const
  {
    return {};
  }

  template <int dim>
  std::vector<std::string>
  FEPhysics<dim>::integral_names() const
  {
    return {};
  }

  template <int dim>
  void
  FEPhysics<dim>::add_cell_integrals(const dealii::FEValues<dim> &,
                                     const dealii::types::material_id,
                                     const std::vector<double> &,
                                     const dealii::Vector<double> &,
                                     std::vector<double> &) const
  {}
} // namespace perideal

/**
 * Register FE physics @p classname (a class template in dim) under @p name for dim = 2 and 3.
 * The registry's own per-plugin subsection is not used: a physics declares its subsection in
 * FEPhysics::declare_parameters() (linear elasticity keeps <Finite elements/Elasticity>).
 */
#define PERIDEAL_REGISTER_FE_PHYSICS_FOR(dim, classname, name, description)    \
  namespace                                                                    \
  {                                                                            \
    const bool PERIDEAL_REGISTRY_CONCAT(perideal_fe_physics_, __COUNTER__) =   \
      ::perideal::PluginRegistry<::perideal::FEPhysics<dim>>::register_plugin( \
        name,                                                                  \
        description,                                                           \
        {},                                                                    \
        []() -> std::unique_ptr<::perideal::FEPhysics<dim>> {                  \
          return std::make_unique<classname<dim>>();                           \
        });                                                                    \
  }

#define PERIDEAL_REGISTER_FE_PHYSICS(classname, name, description)  \
  PERIDEAL_REGISTER_FE_PHYSICS_FOR(2, classname, name, description) \
  PERIDEAL_REGISTER_FE_PHYSICS_FOR(3, classname, name, description)

#endif
