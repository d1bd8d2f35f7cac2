// The anisotropic PD plane-stress model (seed 004, state form, option M): homogeneous strains
// reproduce the FE side's plane-stress tensor (the reduced stiffness C' = C - C_ab33 C_33cd /
// C_3333) at an interior particle to round-off with the discrete calibration, and its
// out-of-plane strain eps_33 = -C_33ab eps_ab / C_3333 (isotropic nu = 1/4, cubic NaCl, the note's
// orthotropic tensor and its C' values, rotated in the plane); the continuum calibration's error;
// the interior force of a homogeneous strain vanishes; the plane-wave speeds of the interior
// operator against the Christoffel equation of C'; bad input is refused with its entry.
#include <deal.II/base/numbers.h>
#include <deal.II/base/parameter_handler.h>

#include <perideal/base/elasticity.h>
#include <perideal/pd/anisotropic_plane_stress.h>

#include "../tests.h"
#include "pd_tests.h"

#include <iomanip>
#include <limits>

using namespace dealii;

using Entries = std::vector<std::pair<std::string, std::string>>;

const unsigned int voigt_pair[3][2] = {{0, 0}, {1, 1}, {0, 1}};
const double       dx = 1e-3, horizon = 3. * dx;

struct Lattice
{
  Lattice(perideal::AnisotropicPlaneStress &model,
          const double                      thickness = 1e-3,
          const perideal::PlanarAssumption  planar    = perideal::PlanarAssumption::plane_stress)
    : ps(MPI_COMM_WORLD)
  {
    perideal::ParticleSystem<2>::Settings s;
    s.spacing        = dx;
    s.horizon        = horizon;
    s.thickness      = thickness;
    s.partial_volume = perideal::PartialVolume::geometric;
    pd_tests::generate_box<2>(ps, s, Point<2>(), Point<2>(n * dx, n * dx));
    model.initialize(ps, pd_tests::model_context(s.horizon, thickness, planar, true));
  }
  const int                   n = 21;
  perideal::ParticleSystem<2> ps;
};

struct Measured
{
  FullMatrix<double>    C{3, 3};
  std::array<double, 3> eps33{};
  double                force = 0.;
};

