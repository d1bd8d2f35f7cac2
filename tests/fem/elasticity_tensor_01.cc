// ---------------------------------------------------------------------
// Elasticity tensors of the symmetry classes: each class reduces to the isotropic tensor when
// its constants are isotropic; rotations leave an isotropic material unchanged and turn a cubic
// one as the closed form says; plane stress gives back the engineering compliance; the general
// 21-constant input reproduces the matrix it was given; bad constants are refused.
// ---------------------------------------------------------------------
#include <deal.II/base/parameter_handler.h>

#include <perideal/base/elasticity.h>

#include <cmath>
#include <iostream>
#include <sstream>
#include <string>

#include <tests.h>

using namespace dealii;
using perideal::ElasticMaterial;
using perideal::PlanarAssumption;

namespace
{
  ElasticMaterial
  make(const std::string &settings)
  {
    ParameterHandler prm;
    ElasticMaterial::declare_parameters(prm);
    prm.parse_input_from_string(settings);
    ElasticMaterial material;
    material.parse_parameters(prm, "Elasticity");
    return material;
  }

  template <int dim>
  double
  difference(const SymmetricTensor<4, dim> &a, const SymmetricTensor<4, dim> &b)
  {
    return (a - b).norm() / b.norm();
  }

  void
  report(const std::string &what, const double value, const double tolerance)
  {
    std::cout << what << ": " << (std::abs(value) <= tolerance ? "ok" : "FAILED") << std::endl;
  }
} // namespace

