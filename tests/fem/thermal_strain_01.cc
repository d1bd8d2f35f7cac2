// ---------------------------------------------------------------------
// FE thermal strain, free expansion (#39): a body held only against rigid motions (u = 0 at the
// origin, u_y (u_z) at (L, 0(, 0)), u_z at (0, L, 0)) under a uniform temperature change
// Delta T = 50 K expands freely, eps = alpha_eff Delta T (u = eps x and the rotation the
// supports leave), without stress and without energy (but sigma_zz = -E alpha Delta T and
// 1/2 E alpha^2 Delta T^2 per volume of the held eps_zz of plane strain).
// L = 0.1 m, Q1, E = 200 GPa, nu = 0.3, alpha = 1.2e-5 /K; 2D 5 x 3 cells on 0.1 x 0.06 m, 3D
// 3 x 3 x 2 cells on 0.1 x 0.1 x 0.06 m. alpha_eff: alpha (plane stress, 3D), (1 + nu) alpha
// (plane strain), and an orthotropic expansion (3e-6, 1e-5, 2.5e-5 /K along the material axes, with
// an orthotropic stiffness) rotated by z-x-z Euler angles (30, 20, 10 degrees; in 2D plane stress
// phi = 30): alpha in the global axes, R diag(alpha_i) R^T, given in <Finite elements/Elasticity>
// or, with <Same material as the particles>, in the particles' <Material/anisotropic bond based>.
// Solved with K and the thermal load f_th (FERegion::assemble_thermal_load()) directly. Printed:
// the largest nodal error relative to the largest nodal displacement, the largest stress (Gauss
// points, from the mechanical strain) relative to E alpha Delta T, the error of the energy 1/2
// u.K.u - u.f_th + c_th (exact: 0, in plane strain 1/2 E alpha^2 Delta T^2 per volume) relative to
// c_th; and without the thermal load (u = 0) the same two errors, which then fail.
// ---------------------------------------------------------------------
#include <perideal/base/elasticity.h>

#include "thermal_strain_tests.h"

#include <tests.h>

using namespace dealii;
using namespace thermal_strain_tests;

namespace
{
  constexpr double E = 200e9, alpha = 1.2e-5, delta_T = 50.;

  // The largest |u - F x| at the nodes relative to the largest |F x|, F = eps + W with the
  // rotation W the supports leave: F_ij = 2 eps_ij above the diagonal, 0 below (u_y(L, 0, 0) =
  // u_z(L, 0, 0) = u_z(0, L, 0) = 0).
  template <int dim>
  double
  nodal_error(const perideal::FERegion<dim> &fe,
              const FEVector                &u,
              const SymmetricTensor<2, dim> &eps)
  {
    Tensor<2, dim> F;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = i; j < dim; ++j)
        F[i][j] = (i == j ? 1. : 2.) * eps[i][j];
    double error = 0., largest = 0.;
    for (const auto &cell : fe.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          {
            const Tensor<1, dim> exact = F * cell->vertex(v);
            for (unsigned int c = 0; c < dim; ++c)
              {
                const double value = u(cell->vertex_dof_index(v, c));
                error              = std::max(error, std::abs(value - exact[c]));
                largest            = std::max(largest, std::abs(exact[c]));
              }
          }
    return Utilities::MPI::max(error, MPI_COMM_WORLD) /
           Utilities::MPI::max(largest, MPI_COMM_WORLD);
  }

