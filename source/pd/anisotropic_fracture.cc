// ---------------------------------------------------------------------
// PeriDeal: fracture energies along the material axes of the anisotropic bond-based model.
// ---------------------------------------------------------------------
#include <deal.II/base/numbers.h>

#include <perideal/base/parameter_utilities.h>
#include <perideal/pd/anisotropic_fracture.h>

#include <cmath>
#include <sstream>

namespace perideal
{
  using namespace dealii;

  template <int dim>
  void
  AnisotropicFractureEnergy<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry(
      "Fracture energy ratios",
      "1, 1, 1",
      Patterns::List(Patterns::Double(), 3, 3),
      "r1, r2, r3: the fracture energy of a crack whose normal is material axis a (after the "
      "Orientation) is r_a times the damage model's Fracture energy (or the energy of its "
      "Critical stretch). A bond's critical energy is interpolated between the axes as "
      "g(n) = sum_a g_a (n . t_a)^2, the g_a fitted so that the ratios hold (on the lattice "
      "with the discrete calibration, in the continuum otherwise); every g_a must be positive: "
      "in 2D 1/2 < r_b/r_a < 2 for the two material axes a, b in the plane (continuum; the "
      "third axis must then be normal to the plane, its ratio is not used), in 3D "
      "4 r_a > r1 + r2 + r3. 1, 1, 1: isotropic fracture energy.");
  }

  template <int dim>
  void
  AnisotropicFractureEnergy<dim>::parse_parameters(ParameterHandler  &prm,
                                                   const std::string &section_path)
  {
    section = section_path;
    const auto values =
      Utilities::string_to_double(Utilities::split_string_list(prm.get("Fracture energy ratios")));
    for (unsigned int a = 0; a < 3; ++a)
      {
        AssertThrow(values[a] > 0.,
                    ExcMessage("<" + section +
                               "/Fracture energy ratios> = " + prm.get("Fracture energy ratios") +
                               ": every ratio must be positive; accepted: three positive "
                               "numbers r1, r2, r3 (1, 1, 1 for isotropic fracture energy)."));
        ratios[a] = values[a];
      }
  }

  template <int dim>
  bool
  AnisotropicFractureEnergy<dim>::is_anisotropic() const
  {
    return ratios[0] != ratios[1] || ratios[0] != ratios[2];
  }

  template <int dim>
  void
  AnisotropicFractureEnergy<dim>::calibrate(const Tensor<2, 3>                          &axes,
                                            const anisotropic_micromodulus::Family<dim> &family,
                                            const bool                                   discrete)
  {
    // The axes of the body's space: all three in 3D; in 2D those in the plane (with unequal
    // ratios one axis must be normal to it, or the ratios would not be those of in-plane
    // crack normals).
    unsigned int n_found = 0;
    for (unsigned int a = 0; a < 3 && n_found < dim; ++a)
      {
        if (dim == 2 && std::abs(axes[2][a]) > 1e-12)
          continue;
        for (unsigned int d = 0; d < dim; ++d)
          axes_in_body[n_found][d] = axes[d][a];
        ratio_in_body[n_found] = ratios[a];
        axis_number[n_found]   = a + 1;
        ++n_found;
      }
    if (n_found < dim)
      {
        AssertThrow(!is_anisotropic(),
                    ExcMessage("<" + section +
                               "/Fracture energy ratios> differ, but no two material axes lie in "
                               "the plane of the 2D body (Orientation tilts them); accepted: an "
                               "Orientation that keeps one material axis along z (theta = 0 or "
                               "90, psi = 0 or 90), or equal ratios."));
        for (unsigned int a = 0; a < dim; ++a)
          {
            axes_in_body[a]    = Tensor<1, dim>();
            axes_in_body[a][a] = 1.;
            ratio_in_body[a]   = ratios[0];
            axis_number[a]     = a + 1;
          }
      }

    // A_ba = crossing moment of crack normal t_b with the weight (n . t_a)^2, rows normalized
    // by the isotropic sum (g = 1), so that A g = r asks G(t_b) / G_iso(t_b) = r_b.
    Tensor<2, dim> A;
    for (unsigned int b = 0; b < dim; ++b)
      if (discrete)
        {
          double row = 0.;
          for (unsigned int k = 0; k < family.xi.size(); ++k)
            {
              const double crossing = family.xi[k] * axes_in_body[b];
              if (crossing <= 0.)
                continue;
              // The bond's critical energy is proportional to w |xi| g(n).
              const double         length = family.xi[k].norm();
              const Tensor<1, dim> n      = family.xi[k] / length;
              for (unsigned int a = 0; a < dim; ++a)
                A[b][a] += crossing * family.weight[k] * length * std::pow(n * axes_in_body[a], 2);
              row += crossing * family.weight[k] * length;
            }
          A[b] /= row;
        }
      else
        for (unsigned int a = 0; a < dim; ++a)
          A[b][a] = dim == 2 ? (a == b ? 2. / 3. : 1. / 3.) : (a == b ? 1. / 2. : 1. / 4.);
    Tensor<1, dim> r;
    for (unsigned int a = 0; a < dim; ++a)
      r[a] = ratio_in_body[a];
    const Tensor<1, dim> solution = invert(A) * r;
    std::ostringstream   g_list;
    bool                 positive = true;
    for (unsigned int a = 0; a < dim; ++a)
      {
        g[a] = solution[a];
        g_list << (a > 0 ? ", " : "") << ParameterUtilities::format_number(g[a]);
        positive = positive && g[a] > 0.;
      }
    AssertThrow(positive,
                ExcMessage("<" + section + "/Fracture energy ratios> = " +
                           ParameterUtilities::format_number(ratios[0]) + ", " +
                           ParameterUtilities::format_number(ratios[1]) + ", " +
                           ParameterUtilities::format_number(ratios[2]) +
                           " need the bond weights g = (" + g_list.str() +
                           ") along the material axes, and a weight that is not positive makes "
                           "bonds of that direction break without energy; accepted: " +
                           (dim == 2 ? "1/2 < r" + std::to_string(axis_number[1]) + "/r" +
                                         std::to_string(axis_number[0]) +
                                         " < 2 for the two material axes in the plane (" +
                                         std::to_string(axis_number[0]) + " and " +
                                         std::to_string(axis_number[1]) + ")" :
                                       std::string("4 r_a > r1 + r2 + r3 for every axis a")) +
                           " (the continuum bound; the lattice's is close). A stronger "
                           "contrast needs weak interfaces between regions, not a smooth bond "
                           "law."));
  }

  template <int dim>
  double
  AnisotropicFractureEnergy<dim>::weight(const Tensor<1, dim> &n) const
  {
    if (!is_anisotropic())
      return 1.;
    double sum = 0.;
    for (unsigned int a = 0; a < dim; ++a)
      sum += g[a] * std::pow(n * axes_in_body[a], 2);
    return sum;
  }

  template <int dim>
  double
  AnisotropicFractureEnergy<dim>::crack_energy_ratio(
    const anisotropic_micromodulus::Family<dim> &family,
    const Tensor<1, dim>                        &m) const
  {
    double weighted = 0., isotropic = 0.;
    for (unsigned int k = 0; k < family.xi.size(); ++k)
      {
        const double crossing = family.xi[k] * m;
        if (crossing <= 0.)
          continue;
        const double length = family.xi[k].norm();
        weighted += crossing * family.weight[k] * length * weight(family.xi[k] / length);
        isotropic += crossing * family.weight[k] * length;
      }
    return weighted / isotropic;
  }

  template <int dim>
  std::string
  AnisotropicFractureEnergy<dim>::summary(const anisotropic_micromodulus::Family<dim> &family) const
  {
    if (!is_anisotropic())
      return "";
    std::ostringstream out;
    out << "fracture energy ratios " << ratios[0] << ", " << ratios[1] << ", " << ratios[2]
        << " (material axes); bond weights g =";
    for (unsigned int a = 0; a < dim; ++a)
      out << " " << g[a];
    out << " (material axes";
    for (unsigned int a = 0; a < dim; ++a)
      out << " " << axis_number[a];
    out << "); lattice G(m)/G_iso(m), m at the angle from material axis " << axis_number[0]
        << " towards " << axis_number[1] << ":";
    for (unsigned int step = 0; step <= 6; ++step)
      {
        const double   angle = step * numbers::PI / 12.;
        Tensor<1, dim> m = std::cos(angle) * axes_in_body[0] + std::sin(angle) * axes_in_body[1];
        out << " " << 15 * step << ": " << crack_energy_ratio(family, m) << ";";
      }
    return out.str();
  }

  template class AnisotropicFractureEnergy<2>;
  template class AnisotropicFractureEnergy<3>;
} // namespace perideal
