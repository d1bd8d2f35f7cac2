// ---------------------------------------------------------------------
// PeriDeal: fracture energies given along the material axes of the anisotropic bond-based
// model, interpolated over the bond directions.
// ---------------------------------------------------------------------
#ifndef perideal_pd_anisotropic_fracture_h
#define perideal_pd_anisotropic_fracture_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>

#include <perideal/pd/anisotropic_micromodulus.h>

#include <array>
#include <string>
#include <vector>

namespace perideal
{
  /**
   * @brief The direction dependence of the bonds' critical energy that makes the fracture
   * energy of a crack whose normal is material axis a equal r_a G0 (G0 the damage model's
   * fracture energy, r_a the entry <Fracture energy ratios>).
   *
   * A bond of direction n breaks when its energy reaches g(n) times the isotropic model's
   * (equal for every direction), with the quadratic interpolation between the axes
   *   g(n) = sum_a g_a (n . t_a)^2,
   * t_a the material axes in the body's dimension (in 2D the two axes in the plane). The
   * energy of a crack with normal m is the critical energy of the bonds that cross it,
   * G(m) ~ sum_{xi . m > 0} (xi . m) w_b |xi_b| g(n_b) (w_b = chi V_j of one family; a bond's
   * critical energy k s0(n)^2 |xi| / 2 is proportional to w_b |xi_b| g(n_b)), linear in g:
   * G(t_b) = sum_a A_ba g_a. The g_a
   * solve A g = r (A 1) component-wise, so that G(t_b) / G_isotropic(t_b) = r_b:
   * - "discrete" calibration: A from the bonds of an interior family (exact on the lattice);
   * - "continuum": A from the integrals over the ball, A_bb = 2/3 and A_ba = 1/3 in 2D
   *   (g_b = 2 r_b - r_other), A_bb = 1/2 and A_ba = 1/4 in 3D (g_b = 4 r_b - sum r).
   * Every g_a must be positive (a direction whose bonds break without energy would make the
   * crack free): in the continuum 1/2 < r_2/r_1 < 2 in 2D, 4 r_b > r_1 + r_2 + r_3 in 3D; a
   * stronger contrast needs weak interfaces, not a smooth bond law. Between the axes G(m) is
   * what the interpolation gives (reported for a few directions in the summary).
   */
  template <int dim>
  class AnisotropicFractureEnergy
  {
  public:
    /**
     * @brief Declare <Fracture energy ratios> in the current subsection.
     */
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /**
     * @brief Read the ratios of the current subsection, whose path @p section names them in
     * errors (count and sign; the range needs the axes and the calibration: calibrate()).
     */
    void
    parse_parameters(dealii::ParameterHandler &prm, const std::string &section);

    /**
     * @brief Find the g_a for the material @p axes (columns, global coordinates) over
     * @p family (an interior family; used by the discrete calibration and the report), with
     * the lattice's (@p discrete) or the continuum's crossing moments. Throws, naming the
     * entry and the accepted range, if a g_a is not positive or, in 2D with unequal ratios,
     * no material axis is normal to the plane.
     */
    void
    calibrate(const dealii::Tensor<2, 3>                  &axes,
              const anisotropic_micromodulus::Family<dim> &family,
              const bool                                   discrete);

    /**
     * @brief g(n) for the unit vector @p n (1 for equal ratios).
     */
    double
    weight(const dealii::Tensor<1, dim> &n) const;

    /**
     * @brief Whether the ratios differ (otherwise g = 1 and nothing is reported).
     */
    bool
    is_anisotropic() const;

    /**
     * @brief The fracture energy of a crack with unit normal @p m relative to the isotropic
     * one, G(m) / G_isotropic(m), on the lattice of @p family: sum (xi . m) w |xi| g(n) over
     * the bonds with xi . m > 0, divided by the same sum with g = 1.
     */
    double
    crack_energy_ratio(const anisotropic_micromodulus::Family<dim> &family,
                       const dealii::Tensor<1, dim>                &m) const;

    /**
     * @brief The ratios, the g_a and the lattice's G(m)/G_isotropic(m) along the axes and at
     * 15 degree steps between the first two (one line; empty for equal ratios).
     */
    std::string
    summary(const anisotropic_micromodulus::Family<dim> &family) const;

  private:
    std::string                             section;
    std::array<double, 3>                   ratios{{1., 1., 1.}};
    std::array<dealii::Tensor<1, dim>, dim> axes_in_body;
    std::array<double, dim>                 ratio_in_body{};
    /// The material axis (1, 2, 3) of each axis in the body.
    std::array<unsigned int, dim> axis_number{};
    std::array<double, dim>       g{};
  };
} // namespace perideal

#endif
