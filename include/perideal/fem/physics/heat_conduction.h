// ---------------------------------------------------------------------
// PeriDeal: FE physics 'heat'.
// ---------------------------------------------------------------------
#ifndef perideal_fem_physics_heat_conduction_h
#define perideal_fem_physics_heat_conduction_h

#include <deal.II/base/tensor.h>

#include <perideal/fem/fe_physics.h>

#include <array>

namespace perideal
{
  /**
   * @brief Transient heat conduction, rho c dT/dt - div(K grad T) = q, with the temperature
   * T [K] as unknown (FieldLayout::temperature(), one component "T", first order in time):
   * Fourier's law q_flux = -K grad T with a conductivity tensor K [W/(m K)], isotropic
   * (K = k I) or orthotropic in material axes (K = R diag(k1, k2, k3) R^T, R the rotation of the
   * z-x-z Euler angles of <Orientation>, the convention of the elastic materials; a 2D problem
   * takes the in-plane block of K: a plate whose temperature does not vary through the
   * thickness). The stiffness is int grad v . K grad T dx, the lumped "mass" of the FE region the
   * heat capacity rho c (rho = <Finite elements/Density>, c = <Specific heat>), the source q
   * [W/m^3] the problem's body force (its one expression), in 2D times the thickness like every
   * load (Hughes, The Finite Element Method, 2000, Sect. 1.4 and 8.1; Lewis, Nithiarasu &
   * Seetharamu, Fundamentals of the Finite Element Method for Heat and Fluid Flow, 2004,
   * eqs. 3.12 and 6.4).
   *
   * Parameters (<Finite elements/heat>): <Symmetry> (isotropic | orthotropic),
   * <Conductivity> k (isotropic), <Conductivities> k1, k2, k3 (orthotropic),
   * <Orientation> (phi, theta, psi) [degrees], <Specific heat> c [J/(kg K)].
   * Conditions: 'value' (the temperature [K]), 'flux' (the heat flux into the body [W/m^2],
   * -q_flux . n), 'convection' (h (T_inf - T), a Robin condition, in the FE region's conditions).
   * Output: T and the heat flux -K grad T as heat_flux_x, heat_flux_y(, heat_flux_z) [W/m^2].
   */
  template <int dim>
  class HeatConduction : public FEPhysics<dim>
  {
  public:
    /// @brief The closed choices of <Symmetry>.
    enum class Symmetry
    {
      isotropic,
      orthotropic
    };

    /// @brief Declare <heat> (@p prm in <Finite elements>).
    void
    declare_parameters(dealii::ParameterHandler &prm) const override;

    /// @brief Read and check <heat> (conductivities and specific heat > 0) and form K.
    void
    parse_parameters(dealii::ParameterHandler &prm, const PlanarAssumption planar) override;

    /// @brief The temperature "T".
    FieldLayout
    field_layout() const override;

    /// @brief sum_q w_q grad phi_i . K grad phi_j.
    void
    add_cell_stiffness(const dealii::FEValues<dim>     &fe_values,
                       const dealii::types::material_id material_id,
                       const std::vector<double>       &weights,
                       dealii::FullMatrix<double>      &cell_matrix) const override;

    /// @brief The specific heat c: the lumped mass is the heat capacity rho c.
    double
    mass_factor() const override;

    /// @brief The heat flux -K grad T as heat_flux_x, ...
    std::unique_ptr<dealii::DataPostprocessor<dim>>
    postprocessor() const override;

    /// @brief "heat conduction, k = ..., c = ..." (the conductivities and orientation if
    /// orthotropic).
    std::string
    summary() const override;

    /// @brief The conductivity tensor K [W/(m K)] in the global axes.
    const dealii::Tensor<2, dim> &
    conductivity() const;

  private:
    Symmetry               symmetry = Symmetry::isotropic;
    std::array<double, 3>  principal{{1., 1., 1.}};
    std::array<double, 3>  orientation{{0., 0., 0.}};
    double                 specific_heat = 1.;
    dealii::Tensor<2, dim> K;
  };
} // namespace perideal

#endif
