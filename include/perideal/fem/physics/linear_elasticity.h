// ---------------------------------------------------------------------
// PeriDeal: FE physics 'linear elasticity'.
// ---------------------------------------------------------------------
#ifndef perideal_fem_physics_linear_elasticity_h
#define perideal_fem_physics_linear_elasticity_h

#include <deal.II/base/symmetric_tensor.h>

#include <perideal/base/elasticity.h>
#include <perideal/fem/fe_physics.h>

namespace perideal
{
  /**
   * @brief Small-strain linear elasticity: -div sigma = b, sigma = C : eps(u),
   * eps(u) = (grad u + grad u^T) / 2, with the displacement u [m] as unknown (translations x,
   * y(, z)) and C from <Finite elements/Elasticity> (any symmetry class, oriented; in 2D plane
   * stress or plane strain, the problem's <Material/Planar assumption>), or, with <Same material
   * as the particles> = true, from the same entries of the particles' <Material/<Model>> (one
   * material block for both regions). The stiffness is
   * int eps(v) : C : eps(u) dx (e.g. Hughes, The Finite Element Method, 2000, eq. 2.8.17 and
   * Sect. 3.9); conditions: 'displacement' [m], 'velocity' [m/s], 'traction' [Pa] = sigma n.
   * Output: strain_ij, stress_ij [Pa], in 2D stress_zz (0 in plane stress, C_33kl eps_kl in
   * plane strain) and the von Mises stress of the 3D stress.
   *
   * A thermal strain eps_th = alpha Delta T (<Thermal expansion> of the material, isotropic or a
   * tensor in the material axes; doc/theory/thermal_strain_fe.md) makes the stress that of the
   * mechanical strain, sigma = C : (eps(u) - alpha_2D Delta T), with alpha_2D the expansion
   * of the planar assumption (planar_thermal_expansion(): the in-plane block of alpha in plane
   * stress, C_p^-1 (C alpha)_p in plane strain); its load is int eps(v) : C : alpha_2D Delta T
   * (Timoshenko and Goodier, Theory of Elasticity, 3rd ed., 1970, ch. 13; the initial strain of
   * Zienkiewicz, Taylor and Zhu, The Finite Element Method: Its Basis and Fundamentals, 6th ed.,
   * 2005, ch. 2). With a
   * temperature change the output adds temperature_change [K] and mechanical_strain_ij = eps_ij -
   * alpha_ij Delta T (the in-plane block of the 3D alpha), and stress_zz of plane strain is
   * C_33kl eps_kl - (C alpha)_33 Delta T.
   */
  template <int dim>
  class LinearElasticity : public FEPhysics<dim>
  {
  public:
    /// @brief Declare <Elasticity> (@p prm in <Finite elements>).
    void
    declare_parameters(dealii::ParameterHandler &prm) const override;

    /// @brief Read <Elasticity> (or the particles' material) and form C for @p planar.
    void
    parse_parameters(dealii::ParameterHandler &prm, const PlanarAssumption planar) override;

    /// @brief The displacement x, y(, z).
    FieldLayout
    field_layout() const override;

    /// @brief sum_q w_q eps(phi_i) : C : eps(phi_j).
    void
    add_cell_stiffness(const dealii::FEValues<dim>     &fe_values,
                       const dealii::types::material_id material_id,
                       const std::vector<double>       &weights,
                       dealii::FullMatrix<double>      &cell_matrix) const override;

    /// @brief Whether <Thermal expansion> is not zero.
    bool
    has_thermal_strain() const override;

    /// @brief sum_q w_q Delta T_q eps(phi_i) : C : alpha_2D.
    void
    add_cell_thermal_load(const dealii::FEValues<dim>     &fe_values,
                          const dealii::types::material_id material_id,
                          const std::vector<double>       &weights,
                          const std::vector<double>       &delta_T,
                          dealii::Vector<double>          &cell_rhs) const override;

    /**
     * @brief 1/2 Delta T^2 alpha : C : alpha of the 3D body: in 3D and in plane strain the 3D
     * alpha and C (plane strain: with the energy of the held out-of-plane strain, so that a
     * free plate stores 1/2 E alpha^2 Delta T^2 per volume), in plane stress the in-plane block
     * of alpha and the reduced C.
     */
    double
    thermal_energy_density(const dealii::types::material_id material_id,
                           const double                     delta_T) const override;

    void
    cell_thermoelastic_measure(const dealii::FEValues<dim>     &fe_values,
                               const dealii::types::material_id material_id,
                               const dealii::Vector<double>    &cell_values,
                               std::vector<double>             &measure) const override;

    /// @brief (C : alpha_2D) : alpha_2D, the coupling modulus of the planar assumption.
    double
    thermoelastic_coupling_modulus() const override;

    /// @brief Strain, stress, stress_zz (2D) and von Mises stress.
    std::unique_ptr<dealii::DataPostprocessor<dim>>
    postprocessor() const override;

    /// @brief The same from the mechanical strain, with temperature_change and
    /// mechanical_strain_ij.
    std::unique_ptr<dealii::DataPostprocessor<dim>>
    thermal_postprocessor(const PointTemperatureChange<dim> &delta_T) const override;

    /// @brief "material <the elastic material's summary>".
    std::string
    summary() const override;

    /// @brief The elasticity tensor C [Pa] (after parse_parameters()).
    const dealii::SymmetricTensor<4, dim> &
    elasticity_tensor() const;

    /// @brief <Elasticity/Same material as the particles>.
    bool
    shares_particle_material() const override;

  private:
    PlanarAssumption                planar = PlanarAssumption::three_dimensional;
    ElasticMaterial                 material;
    bool                            shared = false;
    dealii::SymmetricTensor<4, dim> C;
    /// The in-plane block of the 3D thermal expansion alpha [1/K] (global axes).
    dealii::SymmetricTensor<2, dim> alpha;
    /// alpha_2D, the expansion of the planar assumption (planar_thermal_expansion(): the free
    /// strain per kelvin in the plane) [1/K].
    dealii::SymmetricTensor<2, dim> planar_alpha;
    /// C : alpha_2D, the stress per kelvin of a held body [Pa/K]; (C alpha)_33 of the 3D
    /// tensors (stress_zz of plane strain).
    dealii::SymmetricTensor<2, dim> thermal_stress;
    double                          thermal_stress_zz = 0.;
    /// alpha : C : alpha [Pa/K^2] of thermal_energy_density().
    double thermal_energy = 0.;
  };
} // namespace perideal

#endif
