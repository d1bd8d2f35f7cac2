// Fracture energies along the material axes of the anisotropic bond-based model
// (AnisotropicFractureEnergy, issue #15):
// 1. continuum calibration: the crack energy G(m) / G_iso(m), integrated by quadrature over the
//    bond directions (independent of the calibration's closed form), is r_a for the crack
//    normals along the rotated material axes, in 2D and 3D;
// 2. discrete calibration: the same on the lattice's interior family, to round-off;
// 3. cleaving a 2D plate along a plane through the force kernel's bond breaking: the energy
//    dissipated per unit crack area with the crack normal along axis 2 (Orientation 0) and along
//    axis 1 (Orientation 90) has the ratio r2/r1, and along axis 1 (r1 = 1) that of equal
//    ratios (to 1e-3: the jump grows in steps of 0.05 %, so a bond breaks with up to 0.1 % more
//    than its critical energy; the mean excess is nearly the same for every bond);
// 4. grain boundaries (Grains): cleaving along the boundary between two grains of the same
//    orientation with <Grain boundary fracture energy ratio> = 0.5 costs half of cleaving one
//    grain, and along the boundary between grains of orientation 0 and 90 (ratio 1) the mean
//    of the two grains' energies (to 1e-3, as in 3.);
// 5. bad input: ratios outside the accepted range, a ratio that is not positive, unequal ratios
//    with no material axis normal to a 2D body.
#include <deal.II/base/numbers.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/quadrature_lib.h>

#include <perideal/base/elasticity.h>
#include <perideal/pd/anisotropic_bond_based.h>
#include <perideal/pd/anisotropic_fracture.h>
#include <perideal/pd/damage_model.h>

#include "../tests.h"
#include "pd_tests.h"

#include <fstream>
#include <functional>
#include <iomanip>
#include <limits>

using namespace dealii;
namespace am = perideal::anisotropic_micromodulus;

using Entries = std::vector<std::pair<std::string, std::string>>;

// The material axes of an isotropic material with @p orientation (ElasticMaterial::axes()).
Tensor<2, 3>
material_axes(const std::string &orientation)
{
  ParameterHandler prm;
  perideal::ElasticMaterial::declare_parameters(prm);
  prm.set("Young's modulus", "1e9");
  prm.set("Poisson's ratio", "0.25");
  prm.set("Orientation", orientation);
  perideal::ElasticMaterial material;
  material.parse_parameters(prm, "Material/anisotropic bond based");
  return material.axes();
}

// The fracture-energy weight of @p ratios for the material axes of @p orientation, continuum
// calibration.
template <int dim>
perideal::AnisotropicFractureEnergy<dim>
fracture_energy(const std::string &ratios, const std::string &orientation)
{
  ParameterHandler prm;
  perideal::AnisotropicFractureEnergy<dim>::declare_parameters(prm);
  prm.set("Fracture energy ratios", ratios);
  perideal::AnisotropicFractureEnergy<dim> fracture;
  fracture.parse_parameters(prm, "Material/anisotropic bond based");
  fracture.calibrate(material_axes(orientation), am::Family<dim>(), false);
  return fracture;
}

// G(m) / G_iso(m) in the continuum: the integral of (n . m) g(n) over the directions with
// n . m > 0 divided by that of (n . m), by Gauss quadrature in the angle(s) about m.
template <int dim>
double
continuum_crack_energy_ratio(const perideal::AnisotropicFractureEnergy<dim> &fracture,
                             const Tensor<1, dim>                           &m)
{
  const QGauss<1> gauss(12);
  double          weighted = 0., isotropic = 0.;
  if constexpr (dim == 2)
    {
      const Tensor<1, 2> t({-m[1], m[0]});
      for (unsigned int q = 0; q < gauss.size(); ++q)
        {
          const double       angle = numbers::PI * (gauss.point(q)[0] - 0.5);
          const Tensor<1, 2> n     = std::cos(angle) * m + std::sin(angle) * t;
          weighted += gauss.weight(q) * std::cos(angle) * fracture.weight(n);
          isotropic += gauss.weight(q) * std::cos(angle);
        }
    }
  else
    {
      // An orthonormal frame (m, t1, t2); mu = n . m in (0, 1], 16 azimuths (exact for the
      // quadratic g).
      Tensor<1, 3> t1 =
        std::abs(m[0]) < 0.9 ? Tensor<1, 3>({1., 0., 0.}) : Tensor<1, 3>({0., 1., 0.});
      t1 -= (t1 * m) * m;
      t1 /= t1.norm();
      const Tensor<1, 3> t2 = cross_product_3d(m, t1);
      for (unsigned int q = 0; q < gauss.size(); ++q)
        for (unsigned int k = 0; k < 16; ++k)
          {
            const double       mu  = gauss.point(q)[0];
            const double       phi = 2. * numbers::PI * k / 16.;
            const double       s   = std::sqrt(1. - mu * mu);
            const Tensor<1, 3> n   = mu * m + s * (std::cos(phi) * t1 + std::sin(phi) * t2);
            weighted += gauss.weight(q) * mu * fracture.weight(n);
            isotropic += gauss.weight(q) * mu;
          }
    }
  return weighted / isotropic;
}

