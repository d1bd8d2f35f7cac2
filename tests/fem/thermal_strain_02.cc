// ---------------------------------------------------------------------
// FE thermal strain, a linear temperature in a free body (#39): Delta T = 20 + 300 x - 200 y
// (+ 100 z) K gives eps = alpha Delta T, which is compatible (u = alpha (Delta T_0 x + (g.x) x -
// |x|^2 g / 2), quadratic): no stress and no energy. Plane stress plate 0.1 x 0.1 m and cube
// 0.1 m, held only against rigid motions, E = 200 GPa, nu = 0.3, alpha = 1.2e-5 /K, n cells per
// side. FE_Q(2) holds u: stress and energy are round-off. FE_Q(1) does not: the largest stress
// at the Gauss points falls like h and the energy like h^2. Printed: the largest stress relative
// to E alpha |g| L (L = 0.1 m), the energy 1/2 u.K.u - u.f_th + c_th relative to c_th, and
// without the thermal load (u = 0) the stress, which then fails.
// ---------------------------------------------------------------------
#include "thermal_strain_tests.h"

#include <tests.h>

using namespace dealii;
using namespace thermal_strain_tests;

namespace
{
  constexpr double E = 200e9, alpha = 1.2e-5;

  template <int dim>
  void
  run(const unsigned int degree, const unsigned int n, const bool without_load)
  {
    const std::string cells = std::to_string(n);
    const std::string mesh =
      dim == 2 ? cells + ", " + cells + " : 0, 0 : 0.1, 0.1 : true" :
                 cells + ", " + cells + ", " + cells + " : 0, 0, 0 : 0.1, 0.1, 0.1 : true";
    auto fe = make_region<dim>("  set Generator = subdivided_hyper_rectangle\n"
                               "  set Generator arguments = " +
                                 mesh +
                                 "\n"
                                 "  set Polynomial degree = " +
                                 std::to_string(degree) +
                                 "\n"
                                 "  subsection Elasticity\n"
                                 "    set Young's modulus = 200e9\n"
                                 "    set Poisson's ratio = 0.3\n"
                                 "    set Thermal expansion = 1.2e-5\n"
                                 "  end\n",
                               {},
                               perideal::PlanarAssumption::plane_stress,
                               dim == 2 ? "20 + 300*x - 200*y" : "20 + 300*x - 200*y + 100*z");
    hold(*fe, free_body_supports<dim>(0.1), 0.1);
    FEVector f_th;
    fe->initialize_vector(f_th);
    const double c_th = fe->assemble_thermal_load(0., f_th);
    if (without_load)
      f_th = 0.;
    const auto                    u = solve(*fe, f_th);
    std::map<std::string, double> no_stress;
    for (const auto &component : dim == 2 ?
                                   std::vector<std::string>{"xx", "xy", "yy"} :
                                   std::vector<std::string>{"xx", "xy", "xz", "yy", "yz", "zz"})
      no_stress["stress_" + component] = 0.;
    const double gradient = dim == 2 ? std::sqrt(300. * 300. + 200. * 200.) :
                                       std::sqrt(300. * 300. + 200. * 200. + 100. * 100.);
    const double stress   = output_deviation(*fe, u, no_stress) / (E * alpha * gradient * 0.1);
    deallog << dim << "D FE_Q(" << degree << "), " << n << " cells per side"
            << (without_load ? ", without f_th" : "") << ": largest stress "
            << bounded(stress, 1e-10);
    if (!without_load)
      deallog << ", energy / c_th " << bounded(mechanical_energy(*fe, u) / c_th, 1e-10);
    deallog << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();
  for (const unsigned int n : {2u, 4u})
    run<2>(2, n, false);
  for (const unsigned int n : {4u, 8u, 16u, 32u})
    run<2>(1, n, false);
  run<2>(2, 4, true);
  run<3>(2, 2, false);
  for (const unsigned int n : {2u, 4u, 8u})
    run<3>(1, n, false);
  run<3>(2, 2, true);
}
