// Anisotropic linearized bond-based PD in 2D (seed 004): homogeneous strains reproduce the FE
// side's 2D elasticity tensor of the same material under the same planar assumption (plane
// strain: the in-plane block; plane stress: the reduced stiffness) at an interior particle to
// round-off with the discrete calibration (isotropic, cubic NaCl, the note's orthotropic tensor
// rotated in the plane); the continuum calibration's lattice error; the continuum Lambda against
// the note's 2D closed form (sec. 1.6) and the square-symmetry form c(theta) = a + b cos 4 theta;
// a 2D tensor that violates the 2D Cauchy relation is refused (or symmetrized on request); the
// plane-wave speeds of the interior operator against the Christoffel equation.
#include <deal.II/base/numbers.h>
#include <deal.II/base/parameter_handler.h>

#include <perideal/base/elasticity.h>
#include <perideal/pd/anisotropic_bond_based.h>

#include "../tests.h"
#include "pd_tests.h"

#include <iomanip>
#include <limits>

using namespace dealii;
namespace am = perideal::anisotropic_micromodulus;

using Entries = std::vector<std::pair<std::string, std::string>>;

// The Voigt pairs 11, 22, 12.
const unsigned int voigt_pair[3][2] = {{0, 0}, {1, 1}, {0, 1}};

const double dx = 1e-3, thickness = 1e-3, horizon = 3. * dx;

// A 15 x 15 lattice (delta = 3 dx, plate thickness 1 mm) with the model initialized.
struct Lattice
{
  Lattice(perideal::AnisotropicBondBased<2> &model, const perideal::PlanarAssumption planar)
    : ps(MPI_COMM_WORLD)
  {
    perideal::ParticleSystem<2>::Settings s;
    s.spacing        = dx;
    s.horizon        = horizon;
    s.thickness      = thickness;
    s.partial_volume = perideal::PartialVolume::geometric;
    pd_tests::generate_box<2>(ps, s, Point<2>(), Point<2>(n * dx, n * dx));
    model.initialize(ps, pd_tests::model_context(s.horizon, thickness, planar, false));
  }
  const int                   n = 15;
  perideal::ParticleSystem<2> ps;
};

// The 3 x 3 Voigt stiffness of the model at the centre particle from the energy densities of
// homogeneous strains: C_II = 2 W(e_I), C_IJ = W(e_I + e_J) - W(e_I) - W(e_J).
FullMatrix<double>
measured_stiffness(perideal::AnisotropicBondBased<2> &model,
                   const perideal::PlanarAssumption   planar)
{
  Lattice      lattice(model, planar);
  auto        &ps     = lattice.ps;
  const double centre = 0.5 * lattice.n * dx;
  const auto   energy = [&](const std::array<double, 3> &strain) {
    perideal::ParticleVector u, f;
    ps.reinit_vector(u, 2);
    ps.reinit_vector(f, 2);
    for (unsigned int i = 0; i < ps.n_local(); ++i)
      for (unsigned int I = 0; I < 3; ++I)
        {
          const unsigned int a = voigt_pair[I][0], b = voigt_pair[I][1];
          const double       e = (a == b ? 1. : 0.5) * strain[I];
          u.local_element(i * 2 + a) += e * (ps.positions()[i][b] - centre);
          if (a != b)
            u.local_element(i * 2 + b) += e * (ps.positions()[i][a] - centre);
        }
    std::vector<double> w;
    model.compute_forces(ps, u, f, &w, std::numeric_limits<double>::infinity());
    double local = 0.;
    for (unsigned int i = 0; i < ps.n_owned(); ++i)
      if ((ps.positions()[i] - Point<2>(centre, centre)).norm() < 0.6 * dx)
        local = w[i];
    return Utilities::MPI::sum(local, MPI_COMM_WORLD);
  };
  std::array<double, 3> W;
  FullMatrix<double>    C(3, 3);
  for (unsigned int I = 0; I < 3; ++I)
    {
      std::array<double, 3> e{};
      e[I]    = 1e-3;
      W[I]    = energy(e);
      C(I, I) = 2. * W[I] / 1e-6;
    }
  for (unsigned int I = 0; I < 3; ++I)
    for (unsigned int J = I + 1; J < 3; ++J)
      {
        std::array<double, 3> e{};
        e[I] = e[J] = 1e-3;
        C(I, J) = C(J, I) = (energy(e) - W[I] - W[J]) / 1e-6;
      }
  return C;
}

