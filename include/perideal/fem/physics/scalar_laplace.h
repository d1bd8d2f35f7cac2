// ---------------------------------------------------------------------
// PeriDeal: FE physics 'scalar laplace'.
// ---------------------------------------------------------------------
#ifndef perideal_fem_physics_scalar_laplace_h
#define perideal_fem_physics_scalar_laplace_h

#include <perideal/fem/fe_physics.h>

#include <map>

namespace perideal
{
  /**
   * @brief A scalar field w with -div(k grad w) = f and k > 0 per material id: the
   * out-of-plane displacement of antiplane shear (w [m], k = mu [Pa], f the out-of-plane body
   * force [N/m^3], the stresses tau_xz = mu dw/dx, tau_yz = mu dw/dy; e.g. Barber,
   * Elasticity, 3rd ed., 2010, Sect. 15.1, eq. 15.6 with body force), or any scalar diffusion
   * (w a temperature [K], k a conductivity [W/(m K)], f a heat source [W/m^3]). The stiffness is
   * int k grad v . grad w dx (Hughes, The Finite Element Method, 2000, Sect. 1.4); the source
   * is the problem's body force (first component), in 2D times the thickness, like every load.
   *
   * Parameters (<Finite elements/scalar laplace>): <Coefficient> k [unit of f times m^2 per
   * unit of w: Pa for antiplane shear], <Coefficients by material id> overriding it per cell
   * material id ('1: 8e10, 2: 4e10'). Conditions: 'value' (w), 'rate' (dw/dt, explicit only),
   * 'flux' (g = k dw/dn, n the outward normal: the traction tau_zn of antiplane shear, the heat
   * flux into the body of diffusion). Output: w, dw_dx, dw_dy(, dw_dz) and the flux k grad w as
   * flux_x, flux_y(, flux_z), the same sign as the 'flux' condition: for antiplane shear with
   * k = mu, flux_x = tau_xz and flux_y = tau_yz.
   */
  template <int dim>
  class ScalarLaplace : public FEPhysics<dim>
  {
  public:
    /// @brief Declare <scalar laplace> (@p prm in <Finite elements>).
    void
    declare_parameters(dealii::ParameterHandler &prm) const override;

    /// @brief Read and check <scalar laplace> (k > 0); the planar assumption plays no role.
    void
    parse_parameters(dealii::ParameterHandler &prm, const PlanarAssumption planar) override;

    /// @brief One scalar "w".
    FieldLayout
    field_layout() const override;

    /// @brief sum_q w_q k grad phi_i . grad phi_j, k of @p material_id.
    void
    add_cell_stiffness(const dealii::FEValues<dim>     &fe_values,
                       const dealii::types::material_id material_id,
                       const std::vector<double>       &weights,
                       dealii::FullMatrix<double>      &cell_matrix) const override;

    /// @brief The gradient dw_dx, ... and the flux k grad w as flux_x, ...
    std::unique_ptr<dealii::DataPostprocessor<dim>>
    postprocessor() const override;

    /// @brief "coefficient k = ..." and the per-material values.
    std::string
    summary() const override;

    /// @brief The coefficient k of cells with material id @p material_id.
    double
    coefficient(const dealii::types::material_id material_id) const;

  private:
    double                                       default_coefficient = 1.;
    std::map<dealii::types::material_id, double> coefficients;
  };
} // namespace perideal

#endif
