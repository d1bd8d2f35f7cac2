// ---------------------------------------------------------------------
// PeriDeal: FE physics 'scalar laplace'.
// ---------------------------------------------------------------------
#ifndef perideal_fem_physics_scalar_laplace_h
#define perideal_fem_physics_scalar_laplace_h

#include <perideal/base/torsion.h>
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
   *
   * Saint-Venant torsion (2D, <Twist per unit length> psi != 0 and <Twist axis> (x0, y0) in
   * the same subsection, see Torsion): w is the warping psi phi, the flux is the shear stress
   * tau = k (grad w + psi (-(y - y0), x - x0)) (output flux_x = tau_xz, flux_y = tau_yz), and
   * every boundary face without a condition (outer faces, crack faces of a slit mesh) carries
   * the traction-free load g = k psi ((y - y0) n_x - (x - x0) n_y), so that tau . n = 0 there
   * (Timoshenko & Goodier 1970, sect. 104, eqs. 148-150). Without a 'value' condition w is held
   * at 0 at the vertex nearest to the twist axis (the problem defines w up to a constant).
   * Section integrals (statistics fe_torque, fe_torsion_energy): the torque per unit length
   * T = int ((x - x0) tau_yz - (y - y0) tau_xz) dA and the strain energy per unit length
   * E = 1/2 int tau . gamma dA, with T psi = 2 E at equilibrium.
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

    /// @brief Whether a twist is given.
    bool
    has_cell_load() const override;

    /// @brief The load of the twist, -sum_q w_q k grad phi_i . gamma_t(x_q) (nothing without a
    /// twist).
    void
    add_cell_load(const dealii::FEValues<dim>     &fe_values,
                  const dealii::types::material_id material_id,
                  const std::vector<double>       &weights,
                  dealii::Vector<double>          &cell_rhs) const override;

    /// @brief The twist axis and its entry, with a twist.
    std::optional<std::pair<dealii::Point<dim>, std::string>>
    held_point() const override;

    /// @brief "torque", "torsion_energy" with a twist.
    std::vector<std::string>
    integral_names() const override;

    /// @brief The integrands of the torque and the strain energy of torsion.
    void
    add_cell_integrals(const dealii::FEValues<dim>     &fe_values,
                       const dealii::types::material_id material_id,
                       const std::vector<double>       &weights,
                       const dealii::Vector<double>    &cell_values,
                       std::vector<double>             &integrals) const override;

    /// @brief The gradient dw_dx, ... and the flux k grad w as flux_x, ...
    std::unique_ptr<dealii::DataPostprocessor<dim>>
    postprocessor() const override;

    /// @brief "coefficient k = ..." and the per-material values.
    std::string
    summary() const override;

    /// @brief The coefficient k of cells with material id @p material_id.
    double
    coefficient(const dealii::types::material_id material_id) const;

    /// @brief The twist of torsion (inactive by default).
    const Torsion &
    torsion() const;

  private:
    double                                       default_coefficient = 1.;
    std::map<dealii::types::material_id, double> coefficients;
    Torsion                                      twist;
  };
} // namespace perideal

#endif
