// Anisotropic linearized bond-based PD (seed 004): homogeneous strains reproduce the FE side's
// elasticity tensor at an interior particle to round-off with the discrete calibration, for
// every symmetry class (rotated ones and a C built from a random completely symmetric Lambda
// too); the continuum calibration's lattice error and the note's closed-form values.
#include <deal.II/base/numbers.h>
#include <deal.II/base/parameter_handler.h>

#include <perideal/base/elasticity.h>
#include <perideal/pd/anisotropic_bond_based.h>

#include "../tests.h"
#include "pd_tests.h"

#include <cstdio>
#include <iomanip>
#include <limits>

using namespace dealii;
namespace am = perideal::anisotropic_micromodulus;

using Entries = std::vector<std::pair<std::string, std::string>>;

// The Voigt pairs 11, 22, 33, 23, 13, 12.
const unsigned int voigt_pair[6][2] = {{0, 0}, {1, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}};

std::string
exact(const double value)
{
  char text[32];
  std::snprintf(text, sizeof(text), "%.17g", value);
  return text;
}

// The 6 x 6 Voigt stiffness of the model measured at the centre particle of an 11^3 lattice
// (delta = 3 dx, no surface correction) from the energy densities of homogeneous strains:
// C_II = 2 W(e_I), C_IJ = W(e_I + e_J) - W(e_I) - W(e_J) (engineering shear strains).
FullMatrix<double>
measured_stiffness(perideal::AnisotropicBondBased<3> &model)
{
  const double                          dx = 1e-3;
  const int                             n  = 11;
  perideal::ParticleSystem<3>           ps(MPI_COMM_WORLD);
  perideal::ParticleSystem<3>::Settings s;
  s.spacing        = dx;
  s.horizon        = 3. * dx;
  s.partial_volume = perideal::PartialVolume::geometric;
  pd_tests::generate_box<3>(ps, s, Point<3>(), Point<3>(n * dx, n * dx, n * dx));
  model.initialize(
    ps,
    pd_tests::model_context(s.horizon, 1., perideal::PlanarAssumption::three_dimensional, false));
  const double centre = 0.5 * n * dx;
  const auto   energy = [&](const std::array<double, 6> &strain) {
    perideal::ParticleVector u, f;
    ps.reinit_vector(u, 3);
    ps.reinit_vector(f, 3);
    for (unsigned int i = 0; i < ps.n_local(); ++i)
      for (unsigned int I = 0; I < 6; ++I)
        {
          const unsigned int a = voigt_pair[I][0], b = voigt_pair[I][1];
          const double       e = (a == b ? 1. : 0.5) * strain[I];
          u.local_element(i * 3 + a) += e * (ps.positions()[i][b] - centre);
          if (a != b)
            u.local_element(i * 3 + b) += e * (ps.positions()[i][a] - centre);
        }
    std::vector<double> w;
    model.compute_forces(ps, u, f, &w, std::numeric_limits<double>::infinity());
    double local = 0.;
    for (unsigned int i = 0; i < ps.n_owned(); ++i)
      if ((ps.positions()[i] - Point<3>(centre, centre, centre)).norm() < 0.6 * dx)
        local = w[i];
    return Utilities::MPI::sum(local, MPI_COMM_WORLD);
  };
  std::array<double, 6> W;
  FullMatrix<double>    C(6, 6);
  for (unsigned int I = 0; I < 6; ++I)
    {
      std::array<double, 6> e{};
      e[I]    = 1e-3;
      W[I]    = energy(e);
      C(I, I) = 2. * W[I] / 1e-6;
    }
  for (unsigned int I = 0; I < 6; ++I)
    for (unsigned int J = I + 1; J < 6; ++J)
      {
        std::array<double, 6> e{};
        e[I] = e[J] = 1e-3;
        C(I, J) = C(J, I) = (energy(e) - W[I] - W[J]) / 1e-6;
      }
  return C;
}

// The largest |C_IJ - reference_IJ| relative to the largest |reference_IJ|.
double
relative_error(const FullMatrix<double> &C, const FullMatrix<double> &reference)
{
  double error = 0., scale = 0.;
  for (unsigned int I = 0; I < 6; ++I)
    for (unsigned int J = 0; J < 6; ++J)
      {
        error = std::max(error, std::abs(C(I, J) - reference(I, J)));
        scale = std::max(scale, std::abs(reference(I, J)));
      }
  return error / scale;
}

// Measure C for the material @p entries with both calibrations against the FE side's
// ElasticMaterial of the same entries.
void
check(const std::string &label, const Entries &entries)
{
  ParameterHandler prm;
  perideal::ElasticMaterial::declare_parameters(prm);
  for (const auto &entry : entries)
    prm.set(entry.first, entry.second);
  perideal::ElasticMaterial fe_material;
  fe_material.parse_parameters(prm, "Finite elements/Elasticity");
  const FullMatrix<double> &reference = fe_material.voigt_stiffness();

  perideal::AnisotropicBondBased<3> discrete, continuum;
  pd_tests::parse_model(discrete, entries);
  Entries continuum_entries = entries;
  continuum_entries.emplace_back("Calibration", "continuum");
  pd_tests::parse_model(continuum, continuum_entries);
  const double discrete_error  = relative_error(measured_stiffness(discrete), reference);
  const double continuum_error = relative_error(measured_stiffness(continuum), reference);
  deallog << label << ": C11 = " << reference(0, 0) / 1e9 << " GPa, discrete calibration error "
          << (discrete_error < 1e-12 ? "< 1e-12 ok" : "FAILED") << ", continuum calibration error "
          << std::setprecision(3) << continuum_error << " (logged "
          << continuum.continuum_lattice_error() << ")" << std::setprecision(6)
          << (continuum_error > 1e-3 ? "" : " FAILED: should be a lattice error") << std::endl;
}