// The plane-wave speeds of the model's interior operator against the Christoffel equation of
// the 2D tensor @p C (rho cancels): for u = e_c cos(k.(x - x0)) the force density at x0 is
// -K(k) e_c, so the speeds are sqrt(eig K / rho) / |k| against sqrt(eig Gamma / rho),
// Gamma_ik = C_ijkl n_j n_l; wavelength 60 dx, directions 0, 30, 45, 60, 90, 135 degrees. The
// largest |c_PD / c_Christoffel - 1| over the directions and the two (P-like, S-like) speeds.
double
wave_speed_error(perideal::MaterialModel<2>  &model,
                 perideal::ParticleSystem<2> &ps,
                 const Point<2>              &x0,
                 const SymmetricTensor<4, 2> &C)
{
  const auto eigen = [](const double a, const double b, const double d) {
    const double mean = 0.5 * (a + d), radius = std::sqrt(0.25 * (a - d) * (a - d) + b * b);
    return std::array<double, 2>{{mean + radius, mean - radius}};
  };
  double worst = 0.;
  for (const double degrees : {0., 30., 45., 60., 90., 135.})
    {
      const double       theta = degrees * numbers::PI / 180.;
      const Tensor<1, 2> n     = Point<2>(std::cos(theta), std::sin(theta));
      const Tensor<1, 2> k     = 2. * numbers::PI / (60. * dx) * n;
      double             K[2][2];
      for (unsigned int c = 0; c < 2; ++c)
        {
          perideal::ParticleVector u, f;
          ps.reinit_vector(u, 2);
          ps.reinit_vector(f, 2);
          for (unsigned int i = 0; i < ps.n_local(); ++i)
            u.local_element(i * 2 + c) = std::cos(k * (ps.positions()[i] - x0));
          model.compute_forces(ps, u, f, nullptr, std::numeric_limits<double>::infinity());
          double local[2] = {0., 0.};
          for (unsigned int i = 0; i < ps.n_owned(); ++i)
            if ((ps.positions()[i] - x0).norm() < 0.1 * dx)
              for (unsigned int d = 0; d < 2; ++d)
                local[d] = -f.local_element(i * 2 + d);
          for (unsigned int d = 0; d < 2; ++d)
            K[d][c] = Utilities::MPI::sum(local[d], MPI_COMM_WORLD);
        }
      double Gamma[2][2] = {{0., 0.}, {0., 0.}};
      for (unsigned int i = 0; i < 2; ++i)
        for (unsigned int j = 0; j < 2; ++j)
          for (unsigned int l = 0; l < 2; ++l)
            for (unsigned int m = 0; m < 2; ++m)
              Gamma[i][l] += C[i][j][l][m] * n[j] * n[m] * k.norm_square();
      const auto pd = eigen(K[0][0], 0.5 * (K[0][1] + K[1][0]), K[1][1]);
      const auto ch = eigen(Gamma[0][0], Gamma[0][1], Gamma[1][1]);
      for (unsigned int q = 0; q < 2; ++q)
        worst = std::max(worst, std::abs(std::sqrt(pd[q] / ch[q]) - 1.));
    }
  return worst;
}

// The largest |C_IJ - reference_IJ| relative to the largest |reference_IJ|.
double
relative_error(const FullMatrix<double> &C, const FullMatrix<double> &reference)
{
  double error = 0., scale = 0.;
  for (unsigned int I = 0; I < 3; ++I)
    for (unsigned int J = 0; J < 3; ++J)
      {
        error = std::max(error, std::abs(C(I, J) - reference(I, J)));
        scale = std::max(scale, std::abs(reference(I, J)));
      }
  return error / scale;
}

