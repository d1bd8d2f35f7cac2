// ---------------------------------------------------------------------
// PeriDeal: the thermal expansion of a material (isotropic or a tensor in its axes).
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>
#include <deal.II/lac/vector.h>

#include <perideal/base/elasticity.h>
#include <perideal/base/parameter_utilities.h>
#include <perideal/base/thermal_expansion.h>

#include <array>
#include <cmath>
#include <sstream>

namespace perideal
{
  using namespace dealii;

  void
  ThermalExpansion::declare_parameters(ParameterHandler &prm, const bool tensor)
  {
    prm.declare_entry(
      "Thermal expansion",
      "0",
      Patterns::List(Patterns::Double(), 1, tensor ? 9 : 1),
      tensor ?
        "The thermal expansion alpha [1/K], the free strain per kelvin alpha (T - T_ref) "
        "(<Temperature> gives T and T_ref): one value (isotropic), three (alpha_1, alpha_2, "
        "alpha_3 along the material axes) or nine (the symmetric tensor in the material axes, "
        "row by row). 0: no thermal strain." :
        "The thermal expansion alpha [1/K], the free strain per kelvin alpha (T - T_ref) "
        "(<Temperature> gives T and T_ref): one value (the model is isotropic). 0: no thermal "
        "strain.");
  }

  void
  ThermalExpansion::parse_parameters(ParameterHandler  &prm,
                                     const std::string &section,
                                     const bool         tensor)
  {
    const std::string   entry = "<" + section + "/Thermal expansion>";
    std::vector<double> values;
    for (const auto &v : Utilities::split_string_list(prm.get("Thermal expansion"), ','))
      values.push_back(Utilities::string_to_double(v));
    AssertThrow(values.size() == 1 || (tensor && (values.size() == 3 || values.size() == 9)),
                ExcMessage("The parameter " + entry + " has " + std::to_string(values.size()) +
                           " values; accepted: " +
                           (tensor ? "one (isotropic), three (alpha_1, alpha_2, alpha_3 along "
                                     "the material axes) or nine (the symmetric tensor in the "
                                     "material axes, row by row)." :
                                     "one value (the model is isotropic; an anisotropic "
                                     "expansion needs a model with material axes, e.g. "
                                     "anisotropic bond based).")));
    alpha = 0.;
    if (values.size() == 1)
      alpha = values[0] * unit_symmetric_tensor<3>();
    else if (values.size() == 3)
      for (unsigned int a = 0; a < 3; ++a)
        alpha[a][a] = values[a];
    else
      {
        double largest = 0.;
        for (const double v : values)
          largest = std::max(largest, std::abs(v));
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = i + 1; j < 3; ++j)
            AssertThrow(std::abs(values[3 * i + j] - values[3 * j + i]) <= 1e-12 * largest,
                        ExcMessage("The tensor of " + entry + " is not symmetric: entry (" +
                                   std::to_string(i + 1) + ", " + std::to_string(j + 1) + ") is " +
                                   ParameterUtilities::format_number(values[3 * i + j]) +
                                   ", entry (" + std::to_string(j + 1) + ", " +
                                   std::to_string(i + 1) + ") is " +
                                   ParameterUtilities::format_number(values[3 * j + i]) +
                                   "; accepted: a symmetric tensor (a thermal strain is a "
                                   "strain)."));
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = i; j < 3; ++j)
            alpha[i][j] = values[3 * i + j];
      }
  }

  bool
  ThermalExpansion::is_zero() const
  {
    return alpha.norm() == 0.;
  }

  bool
  ThermalExpansion::is_isotropic() const
  {
    return (alpha - alpha[0][0] * unit_symmetric_tensor<3>()).norm() == 0.;
  }

  double
  ThermalExpansion::coefficient() const
  {
    Assert(is_isotropic(), ExcMessage("The thermal expansion is not isotropic."));
    return alpha[0][0];
  }

  SymmetricTensor<2, 3>
  ThermalExpansion::tensor(const Tensor<2, 3> &axes) const
  {
    // alpha_global = R alpha R^T, R's columns the material axes.
    return symmetrize(axes * Tensor<2, 3>(alpha) * transpose(axes));
  }

  SymmetricTensor<2, 3>
  ThermalExpansion::tensor() const
  {
    return alpha;
  }

  std::string
  ThermalExpansion::summary() const
  {
    std::ostringstream out;
    if (is_isotropic())
      out << "alpha = " << alpha[0][0] << " 1/K";
    else
      {
        const auto values = eigenvalues(alpha);
        out << "alpha principal values " << values[0] << ", " << values[1] << ", " << values[2]
            << " 1/K (material axes)";
      }
    return out.str();
  }

  template <int dim>
  SymmetricTensor<2, dim>
  planar_thermal_expansion(const SymmetricTensor<2, 3> &alpha,
                           const FullMatrix<double>    &voigt,
                           const PlanarAssumption       planar)
  {
    SymmetricTensor<2, dim> result;
    if (dim == 3 || planar == PlanarAssumption::plane_stress)
      {
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = i; j < dim; ++j)
            result[i][j] = alpha[i][j];
        return result;
      }
    AssertThrow(planar == PlanarAssumption::plane_strain,
                ExcMessage("A 2D thermal expansion needs plane stress or plane strain."));
    // Voigt strains 11 22 33 23 13 12 with engineering shears 2 alpha_ij.
    const std::array<double, 6>       strain   = {{alpha[0][0],
                                                   alpha[1][1],
                                                   alpha[2][2],
                                                   2. * alpha[1][2],
                                                   2. * alpha[0][2],
                                                   2. * alpha[0][1]}};
    const std::array<unsigned int, 3> in_plane = {{0, 1, 5}};
    FullMatrix<double>                block(3, 3), inverse(3, 3);
    Vector<double>                    stress(3), planar_strain(3);
    for (unsigned int a = 0; a < 3; ++a)
      {
        for (unsigned int b = 0; b < 3; ++b)
          block(a, b) = voigt(in_plane[a], in_plane[b]);
        for (unsigned int J = 0; J < 6; ++J)
          stress[a] += voigt(in_plane[a], J) * strain[J];
      }
    inverse.invert(block);
    inverse.vmult(planar_strain, stress);
    result[0][0] = planar_strain[0];
    result[1][1] = planar_strain[1];
    result[0][1] = planar_strain[2] / 2.;
    return result;
  }

  template SymmetricTensor<2, 2>
  planar_thermal_expansion<2>(const SymmetricTensor<2, 3> &,
                              const FullMatrix<double> &,
                              const PlanarAssumption);
  template SymmetricTensor<2, 3>
  planar_thermal_expansion<3>(const SymmetricTensor<2, 3> &,
                              const FullMatrix<double> &,
                              const PlanarAssumption);
} // namespace perideal