// Part 1: the continuum calibration against the quadrature.
template <int dim>
void
check_continuum(const std::string &ratios, const std::string &orientation)
{
  const auto fracture = fracture_energy<dim>(ratios, orientation);
  const auto axes     = material_axes(orientation);
  const auto r        = Utilities::string_to_double(Utilities::split_string_list(ratios));
  deallog << dim << "D continuum, ratios " << ratios << ", Orientation " << orientation << ":";
  double error = 0.;
  for (unsigned int a = 0; a < 3; ++a)
    {
      Tensor<1, dim> m;
      double         normal = 0.;
      for (unsigned int d = 0; d < 3; ++d)
        (d < dim ? m[d] : normal) = axes[d][a];
      if (std::abs(normal) > 1e-12)
        continue;
      const double ratio = continuum_crack_energy_ratio(fracture, m);
      deallog << " G(axis " << a + 1 << ")/G_iso = " << std::setprecision(10) << ratio;
      error = std::max(error, std::abs(ratio - r[a]));
    }
  deallog << std::setprecision(6) << "; largest error " << pd_tests::ok(error < 1e-12) << std::endl;
}

// A 2D isotropic plate in plane strain (nu = 1/4: the 2D Cauchy relation holds) with the
// fracture-energy entries.
std::unique_ptr<perideal::AnisotropicBondBased<2>>
plate_model(const std::string &ratios, const std::string &orientation, const Entries &extra)
{
  auto    model   = std::make_unique<perideal::AnisotropicBondBased<2>>();
  Entries entries = {{"Young's modulus", "1e9"},
                     {"Poisson's ratio", "0.25"},
                     {"Orientation", orientation},
                     {"Fracture energy ratios", ratios}};
  entries.insert(entries.end(), extra.begin(), extra.end());
  pd_tests::parse_model(*model, entries);
  return model;
}