void
check(const std::string &label, const Entries &entries, const perideal::PlanarAssumption planar)
{
  const FullMatrix<double>          reference = pd_tests::fe_voigt_stiffness(entries, planar);
  perideal::AnisotropicBondBased<2> discrete, continuum;
  pd_tests::parse_model(discrete, entries);
  Entries continuum_entries = entries;
  continuum_entries.emplace_back("Calibration", "continuum");
  pd_tests::parse_model(continuum, continuum_entries);
  const double discrete_error  = relative_error(measured_stiffness(discrete, planar), reference);
  const double continuum_error = relative_error(measured_stiffness(continuum, planar), reference);
  deallog << label << " (" << pd_tests::planar_name(planar) << "): C11 = " << std::setprecision(6)
          << reference(0, 0) / 1e9 << " GPa, C22 = " << reference(1, 1) / 1e9
          << " GPa, C12 = " << reference(0, 1) / 1e9 << " GPa, C66 = " << reference(2, 2) / 1e9
          << " GPa, C16 = "
          << (std::abs(reference(0, 2)) < 1e-6 * reference(0, 0) ? 0. : reference(0, 2) / 1e9)
          << " GPa; discrete calibration error (tolerance 1e-12) "
          << (discrete_error < 1e-12 ? "ok" : "FAILED") << ", continuum calibration error "
          << std::setprecision(3) << continuum_error << " (logged "
          << continuum.continuum_lattice_error() << ")" << std::setprecision(6)
          << (continuum_error > 1e-3 ? "" : " FAILED: should be a lattice error") << std::endl;
  std::cerr << label << " discrete error " << discrete_error << std::endl;

  perideal::AnisotropicBondBased<2> waves;
  pd_tests::parse_model(waves, entries);
  Lattice      lattice(waves, planar);
  const double centre = 0.5 * lattice.n * dx;
  const double error =
    wave_speed_error(waves, lattice.ps, Point<2>(centre, centre), waves.elasticity_tensor());
  deallog << "  plane-wave speeds (wavelength 60 dx) against the Christoffel equation, largest "
          << "deviation over 6 directions (tolerance 2 %): " << std::setprecision(2) << 100. * error
          << " % " << pd_tests::ok(error < 0.02) << std::setprecision(6) << std::endl;
}

// The continuum Lambda of @p entries in plane strain against the note's 2D closed form
// (m/2) Lambda = A C on (1111, 1112, 1122, 1222, 2222), m = 2 pi h delta^3 / 3 (omega = 1/r), and
// c(theta) against a + b cos 4 theta + the terms of lower symmetry.
void
check_closed_form(const std::string &label, const Entries &entries)
{
  perideal::AnisotropicBondBased<2> model;
  Entries                           e = entries;
  e.emplace_back("Calibration", "continuum");
  pd_tests::parse_model(model, e);
  Lattice      lattice(model, perideal::PlanarAssumption::plane_strain);
  const auto   C = am::completely_symmetric_part(model.elasticity_tensor());
  const double m = 2. * numbers::PI * thickness * std::pow(horizon, 3) / 3.;
  // The note's order (1111, 1112, 1122, 1222, 2222) -> ours (1111, 2222, 1122, 1112, 1222).
  const unsigned int ours[5] = {0, 3, 2, 4, 1};
  const double       A[5][5] = {{5, 0, -10, 0, 1},
                                {0, 10, 0, -6, 0},
                                {-5. / 3., 0, 38. / 3., 0, -5. / 3.},
                                {0, -6, 0, 10, 0},
                                {1, 0, -10, 0, 5}};
  double             error = 0., scale = 0.;
  for (unsigned int r = 0; r < 5; ++r)
    {
      double value = 0.;
      for (unsigned int c = 0; c < 5; ++c)
        value += A[r][c] * C[ours[c]];
      error = std::max(error, std::abs(0.5 * m * model.micromodulus_tensor()[ours[r]] - value));
      scale = std::max(scale, std::abs(value));
    }
  // c(theta) = Lambda_1111 cos^4 + Lambda_2222 sin^4 + 6 Lambda_1122 cos^2 sin^2 + ...; for square
  // symmetry a = 3 (Lambda_1111 + Lambda_1122) / 4, b = (Lambda_1111 - 3 Lambda_1122) / 4.
  const auto  &L = model.micromodulus_tensor();
  const double a = 0.75 * (L[0] + L[2]), b = 0.25 * (L[0] - 3. * L[2]);
  double       square_error = 0.;
  for (unsigned int q = 0; q < 36; ++q)
    {
      const double theta = q * numbers::PI / 36.;
      square_error       = std::max(
        square_error,
        std::abs(
          am::directional_modulus(L, Tensor<1, 2>(Point<2>(std::cos(theta), std::sin(theta)))) -
          (a + b * std::cos(4. * theta))));
    }
  deallog << label << ": (m/2) Lambda against the note's 2D closed form (tolerance 1e-13): "
          << pd_tests::ok(error < 1e-13 * scale) << "; (m/2) a = " << std::setprecision(8)
          << 0.5 * m * a / 1e9
          << " GPa, (m/2) b = " << (std::abs(b) < 1e-12 * std::abs(a) ? 0. : 0.5 * m * b / 1e9)
          << " GPa, c(theta) = a + b cos 4 theta (tolerance 1e-12): "
          << pd_tests::ok(square_error < 1e-12 * std::abs(a)) << std::setprecision(6)
          << ", smallest/largest symbol eigenvalue > 0: "
          << pd_tests::ok(model.symbol_scan().relative_minimum > 0.) << std::endl;
}

