// ---------------------------------------------------------------------
// PeriDeal: Saint-Venant torsion of a prismatic bar: the twist as the load of a warping field.
// ---------------------------------------------------------------------
#include <perideal/base/parameter_utilities.h>
#include <perideal/base/torsion.h>

namespace perideal
{
  using namespace dealii;

  void
  Torsion::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Twist per unit length",
                      "0",
                      Patterns::Double(),
                      "Saint-Venant torsion: the twist per unit length psi [rad/m] of the bar "
                      "(axis along z); the field w is then the warping, loaded by the rotation "
                      "of the sections (traction-free faces: k dw/dn = k psi ((y - y0) n_x - "
                      "(x - x0) n_y)). 0: no torsion. 2D only.");
    prm.declare_entry("Twist axis",
                      "0, 0",
                      Patterns::Anything(),
                      "The point (x0, y0) [m] of the section the sections rotate about (inside "
                      "the section). It changes the warping by a linear function, not the "
                      "stresses nor the torque.");
  }

  void
  Torsion::parse_parameters(ParameterHandler  &prm,
                            const std::string &section_name,
                            const unsigned int dim)
  {
    section = section_name;
    psi     = prm.get_double("Twist per unit length");
    center  = ParameterUtilities::parse_point<2>(prm.get("Twist axis"), axis_entry());
    AssertThrow(psi == 0. || dim == 2,
                ExcMessage("The parameter <" + section + "/Twist per unit length> is " +
                           ParameterUtilities::format_number(psi) +
                           " in a 3D problem; torsion is a problem of the cross-section: set "
                           "<Dimension> = 2, or the twist to 0."));
  }

  bool
  Torsion::active() const
  {
    return psi != 0.;
  }

  double
  Torsion::twist() const
  {
    return psi;
  }

  const Point<2> &
  Torsion::axis() const
  {
    return center;
  }

  std::string
  Torsion::axis_entry() const
  {
    return "<" + section + "/Twist axis>";
  }

  void
  Torsion::check_axis(const BoundingBox<2> &body) const
  {
    for (unsigned int d = 0; d < 2; ++d)
      {
        const char  *name = d == 0 ? "x" : "y";
        const double low = body.lower_bound(d), high = body.upper_bound(d);
        AssertThrow(center[d] >= low && center[d] <= high,
                    ExcMessage("The parameter " + axis_entry() + " has " + name + " = " +
                               ParameterUtilities::format_number(center[d]) +
                               ", outside the section (" + name + " in [" +
                               ParameterUtilities::format_number(low) + ", " +
                               ParameterUtilities::format_number(high) +
                               "]); accepted are points of the section (the twist axis must "
                               "pierce the bar's cross-section)."));
      }
  }

  template <int dim>
  Tensor<1, dim>
  Torsion::twist_strain(const Point<dim> &p) const
  {
    Tensor<1, dim> gamma;
    gamma[0] = -psi * (p[1] - center[1]);
    gamma[1] = psi * (p[0] - center[0]);
    return gamma;
  }

  template <int dim>
  double
  Torsion::torque_density(const Point<dim> &p, const Tensor<1, dim> &tau) const
  {
    return (p[0] - center[0]) * tau[1] - (p[1] - center[1]) * tau[0];
  }

  template Tensor<1, 2>
  Torsion::twist_strain(const Point<2> &) const;
  template Tensor<1, 3>
  Torsion::twist_strain(const Point<3> &) const;
  template double
  Torsion::torque_density(const Point<2> &, const Tensor<1, 2> &) const;
  template double
  Torsion::torque_density(const Point<3> &, const Tensor<1, 3> &) const;
} // namespace perideal
