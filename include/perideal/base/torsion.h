// ---------------------------------------------------------------------
// PeriDeal: Saint-Venant torsion of a prismatic bar: the twist as the load of a warping field.
// ---------------------------------------------------------------------
#ifndef perideal_base_torsion_h
#define perideal_base_torsion_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <string>

namespace perideal
{
  /**
   * @brief The twist of Saint-Venant torsion about an axis parallel to z through (x0, y0):
   * u = -psi z (y - y0), v = psi z (x - x0), w = w(x, y) the warping (Timoshenko & Goodier,
   * Theory of Elasticity, 3rd ed., 1970, sect. 104; seed 000, eqs. 3, 62-67, with the note's
   * corrections T3 and T4). The shear strains are
   *   gamma = grad w + psi (-(y - y0), x - x0) = grad w + twist_strain(x),
   * the stresses tau = (tau_xz, tau_yz) = mu gamma, the traction-free condition tau . n = 0,
   * i.e. mu dw/dn = -mu twist_strain . n on every free face and crack face, the torque per
   * unit length T = int ((x - x0) tau_yz - (y - y0) tau_xz) dA and the strain energy per unit
   * length E = 1/2 int tau . gamma dA; at equilibrium T psi = 2 E (Clapeyron).
   *
   * Parameters (in the subsection of the scalar physics or model that reads them): <Twist per
   * unit length> psi [rad/m] (0: no torsion) and <Twist axis> (x0, y0) [m]. Torsion is a 2D
   * (cross-section) problem: a nonzero twist in 3D is refused.
   */
  class Torsion
  {
  public:
    /**
     * @brief Declare <Twist per unit length> and <Twist axis> in the current subsection.
     */
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /**
     * @brief Read the entries of the current subsection; @p section names it in messages
     * ("Finite elements/scalar laplace"). Throws for a nonzero twist with @p dim = 3.
     */
    void
    parse_parameters(dealii::ParameterHandler &prm,
                     const std::string        &section,
                     const unsigned int        dim);

    /**
     * @brief Whether the twist is nonzero.
     */
    bool
    active() const;

    /**
     * @brief The twist per unit length psi [rad/m].
     */
    double
    twist() const;

    /**
     * @brief The twist axis (x0, y0).
     */
    const dealii::Point<2> &
    axis() const;

    /**
     * @brief The entry of the axis, "<section/Twist axis>", for messages.
     */
    std::string
    axis_entry() const;

    /**
     * @brief Stop, naming the axis entry, unless the axis lies in @p body, the extent in x and y
     * of the whole body (the particles' lattice cells and the FE mesh together): the twist is
     * defined for the whole section, so a region of particles away from the axis is accepted.
     */
    void
    check_axis(const dealii::BoundingBox<2> &body) const;

    /**
     * @brief The shear strain of the rotation of the sections at @p p (first two coordinates):
     * psi (-(y - y0), x - x0), to be added to grad w.
     */
    template <int dim>
    dealii::Tensor<1, dim>
    twist_strain(const dealii::Point<dim> &p) const;

    /**
     * @brief The moment arm of @p tau at @p p: (x - x0) tau_yz - (y - y0) tau_xz, whose
     * integral over the section is the torque per unit length.
     */
    template <int dim>
    double
    torque_density(const dealii::Point<dim> &p, const dealii::Tensor<1, dim> &tau) const;

  private:
    double           psi = 0.;
    dealii::Point<2> center;
    std::string      section;
  };
} // namespace perideal

#endif