// The message of the exception that initializing @p entries under @p planar throws.
void
check_refused(const std::string               &label,
              const Entries                   &entries,
              const perideal::PlanarAssumption planar)
{
  try
    {
      perideal::AnisotropicBondBased<2> model;
      pd_tests::parse_model(model, entries);
      Lattice lattice(model, planar);
      deallog << label << ": accepted (wrong)" << std::endl;
    }
  catch (const ExceptionBase &exc)
    {
      deallog << label << ": refused: " << perideal_tests::exception_text(exc) << std::endl;
    }
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();
  const auto    strain  = perideal::PlanarAssumption::plane_strain;
  const auto    stress  = perideal::PlanarAssumption::plane_stress;
  const Entries iso_1_4 = {{"Symmetry", "isotropic"},
                           {"Young's modulus", "25e9"},
                           {"Poisson's ratio", "0.25"}};
  const Entries iso_1_3 = {{"Symmetry", "isotropic"},
                           {"Young's modulus", "30e9"},
                           {"Poisson's ratio", "0.3333333333333333"}};
  const Entries nacl    = {{"Symmetry", "cubic"}, {"Cubic constants", "49.1e9, 12.8e9, 12.8e9"}};
  // Seed note 004, sec. 3.3, times 10 GPa: C11 = 12, C22 = 9, C33 = 6, C12 = C66 = 3,
  // C13 = C55 = 2, C23 = C44 = 1.
  const Entries orthotropic = {
    {"Symmetry", "orthotropic"},
    {"Young's moduli", "105283018867.92453, 82058823529.411758, 56363636363.63636"},
    {"Poisson's ratios", "0.30188679245283018, 0.28301886792452829, 0.088235294117647065"},
    {"Shear moduli", "30e9, 20e9, 10e9"}};
  Entries orthotropic_30 = orthotropic;
  orthotropic_30.emplace_back("Orientation", "30, 0, 0");
  Entries nacl_25 = nacl;
  nacl_25.emplace_back("Orientation", "25, 0, 0");

  check("isotropic E = 25 GPa, nu = 1/4", iso_1_4, strain);
  check("cubic NaCl", nacl, strain);
  check("cubic NaCl rotated by 25 degrees", nacl_25, strain);
  check("orthotropic (note 004)", orthotropic, strain);
  check("orthotropic (note 004) rotated by 30 degrees", orthotropic_30, strain);
  check("isotropic E = 30 GPa, nu = 1/3", iso_1_3, stress);

  check_closed_form("isotropic nu = 1/4, plane strain", iso_1_4);
  check_closed_form("cubic NaCl, plane strain", nacl);

  // Plane stress of a 3D material with Cauchy's relations: C'66 != C'12.
  check_refused("cubic NaCl in plane stress", nacl, stress);
  check_refused("isotropic nu = 0.3 in plane strain",
                {{"Symmetry", "isotropic"},
                 {"Young's modulus", "25e9"},
                 {"Poisson's ratio", "0.3"}},
                strain);
  Entries symmetrized = nacl;
  symmetrized.emplace_back("Cauchy relations", "symmetrize");
  perideal::AnisotropicBondBased<2> model;
  pd_tests::parse_model(model, symmetrized);
  Lattice    lattice(model, stress);
  const auto C = model.elasticity_tensor();
  deallog << "cubic NaCl in plane stress, symmetrized: C'11 = " << C[0][0][0][0] / 1e9
          << " GPa, C'12 = C'66 = " << C[0][0][1][1] / 1e9
          << " GPa (the FE side's C'12 = " << pd_tests::fe_voigt_stiffness(nacl, stress)(0, 1) / 1e9
          << ", C'66 = " << pd_tests::fe_voigt_stiffness(nacl, stress)(2, 2) / 1e9 << " GPa)"
          << std::endl;
}