// A C built from a random completely symmetric Lambda (an isotropic part that keeps C positive
// definite plus random components), as the 21 constants of Symmetry = general.
Entries
random_lambda_material()
{
  am::Components Lambda;
  for (unsigned int k = 0; k < 15; ++k)
    {
      const auto e = am::component_exponents(k);
      Lambda[k]    = (e[0] % 2 == 0 && e[1] % 2 == 0 ? (k < 3 ? 3. : 1.) : 0.) +
                  0.3 * pd_tests::random_number(k);
    }
  const auto         C = am::to_tensor(am::multiply(am::continuum_moment_matrix(1.), Lambda));
  std::ostringstream constants;
  for (unsigned int I = 0; I < 6; ++I)
    for (unsigned int J = I; J < 6; ++J)
      constants << (I + J > 0 ? ", " : "")
                << exact(1e10 *
                         C[voigt_pair[I][0]][voigt_pair[I][1]][voigt_pair[J][0]][voigt_pair[J][1]]);
  return {{"Symmetry", "general"}, {"Stiffness constants", constants.str()}};
}

// The continuum Lambda against seed note 004, sec. 3.3: (m/2) Lambda in units of C, m = pi delta^4.
void
check_closed_form(const std::string                                  &label,
                  const Entries                                      &entries,
                  const std::vector<std::pair<unsigned int, double>> &expected)
{
  perideal::AnisotropicBondBased<3> model;
  Entries                           e = entries;
  e.emplace_back("Calibration", "continuum");
  pd_tests::parse_model(model, e);
  measured_stiffness(model);
  const double m     = numbers::PI * std::pow(3e-3, 4);
  double       error = 0.;
  for (const auto &[k, value] : expected)
    error =
      std::max(error,
               std::abs(0.5 * m * model.micromodulus_tensor()[k] / 1e10 - value) / std::abs(value));
  deallog << label << ": (m/2) Lambda against the note's closed form: "
          << (error < 1e-13 ? "agrees to 1e-13 ok" : "FAILED") << std::endl;
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();
  const Entries isotropic = {{"Symmetry", "isotropic"},
                             {"Young's modulus", "25e9"},
                             {"Poisson's ratio", "0.25"}};
  const Entries nacl      = {{"Symmetry", "cubic"}, {"Cubic constants", "49.1e9, 12.8e9, 12.8e9"}};
  // C11 = 3 C12, C66 = C12 = 10, C13 = C44 = 10, C33 = 20 GPa.
  const Entries transversely_isotropic = {{"Symmetry", "transversely isotropic"},
                                          {"Young's moduli", "24e9, 15e9"},
                                          {"Poisson's ratios", "0.2, 0.4"},
                                          {"Shear moduli", "10e9"}};
  // Seed note 004, sec. 3.3, times 10 GPa: C11 = 12, C22 = 9, C33 = 6, C12 = C66 = 3,
  // C13 = C55 = 2, C23 = C44 = 1.
  const Entries orthotropic = {
    {"Symmetry", "orthotropic"},
    {"Young's moduli", "105283018867.92453, 82058823529.411758, 56363636363.63636"},
    {"Poisson's ratios", "0.30188679245283018, 0.28301886792452829, 0.088235294117647065"},
    {"Shear moduli", "30e9, 20e9, 10e9"}};
  check("isotropic (E = 25 GPa, nu = 1/4)", isotropic);
  check("cubic NaCl", nacl);
  check("transversely isotropic", transversely_isotropic);
  check("orthotropic", orthotropic);
  check("random completely symmetric Lambda", random_lambda_material());
  Entries rotated = nacl;
  rotated.emplace_back("Orientation", "30, 40, 50");
  check("cubic NaCl rotated (30, 40, 50)", rotated);
  rotated = orthotropic;
  rotated.emplace_back("Orientation", "10, 70, -20");
  check("orthotropic rotated (10, 70, -20)", rotated);

  // lambda_L = mu = 10 GPa: (m/2) Lambda_1111 = 15, (m/2) Lambda_1122 = 5 (units of 10 GPa).
  check_closed_form("isotropic", isotropic, {{0, 15.}, {1, 15.}, {2, 15.}, {3, 5.}, {5, 5.}});
  check_closed_form("orthotropic",
                    orthotropic,
                    {{0, 795. / 8.},
                     {1, 345. / 4.},
                     {2, 585. / 8.},
                     {3, 45. / 4.},
                     {4, -85. / 8.},
                     {5, -65. / 2.}});
}
