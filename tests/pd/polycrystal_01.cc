// A polycrystal of the anisotropic bond-based model (Grains, issue #15):
// 1. one grain of orientation phi in a Grains file gives the forces of the material with
//    Orientation phi (2D cubic NaCl, plane strain), to round-off;
// 2. a bicrystal (grains of orientation 0 and 30 degrees, the boundary at x = 20 dx): a
//    homogeneous strain gives, at the particles of each grain more than a horizon from the
//    boundary and the sides, the energy density 1/2 e : C_g : e of that grain's rotated tensor
//    (discrete calibration: to round-off), and the particles next to the boundary what the mean
//    rule gives (printed);
// 3. bad input: no such file, a line with a wrong count, a word that is not a number, a file
//    without grains, a grain-boundary ratio that is not positive.
// (The grain-boundary fracture energy is checked by cleaving in aniso_fracture_01.)
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <perideal/base/elasticity.h>
#include <perideal/pd/anisotropic_bond_based.h>

#include "../tests.h"
#include "pd_tests.h"

#include <fstream>
#include <functional>
#include <iomanip>
#include <limits>

using namespace dealii;

using Entries = std::vector<std::pair<std::string, std::string>>;

const double dx = 1e-3, thickness = 1e-3;

// Write @p text to @p name on rank 0 (all ranks read it afterwards).
void
write_file(const std::string &name, const std::string &text)
{
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    std::ofstream(name) << text;
  MPI_Barrier(MPI_COMM_WORLD);
}

// Cubic NaCl (C11 = 49.1, C12 = C44 = 12.8 GPa: Cauchy's relations hold) with @p extra entries.
std::unique_ptr<perideal::AnisotropicBondBased<2>>
nacl(const Entries &extra)
{
  Entries entries = {{"Symmetry", "cubic"}, {"Cubic constants", "49.1e9, 12.8e9, 12.8e9"}};
  entries.insert(entries.end(), extra.begin(), extra.end());
  auto model = std::make_unique<perideal::AnisotropicBondBased<2>>();
  pd_tests::parse_model(*model, entries);
  return model;
}

// A 40 dx x 20 dx plate with @p model initialized (plane strain, no surface correction).
struct Plate
{
  explicit Plate(perideal::AnisotropicBondBased<2> &model)
    : ps(MPI_COMM_WORLD)
  {
    perideal::ParticleSystem<2>::Settings s;
    s.spacing        = dx;
    s.horizon        = 3.015 * dx;
    s.thickness      = thickness;
    s.partial_volume = perideal::PartialVolume::geometric;
    pd_tests::generate_box<2>(ps, s, Point<2>(), Point<2>(40 * dx, 20 * dx));
    model.initialize(ps,
                     pd_tests::model_context(s.horizon,
                                             thickness,
                                             perideal::PlanarAssumption::plane_strain,
                                             false));
  }
  perideal::ParticleSystem<2> ps;
};

// The forces of @p model for a smooth non-homogeneous field.
std::vector<double>
forces(perideal::AnisotropicBondBased<2> &model)
{
  Plate                    plate(model);
  perideal::ParticleVector u, f;
  plate.ps.reinit_vector(u, 2);
  plate.ps.reinit_vector(f, 2);
  for (unsigned int i = 0; i < plate.ps.n_local(); ++i)
    {
      const auto &x              = plate.ps.positions()[i];
      u.local_element(2 * i)     = 1e-6 * std::sin(100. * x[0] + 50. * x[1]);
      u.local_element(2 * i + 1) = 1e-6 * std::cos(80. * x[0] - 120. * x[1]);
    }
  model.compute_forces(plate.ps, u, f, nullptr, std::numeric_limits<double>::infinity());
  return std::vector<double>(f.begin(), f.end());
}

// 1/2 e : C : e of NaCl with Orientation @p phi degrees (plane strain).
double
classical_energy(const double phi, const SymmetricTensor<2, 2> &e)
{
  ParameterHandler prm;
  perideal::ElasticMaterial::declare_parameters(prm);
  prm.set("Symmetry", "cubic");
  prm.set("Cubic constants", "49.1e9, 12.8e9, 12.8e9");
  prm.set("Orientation", std::to_string(phi) + ", 0, 0");
  perideal::ElasticMaterial material;
  material.parse_parameters(prm, "Material/anisotropic bond based");
  return 0.5 * e * (material.tensor<2>(perideal::PlanarAssumption::plane_strain) * e);
}

