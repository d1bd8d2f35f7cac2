// ---------------------------------------------------------------------
// PeriDeal: linear elasticity tensors (isotropic and anisotropic, 2D and 3D).
// ---------------------------------------------------------------------
#ifndef perideal_base_elasticity_h
#define perideal_base_elasticity_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/lac/full_matrix.h>

#include <perideal/base/parameter_utilities.h>
#include <perideal/base/thermal_expansion.h>

#include <string>

namespace perideal
{
  /**
   * @brief How a 2D model represents the third direction.
   */
  enum class PlanarAssumption
  {
    plane_stress,
    plane_strain,
    three_dimensional
  };

  /**
   * @brief The 2D planar assumptions by the names <Material/Planar assumption> accepts ("plane
   * stress", "plane strain").
   */
  const ParameterUtilities::Choices<PlanarAssumption> &
  planar_assumption_names();

  /**
   * @brief The planar assumption named by a value of <Material/Planar assumption>
   * (planar_assumption_names()); three_dimensional when @p dim is 3.
   */
  PlanarAssumption
  planar_assumption_from_name(const std::string &name, const int dim);

  /**
   * @brief Isotropic elasticity tensor for (E, nu) under a planar assumption (plane stress:
   * lambda* = E nu / (1 - nu^2)).
   */
  template <int dim>
  dealii::SymmetricTensor<4, dim>
  isotropic_elasticity_tensor(const double           youngs_modulus,
                              const double           poisson_ratio,
                              const PlanarAssumption planar);

  /**
   * @brief The elasticity tensor of a @p dim dimensional body from the 3D stiffness @p voigt
   * (6 x 6, Voigt order 11, 22, 33, 23, 13, 12, engineering shear strains): in 3D the tensor
   * itself; in 2D plane strain the in-plane block (11, 22, 12); in 2D plane stress the inverse of
   * the in-plane block of the compliance (sigma_33 = sigma_23 = sigma_13 = 0).
   */
  template <int dim>
  dealii::SymmetricTensor<4, dim>
  reduce_elasticity_tensor(const dealii::FullMatrix<double> &voigt, const PlanarAssumption planar);

  /**
   * @brief The 3D stiffness @p voigt (6 x 6 Voigt matrix) of a material whose axes are rotated
   * by the proper rotation @p rotation (columns: the material axes in global coordinates).
   */
  dealii::FullMatrix<double>
  rotate_voigt_stiffness(const dealii::FullMatrix<double> &voigt,
                         const dealii::Tensor<2, 3>       &rotation);

  /**
   * @brief The rotation of z-x-z Euler angles (phi, theta, psi) given in degrees: the material
   * axes are the global ones rotated by phi about z, then by theta about the new x, then by psi
   * about the new z. In 2D only phi (a rotation in the plane) keeps the plane a symmetry plane.
   */
  dealii::Tensor<2, 3>
  rotation_from_euler_angles(const double phi, const double theta, const double psi);

  /**
   * @brief The thermal expansion a @p dim dimensional model reproduces: the strain of a free
   * body per kelvin, for the 3D expansion @p alpha and 3D stiffness @p voigt (Voigt, 6 x 6),
   * both in the global axes, under @p planar. In 3D, alpha. In plane stress, the in-plane block
   * of alpha (the stresses out of the plane vanish). In plane strain (eps_33 = eps_13 = eps_23
   * = 0), C_p^-1 (C alpha)_p with C_p the in-plane block of the stiffness and (C alpha)_p the
   * in-plane part of the 3D thermal stress: (1 + nu) alpha for an isotropic material. The
   * in-plane thermal stress is then C_2D : alpha_2D for the reduced tensor C_2D of
   * reduce_elasticity_tensor().
   */
  template <int dim>
  dealii::SymmetricTensor<2, dim>
  planar_thermal_expansion(const dealii::SymmetricTensor<2, 3> &alpha,
                           const dealii::FullMatrix<double>    &voigt,
                           const PlanarAssumption               planar);
  /**
   * @brief An elastic material read from a parameter section: the symmetry class, its
   * constants and the orientation of its axes.
   *
   * Symmetry classes and their entries (material axes 1, 2, 3):
   * - isotropic: Young's modulus E, Poisson's ratio nu;
   * - cubic: C11, C12, C44;
   * - transversely isotropic (axis 3 normal to the plane of isotropy): E1, E3, nu12, nu13, G13
   *   (E2 = E1, nu23 = nu13, G23 = G13, G12 = E1 / (2 (1 + nu12)));
   * - orthotropic: E1, E2, E3, nu12, nu13, nu23, G12, G13, G23;
   * - general: the 21 stiffness constants C_IJ, I <= J, Voigt order, row by row.
   * Engineering convention: nu_ij = -eps_j / eps_i under uniaxial stress along i, so
   * S_ij = -nu_ij / E_i.
   */
  class ElasticMaterial
  {
  public:
    /**
     * @brief Declare the entries in the current subsection.
     */
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /**
     * @brief Read and check the entries of the current subsection, whose path @p section (e.g.
     * "Finite elements/Elasticity") is used in error messages.
     */
    void
    parse_parameters(dealii::ParameterHandler &prm, const std::string &section);

    /**
     * @brief The 3D stiffness in the global axes (Voigt, 6 x 6).
     */
    const dealii::FullMatrix<double> &
    voigt_stiffness() const;

    /**
     * @brief The material axes in the global ones: column a is axis a + 1 (the rotation of
     * the Orientation entry; the identity without one).
     */
    const dealii::Tensor<2, 3> &
    axes() const;

    /**
     * @brief The same material with its axes rotated by @p rotation about the global axes
     * (axes() becomes @p rotation times axes()); a grain of a polycrystal.
     */
    ElasticMaterial
    rotated(const dealii::Tensor<2, 3> &rotation) const;

    /**
     * @brief The elasticity tensor of a @p dim dimensional body under @p planar.
     */
    template <int dim>
    dealii::SymmetricTensor<4, dim>
    tensor(const PlanarAssumption planar) const;

    /**
     * @brief Whether the symmetry class is isotropic; then E and nu are available.
     */
    bool
    is_isotropic() const;
    /// @brief Young's modulus E [Pa] and Poisson's ratio nu of an isotropic material.
    ///@{
    double
    youngs_modulus() const;
    double
    poisson_ratio() const;
    ///@}

    /**
     * @brief The thermal expansion alpha [1/K] in the global axes (<Thermal expansion>, in the
     * material axes: ThermalExpansion); zero for none.
     */
    dealii::SymmetricTensor<2, 3>
    thermal_expansion() const;

    /**
     * @brief The thermal expansion as read (ThermalExpansion: isotropic or not, its summary).
     */
    const ThermalExpansion &
    thermal_expansion_entry() const;

    /**
     * @brief One line describing the material, for the log.
     */
    std::string
    summary() const;

    /// The symmetry classes of <Symmetry>.
    enum class Symmetry
    {
      isotropic,
      cubic,
      transversely_isotropic,
      orthotropic,
      general
    };

  private:
    Symmetry                   symmetry = Symmetry::isotropic;
    double                     E = 0., nu = 0.;
    dealii::FullMatrix<double> stiffness;
    dealii::Tensor<2, 3>       rotation;
    ThermalExpansion           expansion;
  };
} // namespace perideal

#endif