// Part 2 and 3: cleave a 40 dx x 20 dx plate along y = 10 dx by a rigid jump of the upper half,
// increased in steps of 0.05 %, and return the energy the broken bonds took with them per unit
// crack area, counted at the particles of the 20 middle columns (both ends of every bond there
// have complete families, so the count is that of an infinite crack); @p extra: more entries
// of the model (grains).
double
cleave(const std::string &ratios, const std::string &orientation, const Entries &extra = {})
{
  const double                          dx = 1e-3, thickness = 1e-3, G0 = 100.;
  perideal::ParticleSystem<2>           ps(MPI_COMM_WORLD);
  perideal::ParticleSystem<2>::Settings s;
  s.spacing        = dx;
  s.horizon        = 3.015 * dx;
  s.thickness      = thickness;
  s.partial_volume = perideal::PartialVolume::geometric;
  pd_tests::generate_box<2>(ps, s, Point<2>(), Point<2>(40 * dx, 20 * dx));
  auto model = plate_model(ratios, orientation, extra);
  model->initialize(
    ps,
    pd_tests::model_context(s.horizon, thickness, perideal::PlanarAssumption::plane_strain, false));
  if (orientation == "0, 0, 0" && extra.empty())
    {
      // Part 2: the discrete calibration on the family the model fitted.
      const auto                             family   = am::interior_family(ps);
      const auto                             fracture = fracture_energy<2>(ratios, orientation);
      perideal::AnisotropicFractureEnergy<2> discrete = fracture;
      discrete.calibrate(Tensor<2, 3>(unit_symmetric_tensor<3>()), family, true);
      const auto   r  = Utilities::string_to_double(Utilities::split_string_list(ratios));
      const double e1 = discrete.crack_energy_ratio(family, Tensor<1, 2>({1., 0.})) - r[0];
      const double e2 = discrete.crack_energy_ratio(family, Tensor<1, 2>({0., 1.})) - r[1];
      deallog << "2D discrete, ratios " << ratios << ": lattice G(axis a)/G_iso - r_a = " << e1
              << ", " << e2 << " " << pd_tests::ok(std::max(std::abs(e1), std::abs(e2)) < 1e-12)
              << "; at 45 degrees "
              << discrete.crack_energy_ratio(family, Tensor<1, 2>({std::sqrt(0.5), std::sqrt(0.5)}))
              << std::endl;
    }
  const double             s0 = model->critical_stretch(G0);
  perideal::ParticleVector u, f;
  ps.reinit_vector(u, 2);
  ps.reinit_vector(f, 2);
  const auto window_energy = [&]() {
    std::vector<double> w;
    model->compute_forces(ps, u, f, &w, std::numeric_limits<double>::infinity());
    double local = 0.;
    for (unsigned int i = 0; i < ps.n_owned(); ++i)
      if (ps.positions()[i][0] > 10 * dx && ps.positions()[i][0] < 30 * dx)
        local += w[i] * ps.volumes()[i];
    return Utilities::MPI::sum(local, MPI_COMM_WORLD);
  };
  double dissipated = 0.;
  for (double jump = 0.5 * s0 * dx; perideal::n_broken_bonds(ps) == 0 || window_energy() > 0.;
       jump *= 1.0005)
    {
      for (unsigned int i = 0; i < ps.n_local(); ++i)
        u.local_element(2 * i + 1) = ps.positions()[i][1] > 10 * dx ? jump : 0.;
      const double before = window_energy();
      model->compute_forces(ps, u, f, nullptr, s0);
      dissipated += before - window_energy();
    }
  return dissipated / (20 * dx * thickness * G0);
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();

  check_continuum<2>("1, 1.6, 1", "30, 0, 0");
  check_continuum<2>("1.9, 7, 1", "-20, 90, 0");
  check_continuum<3>("1, 1.4, 0.8", "30, 20, 10");

  const double along_2 = cleave("1, 1.6, 1", "0, 0, 0");
  const double along_1 = cleave("1, 1.6, 1", "90, 0, 0");
  const double equal   = cleave("1, 1, 1", "0, 0, 0");
  deallog << "cleaving, G / G0 (lattice and step error of the isotropic model: "
          << std::setprecision(4) << equal << "): normal along axis 2 " << along_2
          << ", along axis 1 " << along_1 << "; ratio " << along_2 / along_1
          << " (r2/r1 = 1.6, relative difference " << std::setprecision(1)
          << along_2 / along_1 / 1.6 - 1. << ") "
          << pd_tests::ok(std::abs(along_2 / along_1 / 1.6 - 1.) < 1e-3) << std::setprecision(4)
          << "; axis 1 against isotropic " << along_1 / equal << " (r1 = 1) "
          << pd_tests::ok(std::abs(along_1 / equal - 1.) < 1e-3) << std::setprecision(6)
          << std::endl;

  // Part 4: the grains meet at y = 10 dx, the cleaving plane (seeds 5 dx below and above it).
  const auto grains =
    [](const std::string &name, const std::string &phi_1, const std::string &phi_2) {
      if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
        std::ofstream(name) << "0.02 0.005 " << phi_1 << "\n0.02 0.015 " << phi_2 << "\n";
      MPI_Barrier(MPI_COMM_WORLD);
    };
  grains("same.txt", "0", "0");
  grains("crossed.txt", "0", "90");
  const double weak =
    cleave("1, 1.6, 1",
           "0, 0, 0",
           {{"Grains file", "same.txt"}, {"Grain boundary fracture energy ratio", "0.5"}});
  const double mixed = cleave("1, 1.6, 1", "0, 0, 0", {{"Grains file", "crossed.txt"}});
  deallog << "cleaving along a grain boundary, G / G0: same orientations, ratio 0.5: "
          << std::setprecision(4) << weak << " (half of one grain's " << along_2 << ": "
          << weak / along_2 << ") " << pd_tests::ok(std::abs(weak / along_2 / 0.5 - 1.) < 1e-3)
          << "; orientations 0 and 90, ratio 1: " << mixed << " (the grains' mean "
          << 0.5 * (along_2 + along_1) << ") "
          << pd_tests::ok(std::abs(mixed / (0.5 * (along_2 + along_1)) - 1.) < 1e-3)
          << std::setprecision(6) << std::endl;

  pd_tests::check_refused("2D, r2/r1 = 2.5", [] { fracture_energy<2>("1, 2.5, 1", "0, 0, 0"); });
  pd_tests::check_refused("3D, 1, 1, 4", [] { fracture_energy<3>("1, 1, 4", "0, 0, 0"); });
  pd_tests::check_refused("ratio 0", [] { fracture_energy<3>("1, 0, 1", "0, 0, 0"); });
  pd_tests::check_refused("2D, tilted axes", [] { fracture_energy<2>("1, 1.5, 1", "0, 30, 0"); });
}