void
check_one_grain()
{
  write_file("one_grain.txt", "# x y phi\n0.01 0.01 30\n");
  auto       oriented = nacl({{"Orientation", "30, 0, 0"}});
  auto       grain    = nacl({{"Grains file", "one_grain.txt"}});
  const auto f1 = forces(*oriented), f2 = forces(*grain);
  double     difference = 0., scale = 0.;
  for (unsigned int i = 0; i < f1.size(); ++i)
    {
      difference = std::max(difference, std::abs(f1[i] - f2[i]));
      scale      = std::max(scale, std::abs(f1[i]));
    }
  difference = Utilities::MPI::max(difference, MPI_COMM_WORLD);
  scale      = Utilities::MPI::max(scale, MPI_COMM_WORLD);
  deallog << "one grain of 30 degrees against Orientation 30: largest force difference "
          << difference / scale << " of the largest force "
          << pd_tests::ok(difference <= 1e-12 * scale) << std::endl;
}

void
check_bicrystal()
{
  write_file("bicrystal.txt", "0.01 0.01 0\n0.03 0.01 30\n");
  auto  model = nacl({{"Grains file", "bicrystal.txt"}});
  Plate plate(*model);
  auto &ps = plate.ps;
  deallog << "bicrystal: " << model->summary().substr(model->summary().rfind('\n') + 3)
          << std::endl;
  SymmetricTensor<2, 2> e;
  e[0][0] = 1e-4;
  e[1][1] = -3e-5;
  e[0][1] = 5e-5;
  perideal::ParticleVector u, f;
  ps.reinit_vector(u, 2);
  ps.reinit_vector(f, 2);
  for (unsigned int i = 0; i < ps.n_local(); ++i)
    for (unsigned int d = 0; d < 2; ++d)
      u.local_element(2 * i + d) = (e * ps.positions()[i])[d];
  std::vector<double> w;
  model->compute_forces(ps, u, f, &w, std::numeric_limits<double>::infinity());
  const double W[2]     = {classical_energy(0., e), classical_energy(30., e)};
  double       error[2] = {0., 0.}, column[5] = {0., 0., 0., 0., 0.};
  unsigned int count[5] = {0, 0, 0, 0, 0};
  for (unsigned int i = 0; i < ps.n_owned(); ++i)
    {
      const auto  &x        = ps.positions()[i];
      const double interior = x[1] > 4 * dx && x[1] < 16 * dx;
      if (!interior)
        continue;
      if ((x[0] > 4 * dx && x[0] < 16 * dx) || (x[0] > 24 * dx && x[0] < 36 * dx))
        {
          const unsigned int g = x[0] > 20 * dx;
          error[g]             = std::max(error[g], std::abs(w[i] / W[g] - 1.));
        }
      // The columns 2.5 dx ... -1.5 dx before the boundary and after it.
      const int c = int(std::floor(x[0] / dx)) - 18;
      if (c >= 0 && c < 5 && std::abs(x[0] / dx - std::floor(x[0] / dx) - 0.5) < 1e-6)
        {
          column[c] += w[i];
          ++count[c];
        }
    }
  for (unsigned int g = 0; g < 2; ++g)
    deallog << "grain " << g << " (" << (g == 0 ? 0 : 30)
            << " degrees), interior: largest |W / W_classical - 1| = " << std::setprecision(1)
            << Utilities::MPI::max(error[g], MPI_COMM_WORLD) << std::setprecision(6) << " "
            << pd_tests::ok(Utilities::MPI::max(error[g], MPI_COMM_WORLD) < 1e-10) << std::endl;
  deallog << "next to the boundary (W / W of grain 0, columns x = 18.5 ... 22.5 dx):"
          << std::setprecision(5);
  for (unsigned int c = 0; c < 5; ++c)
    deallog << " "
            << Utilities::MPI::sum(column[c], MPI_COMM_WORLD) /
                 Utilities::MPI::sum(double(count[c]), MPI_COMM_WORLD) / W[0];
  deallog << " (grain 1: " << W[1] / W[0] << ")" << std::setprecision(6) << std::endl;
}

void
check_bad(const std::string &label, const Entries &entries)
{
  pd_tests::check_refused(label, [&] { nacl(entries); });
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();

  check_one_grain();
  check_bicrystal();

  write_file("count.txt", "0.01 0.01 0\n0.02 0.01\n");
  write_file("word.txt", "0.01 0.01 x30\n");
  write_file("empty.txt", "# no grains\n\n");
  check_bad("no such file", {{"Grains file", "missing.txt"}});
  check_bad("two numbers", {{"Grains file", "count.txt"}});
  check_bad("not a number", {{"Grains file", "word.txt"}});
  check_bad("no grain", {{"Grains file", "empty.txt"}});
  check_bad("ratio 0",
            {{"Grains file", "bicrystal.txt"}, {"Grain boundary fracture energy ratio", "0"}});
}
