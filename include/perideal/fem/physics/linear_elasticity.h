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

    /// @brief Strain, stress, stress_zz (2D) and von Mises stress.
    std::unique_ptr<dealii::DataPostprocessor<dim>>
    postprocessor() const override;

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
  };
} // namespace perideal

#endif
