// ThermalExpansion and planar_thermal_expansion(): the entry's one, three and nine values, the
// tensor in the global axes of a rotated material, and the in-plane expansion of a 2D body.
// Plane stress keeps the in-plane block; plane strain gives (1 + nu) alpha for an isotropic
// material and, for any stiffness, the in-plane strain at which the 3D thermal stress has no
// in-plane components. Refusals: a count the entry does not take, an asymmetric tensor, a
// tensor for an isotropic model.

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <perideal/base/elasticity.h>
#include <perideal/base/thermal_expansion.h>

#include "../tests.h"

#include <cmath>
#include <string>

using namespace dealii;
using namespace perideal;

namespace
{
  ElasticMaterial
  material(const std::string &symmetry_entries, const std::string &expansion)
  {
    ParameterHandler prm;
    ElasticMaterial::declare_parameters(prm);
    prm.parse_input_from_string(symmetry_entries + "\nset Thermal expansion = " + expansion);
    ElasticMaterial m;
    m.parse_parameters(prm, "Material/anisotropic bond based");
    return m;
  }

  // The largest in-plane component of the 3D thermal stress C (eps - alpha) of the 2D strain
  // eps = alpha_2D with no strain out of the plane, relative to |C alpha|.
  double
  in_plane_stress(const ElasticMaterial &m)
  {
    const auto alpha = m.thermal_expansion();
    const auto a2 =
      planar_thermal_expansion<2>(alpha, m.voigt_stiffness(), PlanarAssumption::plane_strain);
    const std::array<double, 6> thermal = {{alpha[0][0],
                                            alpha[1][1],
                                            alpha[2][2],
                                            2. * alpha[1][2],
                                            2. * alpha[0][2],
                                            2. * alpha[0][1]}};
    const std::array<double, 6> strain  = {{a2[0][0], a2[1][1], 0., 0., 0., 2. * a2[0][1]}};
    double                      largest = 0., scale = 0.;
    for (const unsigned int I : {0u, 1u, 5u})
      {
        double s = 0., c = 0.;
        for (unsigned int J = 0; J < 6; ++J)
          {
            s += m.voigt_stiffness()(I, J) * (strain[J] - thermal[J]);
            c += m.voigt_stiffness()(I, J) * thermal[J];
          }
        largest = std::max(largest, std::abs(s));
        scale   = std::max(scale, std::abs(c));
      }
    return largest / scale;
  }

  void
  refuse(const std::string &expansion, const bool tensor)
  {
    ParameterHandler prm;
    ThermalExpansion::declare_parameters(prm, true);
    prm.set("Thermal expansion", expansion);
    ThermalExpansion e;
    try
      {
        e.parse_parameters(prm, "Material/bond based", tensor);
        deallog << "NOT refused: " << expansion << std::endl;
      }
    catch (const ExceptionBase &error)
      {
        deallog << "refused: " << perideal_tests::exception_text(error) << std::endl;
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();
  deallog << std::scientific << std::setprecision(6);

  // Isotropic: 3D alpha; plane stress alpha; plane strain (1 + nu) alpha.
  {
    const auto m = material("set Young's modulus = 200e9\nset Poisson's ratio = 0.3", "1e-5");
    deallog << "isotropic: " << m.summary() << std::endl;
    const auto a3 = planar_thermal_expansion<3>(m.thermal_expansion(),
                                                m.voigt_stiffness(),
                                                PlanarAssumption::three_dimensional);
    const auto ps = planar_thermal_expansion<2>(m.thermal_expansion(),
                                                m.voigt_stiffness(),
                                                PlanarAssumption::plane_stress);
    const auto pe = planar_thermal_expansion<2>(m.thermal_expansion(),
                                                m.voigt_stiffness(),
                                                PlanarAssumption::plane_strain);
    deallog << "3D: " << a3 << std::endl;
    deallog << "plane stress: " << ps << std::endl;
    deallog << "plane strain: " << pe << " (1 + nu) alpha = " << 1.3e-5 << std::endl;
    AssertThrow(std::abs(pe[0][0] - 1.3e-5) < 1e-18 && std::abs(pe[0][1]) < 1e-20,
                ExcInternalError());
  }

  // Orthotropic, rotated by 30 degrees about z: alpha_xx = a1 cos^2 + a2 sin^2, and the plane
  // strain expansion leaves no in-plane thermal stress.
  {
    const auto m = material("set Symmetry = orthotropic\n"
                            "set Young's moduli = 150e9, 10e9, 12e9\n"
                            "set Poisson's ratios = 0.3, 0.25, 0.4\n"
                            "set Shear moduli = 5e9, 4e9, 3.5e9\n"
                            "set Orientation = 30, 0, 0",
                            "-1e-6, 3e-5, 2e-5");
    deallog << "orthotropic: " << m.summary() << std::endl;
    const auto   alpha = m.thermal_expansion();
    const double c = std::cos(numbers::PI / 6.), s = std::sin(numbers::PI / 6.);
    deallog << "alpha_xx " << alpha[0][0] << " expected " << -1e-6 * c * c + 3e-5 * s * s
            << "; alpha_xy " << alpha[0][1] << " expected " << (-1e-6 - 3e-5) * s * c
            << "; alpha_zz " << alpha[2][2] << std::endl;
    deallog << "plane strain: in-plane thermal stress / |C alpha| = "
            << (in_plane_stress(m) < 1e-12 ? "below 1e-12" : "TOO LARGE") << std::endl;
  }

  // Nine values: a symmetric tensor.
  {
    const auto m = material("set Young's modulus = 200e9\nset Poisson's ratio = 0.3",
                            "1e-5, 2e-6, 0, 2e-6, 1e-5, 0, 0, 0, 3e-5");
    deallog << "nine values: " << m.thermal_expansion() << std::endl;
  }

  refuse("1e-5, 2e-5", true);
  refuse("1e-5, 2e-6, 0, 0, 1e-5, 0, 0, 0, 3e-5", true);
  refuse("1e-5, 1e-5, 1e-5", false);
}
