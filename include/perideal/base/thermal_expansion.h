// ---------------------------------------------------------------------
// PeriDeal: the thermal expansion of a material (isotropic or a tensor in its axes).
// ---------------------------------------------------------------------
#ifndef perideal_base_thermal_expansion_h
#define perideal_base_thermal_expansion_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <string>

namespace perideal
{
  /**
   * @brief The thermal expansion alpha of a material, read from the entry <Thermal expansion>
   * of its parameter section (doc/theory/thermal_strain.md): the free strain per kelvin,
   * eps_th = alpha (T - T_ref).
   *
   * The entry takes one value (isotropic: alpha I), three (alpha_1, alpha_2, alpha_3 along the
   * material axes: orthotropic) or nine (the tensor in the material axes, row by row; it must be
   * symmetric). 0, the default, is no thermal strain. A section that holds the elastic
   * constants of an isotropic model takes one value only (declare_parameters(prm, false)).
   */
  class ThermalExpansion
  {
  public:
    /**
     * @brief Declare <Thermal expansion> in the current subsection; @p tensor: whether it
     * takes the 3 and 9 values of an anisotropic material (in the axes of the section's
     * Orientation) or one value only.
     */
    static void
    declare_parameters(dealii::ParameterHandler &prm, const bool tensor);

    /**
     * @brief Read and check the entry of the current subsection, whose path @p section (e.g.
     * "Material/bond based") names it in error messages: one value, or (with @p tensor) three
     * or nine, a symmetric tensor; any other count or an asymmetric tensor is refused, naming
     * the entry and the accepted values.
     */
    void
    parse_parameters(dealii::ParameterHandler &prm, const std::string &section, const bool tensor);

    /**
     * @brief Whether alpha is zero (no thermal strain).
     */
    bool
    is_zero() const;

    /**
     * @brief Whether alpha is isotropic (alpha I; zero included).
     */
    bool
    is_isotropic() const;

    /**
     * @brief The isotropic coefficient alpha [1/K] (is_isotropic()).
     */
    double
    coefficient() const;

    /**
     * @brief The tensor alpha [1/K] in the global axes, for material axes @p axes (column a is
     * axis a + 1, ElasticMaterial::axes()).
     */
    dealii::SymmetricTensor<2, 3>
    tensor(const dealii::Tensor<2, 3> &axes) const;

    /**
     * @brief The tensor alpha [1/K] of a material whose axes are the global ones.
     */
    dealii::SymmetricTensor<2, 3>
    tensor() const;

    /**
     * @brief One line for the log ("alpha = 7.5e-06 1/K" or the tensor's principal values).
     */
    std::string
    summary() const;

  private:
    dealii::SymmetricTensor<2, 3> alpha;
  };

} // namespace perideal

#endif