  template <int dim>
  void
  run(const std::string               &name,
      const perideal::PlanarAssumption planar,
      const std::string               &material,
      const SymmetricTensor<2, dim>   &alpha_eff,
      const double                     energy_density,
      const std::string               &particles = "")
  {
    const std::string mesh =
      dim == 2 ? "5, 3 : 0, 0 : 0.1, 0.06 : true" : "3, 3, 2 : 0, 0, 0 : 0.1, 0.1, 0.06 : true";
    auto fe = make_region<dim>("  set Generator = subdivided_hyper_rectangle\n"
                               "  set Generator arguments = " +
                                 mesh +
                                 "\n"
                                 "  subsection Elasticity\n" +
                                 material + "  end\n",
                               {},
                               planar,
                               std::to_string(delta_T),
                               particles);
    hold(*fe, free_body_supports<dim>(0.1), 0.1);
    FEVector f_th, zero;
    fe->initialize_vector(f_th);
    fe->initialize_vector(zero);
    const double                  c_th = fe->assemble_thermal_load(0., f_th);
    const SymmetricTensor<2, dim> eps  = delta_T * alpha_eff;
    // No stress but sigma_zz = -E alpha Delta T of an isotropic plane strain.
    const double                  sigma = E * alpha * delta_T;
    std::map<std::string, double> no_stress;
    for (const auto &component : dim == 2 ?
                                   std::vector<std::string>{"xx", "xy", "yy", "zz"} :
                                   std::vector<std::string>{"xx", "xy", "xz", "yy", "yz", "zz"})
      no_stress["stress_" + component] = 0.;
    if (planar == perideal::PlanarAssumption::plane_strain)
      no_stress["stress_zz"] = -sigma;
    const auto   u      = solve(*fe, f_th);
    const double volume = dim == 2 ? 0.1 * 0.06 : 0.1 * 0.1 * 0.06;
    deallog << name << ": nodal error " << bounded(nodal_error(*fe, u, eps), 1e-10)
            << ", largest stress / (E alpha Delta T) "
            << bounded(output_deviation(*fe, u, no_stress) / sigma, 1e-10)
            << ", (energy - exact) / c_th "
            << bounded((mechanical_energy(*fe, u) - energy_density * volume) / c_th, 1e-10)
            << std::endl;
    const auto held = solve(*fe, zero);
    deallog << "  without f_th: nodal error " << bounded(nodal_error(*fe, held, eps), 1e-10)
            << ", largest stress / (E alpha Delta T) "
            << bounded(output_deviation(*fe, held, no_stress) / sigma, 1e-10) << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();
  const std::string     isotropic   = "    set Young's modulus = 200e9\n"
                                      "    set Poisson's ratio = 0.3\n"
                                      "    set Thermal expansion = 1.2e-5\n";
  const std::string     orthotropic = "    set Symmetry = orthotropic\n"
                                      "    set Young's moduli = 200e9, 120e9, 80e9\n"
                                      "    set Poisson's ratios = 0.3, 0.25, 0.2\n"
                                      "    set Shear moduli = 60e9, 40e9, 30e9\n"
                                      "    set Thermal expansion = 3e-6, 1e-5, 2.5e-5\n";
  const auto            axes        = perideal::rotation_from_euler_angles(30., 20., 10.);
  SymmetricTensor<2, 3> rotated;
  for (unsigned int i = 0; i < 3; ++i)
    for (unsigned int j = i; j < 3; ++j)
      for (unsigned int a = 0; a < 3; ++a)
        rotated[i][j] += axes[i][a] * axes[j][a] * std::vector<double>{3e-6, 1e-5, 2.5e-5}[a];
  const auto            axes_2d = perideal::rotation_from_euler_angles(30., 0., 0.);
  SymmetricTensor<2, 2> rotated_2d;
  for (unsigned int i = 0; i < 2; ++i)
    for (unsigned int j = i; j < 2; ++j)
      for (unsigned int a = 0; a < 2; ++a)
        rotated_2d[i][j] += axes_2d[i][a] * axes_2d[j][a] * std::vector<double>{3e-6, 1e-5}[a];

  run<2>("2D plane stress",
         perideal::PlanarAssumption::plane_stress,
         isotropic,
         alpha * unit_symmetric_tensor<2>(),
         0.);
  run<2>("2D plane strain",
         perideal::PlanarAssumption::plane_strain,
         isotropic,
         1.3 * alpha * unit_symmetric_tensor<2>(),
         0.5 * E * alpha * alpha * delta_T * delta_T);
  run<3>("3D",
         perideal::PlanarAssumption::three_dimensional,
         isotropic,
         alpha * unit_symmetric_tensor<3>(),
         0.);
  run<2>("2D plane stress, orthotropic, rotated",
         perideal::PlanarAssumption::plane_stress,
         orthotropic + "    set Orientation = 30, 0, 0\n",
         rotated_2d,
         0.);
  run<3>("3D, orthotropic, rotated",
         perideal::PlanarAssumption::three_dimensional,
         orthotropic + "    set Orientation = 30, 20, 10\n",
         rotated,
         0.);
  // The block of the particles' model, read through <Same material as the particles>.
  run<2>("2D plane stress, orthotropic, rotated, same material as the particles",
         perideal::PlanarAssumption::plane_stress,
         "    set Same material as the particles = true\n",
         rotated_2d,
         0.,
         "subsection Material\n"
         "  subsection anisotropic bond based\n" +
           orthotropic + "    set Orientation = 30, 0, 0\n" + "  end\nend\n");
}