// The Voigt stiffness at the centre particle from energy densities (as tests/pd/aniso_2d_01), the
// out-of-plane strain of the unit strains e_I (scaled) and the largest interior force density of
// them relative to C11 * strain / dx.
Measured
measure(perideal::AnisotropicPlaneStress &model)
{
  Lattice      lattice(model);
  auto        &ps     = lattice.ps;
  const double centre = 0.5 * lattice.n * dx;
  Measured     result;
  const auto   energy = [&](const std::array<double, 3> &strain, double *eps33) {
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
    const auto fields = model.derived_fields(ps, u);
    double     local = 0., local_eps = 0., force = 0.;
    for (unsigned int i = 0; i < ps.n_owned(); ++i)
      {
        const auto d = ps.positions()[i] - Point<2>(centre, centre);
        if (d.norm() < 0.6 * dx)
          {
            local     = w[i];
            local_eps = fields[0].values[i];
          }
        // Interior: the force uses the neighbours' families, complete 2 delta from the edges.
        if (std::abs(d[0]) < centre - 2. * horizon && std::abs(d[1]) < centre - 2. * horizon)
          force = std::max(
            {force, std::abs(f.local_element(2 * i)), std::abs(f.local_element(2 * i + 1))});
      }
    if (eps33 != nullptr)
      *eps33 = Utilities::MPI::sum(local_eps, MPI_COMM_WORLD);
    result.force = std::max(result.force, Utilities::MPI::max(force, MPI_COMM_WORLD));
    return Utilities::MPI::sum(local, MPI_COMM_WORLD);
  };
  std::array<double, 3> W;
  for (unsigned int I = 0; I < 3; ++I)
    {
      std::array<double, 3> e{};
      e[I]           = 1e-3;
      W[I]           = energy(e, &result.eps33[I]);
      result.C(I, I) = 2. * W[I] / 1e-6;
      result.eps33[I] /= 1e-3;
    }
  for (unsigned int I = 0; I < 3; ++I)
    for (unsigned int J = I + 1; J < 3; ++J)
      {
        std::array<double, 3> e{};
        e[I] = e[J]    = 1e-3;
        result.C(I, J) = result.C(J, I) = (energy(e, nullptr) - W[I] - W[J]) / 1e-6;
      }
  return result;
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
check(const std::string &label, const Entries &entries)
{
  ParameterHandler prm;
  perideal::ElasticMaterial::declare_parameters(prm);
  for (const auto &entry : entries)
    prm.set(entry.first, entry.second);
  perideal::ElasticMaterial material;
  material.parse_parameters(prm, "Finite elements/Elasticity");
  const auto            C2 = material.tensor<2>(perideal::PlanarAssumption::plane_stress);
  const auto            C3 = material.tensor<3>(perideal::PlanarAssumption::three_dimensional);
  FullMatrix<double>    reference(3, 3);
  std::array<double, 3> eps33;
  for (unsigned int I = 0; I < 3; ++I)
    {
      const unsigned int a = voigt_pair[I][0], b = voigt_pair[I][1];
      for (unsigned int J = 0; J < 3; ++J)
        reference(I, J) = C2[a][b][voigt_pair[J][0]][voigt_pair[J][1]];
      // eps_33 of the unit (engineering) strain e_I.
      eps33[I] = -(a == b ? 1. : 2. * 0.5) * C3[2][2][a][b] / C3[2][2][2][2];
    }

  perideal::AnisotropicPlaneStress discrete, continuum;
  pd_tests::parse_model(discrete, entries);
  Entries continuum_entries = entries;
  continuum_entries.emplace_back("Calibration", "continuum");
  pd_tests::parse_model(continuum, continuum_entries);
  const Measured d = measure(discrete), c = measure(continuum);
  double         eps_error = 0., eps_error_c = 0.;
  for (unsigned int I = 0; I < 3; ++I)
    {
      eps_error   = std::max(eps_error, std::abs(d.eps33[I] - eps33[I]));
      eps_error_c = std::max(eps_error_c, std::abs(c.eps33[I] - eps33[I]));
    }
  const double scale = std::max({std::abs(eps33[0]), std::abs(eps33[1]), 1e-300});
  deallog << label << ": C'11 = " << std::setprecision(6) << reference(0, 0) / 1e9
          << " GPa, C'22 = " << reference(1, 1) / 1e9 << " GPa, C'12 = " << reference(0, 1) / 1e9
          << " GPa, C'66 = " << reference(2, 2) / 1e9 << " GPa, eps33/eps11 = " << eps33[0]
          << ", eps33/eps22 = " << eps33[1] << std::endl;
  deallog << "  discrete: C' error (tolerance 1e-12) "
          << pd_tests::ok(relative_error(d.C, reference) < 1e-12)
          << ", eps33 error (tolerance 1e-12) " << pd_tests::ok(eps_error < 1e-12 * scale)
          << ", interior force / (C'11 eps / dx) (tolerance 1e-10) "
          << pd_tests::ok(d.force < 1e-10 * reference(0, 0) * 1e-3 / dx)
          << ", symbol smallest/largest eigenvalue " << std::setprecision(3)
          << discrete.symbol_minimum() << std::endl;
  deallog << "  continuum: C' error " << relative_error(c.C, reference) << ", eps33 error ";
  if (eps_error_c < 1e-12 * scale)
    deallog << "< 1e-12";
  else
    deallog << eps_error_c / scale;
  deallog << " (logged lattice error " << continuum.continuum_lattice_error() << ")"
          << std::setprecision(6) << std::endl;
  std::cerr << label << " discrete error " << relative_error(d.C, reference) << " eps "
            << eps_error / scale << " force " << d.force / (reference(0, 0) * 1e-3 / dx)
            << std::endl;

  perideal::AnisotropicPlaneStress waves;
  pd_tests::parse_model(waves, entries);
  Lattice      lattice(waves);
  const double centre = 0.5 * lattice.n * dx;
  const double error  = wave_speed_error(waves, lattice.ps, Point<2>(centre, centre), C2);
  deallog << "  plane-wave speeds (wavelength 60 dx) against the Christoffel equation of C', "
          << "largest deviation over 6 directions (tolerance 2 %): " << std::setprecision(2)
          << 100. * error << " % " << pd_tests::ok(error < 0.02) << std::setprecision(6)
          << std::endl;
}

void
check_refused(const std::string               &label,
              const Entries                   &entries,
              const double                     thickness = 1e-3,
              const perideal::PlanarAssumption planar    = perideal::PlanarAssumption::plane_stress)
{
  try
    {
      perideal::AnisotropicPlaneStress model;
      pd_tests::parse_model(model, entries);
      Lattice lattice(model, thickness, planar);
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
  const Entries iso  = {{"Symmetry", "isotropic"},
                        {"Young's modulus", "25e9"},
                        {"Poisson's ratio", "0.25"}};
  const Entries nacl = {{"Symmetry", "cubic"}, {"Cubic constants", "49.1e9, 12.8e9, 12.8e9"}};
  // Seed note 004, sec. 3.3, times 10 GPa: C' = 34/3, 53/6, 8/3, 3 (x 10 GPa),
  // eps33 = -(2 eps11 + eps22)/6.
  const Entries orthotropic = {
    {"Symmetry", "orthotropic"},
    {"Young's moduli", "105283018867.92453, 82058823529.411758, 56363636363.63636"},
    {"Poisson's ratios", "0.30188679245283018, 0.28301886792452829, 0.088235294117647065"},
    {"Shear moduli", "30e9, 20e9, 10e9"}};
  Entries orthotropic_30 = orthotropic;
  orthotropic_30.emplace_back("Orientation", "30, 0, 0");
  Entries nacl_25 = nacl;
  nacl_25.emplace_back("Orientation", "25, 0, 0");
  check("isotropic E = 25 GPa, nu = 1/4 (C' = 16E/15, 4E/15, 2E/5)", iso);
  check("cubic NaCl", nacl);
  check("cubic NaCl rotated by 25 degrees about z", nacl_25);
  check("orthotropic (note 004)", orthotropic);
  check("orthotropic (note 004) rotated by 30 degrees about z", orthotropic_30);

  check_refused("isotropic nu = 0.3",
                {{"Symmetry", "isotropic"},
                 {"Young's modulus", "25e9"},
                 {"Poisson's ratio", "0.3"}});
  Entries tilted = orthotropic;
  tilted.emplace_back("Orientation", "0, 30, 0");
  check_refused("orthotropic tilted out of the plane", tilted);
  check_refused("plate thicker than the horizon", iso, 4e-3);
  check_refused("plane strain", iso, 1e-3, perideal::PlanarAssumption::plane_strain);
}