int
main()
{
  const double      E = 200e9, nu = 0.3, G = E / (2. * (1. + nu));
  const std::string E3 = std::to_string(E) + ", " + std::to_string(E) + ", " + std::to_string(E);
  const std::string G3 = std::to_string(G) + ", " + std::to_string(G) + ", " + std::to_string(G);
  const std::string isotropic = "set Young's modulus = 200e9\nset Poisson's ratio = 0.3\n";

  // Isotropic: the same tensor as the closed form (lambda, mu) in 3D, plane strain, plane stress.
  for (const auto planar : {PlanarAssumption::plane_strain, PlanarAssumption::plane_stress})
    report(std::string("isotropic 2D ") +
             (planar == PlanarAssumption::plane_stress ? "plane stress" : "plane strain"),
           difference(make(isotropic).tensor<2>(planar),
                      perideal::isotropic_elasticity_tensor<2>(E, nu, planar)),
           1e-14);
  const auto C3 =
    perideal::isotropic_elasticity_tensor<3>(E, nu, PlanarAssumption::three_dimensional);
  report("isotropic 3D",
         difference(make(isotropic).tensor<3>(PlanarAssumption::three_dimensional), C3),
         1e-14);

  // Orthotropic and transversely isotropic with isotropic constants.
  report("orthotropic with isotropic constants",
         difference(make("set Symmetry = orthotropic\nset Young's moduli = " + E3 +
                         "\nset Poisson's ratios = 0.3, 0.3, 0.3\nset Shear moduli = " + G3 + "\n")
                      .tensor<3>(PlanarAssumption::three_dimensional),
                    C3),
         1e-14);
  report("transversely isotropic with isotropic constants",
         difference(
           make("set Symmetry = transversely isotropic\nset Young's moduli = " + std::to_string(E) +
                ", " + std::to_string(E) +
                "\nset Poisson's ratios = 0.3, 0.3\nset Shear moduli = " + std::to_string(G) + "\n")
             .tensor<3>(PlanarAssumption::three_dimensional),
           C3),
         1e-14);

  // Rotations: an isotropic material is invariant.
  report("isotropic rotated by (30, 40, 50) degrees",
         difference(make(isotropic + "set Orientation = 30, 40, 50\n")
                      .tensor<3>(PlanarAssumption::three_dimensional),
                    C3),
         1e-14);

  // Cubic rotated by 45 degrees about z: C'11 = (C11 + C12 + 2 C44) / 2, C'12 = (C11 + C12 -
  // 2 C44) / 2, C'66 = (C11 - C12) / 2, C'44 = C44, C'33 = C11.
  {
    const double c11 = 168e9, c12 = 121e9, c44 = 75e9; // copper
    const auto   m = make("set Symmetry = cubic\nset Cubic constants = 168e9, 121e9, 75e9\n"
                          "set Orientation = 45, 0, 0\n")
                     .voigt_stiffness();
    const double error = std::max({std::abs(m(0, 0) - (c11 + c12 + 2. * c44) / 2.),
                                   std::abs(m(0, 1) - (c11 + c12 - 2. * c44) / 2.),
                                   std::abs(m(5, 5) - (c11 - c12) / 2.),
                                   std::abs(m(3, 3) - c44),
                                   std::abs(m(2, 2) - c11),
                                   std::abs(m(0, 5))}) /
                         c11;
    report("cubic rotated by 45 degrees about z", error, 1e-14);
    std::cout << "  C'11 = " << m(0, 0) / 1e9 << " GPa, C'12 = " << m(0, 1) / 1e9
              << " GPa, C'66 = " << m(5, 5) / 1e9 << " GPa" << std::endl;
  }

  // Orthotropic plane stress: the in-plane compliance is that of the engineering constants.
  {
    const double E1 = 140e9, E2 = 10e9, nu12 = 0.3, G12 = 5e9;
    const auto   C = make("set Symmetry = orthotropic\nset Young's moduli = 140e9, 10e9, 10e9\n"
                          "set Poisson's ratios = 0.3, 0.3, 0.45\n"
                          "set Shear moduli = 5e9, 5e9, 3.4e9\n")
                     .tensor<2>(PlanarAssumption::plane_stress);
    // Uniaxial stress along 1: eps11 = 1/E1, eps22 = -nu12/E1; pure shear: 2 eps12 = 1/G12.
    SymmetricTensor<2, 2> eps;
    eps[0][0]                         = 1. / E1;
    eps[1][1]                         = -nu12 / E1;
    const SymmetricTensor<2, 2> sigma = C * eps;
    SymmetricTensor<2, 2>       shear;
    shear[0][1]                       = 0.5 / G12;
    const SymmetricTensor<2, 2> tau   = C * shear;
    const double                error = std::max({std::abs(sigma[0][0] - 1.),
                                                  std::abs(sigma[1][1]),
                                                  std::abs(sigma[0][1]),
                                                  std::abs(tau[0][1] - 1.)});
    report("orthotropic plane stress: uniaxial and shear compliance", error, 1e-12);
    (void)E2;
  }

  // General: the 21 constants come back unchanged.
  {
    std::string  values;
    double       expected[6][6];
    unsigned int k = 0;
    for (unsigned int i = 0; i < 6; ++i)
      for (unsigned int j = i; j < 6; ++j, ++k)
        {
          expected[i][j] = expected[j][i] = (i == j ? 100e9 : 1e9 * (1 + k % 7));
          values += (k > 0 ? ", " : "") + std::to_string(expected[i][j]);
        }
    const auto m =
      make("set Symmetry = general\nset Stiffness constants = " + values + "\n").voigt_stiffness();
    double error = 0.;
    for (unsigned int i = 0; i < 6; ++i)
      for (unsigned int j = 0; j < 6; ++j)
        error = std::max(error, std::abs(m(i, j) - expected[i][j]) / 100e9);
    report("general 21 constants", error, 1e-15);
  }

  // Bad input: a Poisson ratio that makes an orthotropic material unstable, a wrong count.
  for (const std::string bad :
       {"set Symmetry = orthotropic\nset Young's moduli = 1e9, 1e9, 1e9\n"
        "set Poisson's ratios = 0.9, 0.9, 0.9\nset Shear moduli = 1e9, 1e9, 1e9\n",
        "set Symmetry = general\nset Stiffness constants = 1, 2, 3\n"})
    try
      {
        make(bad);
        std::cout << "bad input accepted: FAILED" << std::endl;
      }
    catch (const ExceptionBase &exc)
      {
        std::cout << "bad input refused: " << perideal_tests::exception_text(exc) << std::endl;
      }
}
