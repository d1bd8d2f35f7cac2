// Linear softening of PMB bonds (<Material/critical stretch/Failure law> = linear softening,
// issue #40 part 2), in the saw-tooth form of the sequentially linear control:
// - the law (BondSoftening, n = 4 and 2, N = 8 and 3): the teeth x_i = n^(i/N), mu_i =
//   (n/x_i - 1)/(n - 1), the drops at x~_i = sqrt(x_i x_{i+1}); each tooth's dissipated
//   (mu_i - mu_{i+1}) x~_i^2 against the envelope's exact integral n (x_{i+1} - x_i)/(n - 1) of
//   x^2 (-dmu/dx), their sum n (the work 1/2 k s0 s1 |xi| = 1/2 k s_G^2 |xi| of the brittle
//   bond), and each tooth's peak force n^(1/(2N)) times the envelope's at the start x_i of its
//   secant (the largest force of the path n^(1/(2N)) k s0);
// - one bond of the model (two particles) pulled along itself through its teeth: the force
//   at each drop (before and after) from compute_forces() against mu k s, the work along the
//   saw-tooth path and the model's released energy both equal to 1/2 k s_G^2 |xi|, and the
//   bond broken after N drops;
// - a cleave of the lattice (book partial volumes, energy surface correction, the lattice
//   calibration of the fracture energy): the uniform expansion u = eps x held at each tooth's
//   drop (every bond at the same stretch), the bonds across the middle plane lowered one tooth
//   there; the drops of the energy of a window of interior particles (compute_forces(), i.e.
//   the kernel's lane coefficients) per unit area sum to G = G_c within 1e-2 (the brittle
//   lattice's G: lattice_fracture_01), and the energy the model reports as released equals the
//   drop of the whole box's energy. 2D (plane stress) m = 2, 3, 4; 3D m = 3.
#include <perideal/pd/bond_based.h>

#include "../tests.h"
#include "pd_tests.h"

#include <cmath>
#include <iomanip>
#include <limits>

using namespace dealii;

constexpr double dx = 1e-3, thickness = 1e-3, G0 = 1000.;

// The law's teeth, their energies and the ripple of their peaks.
void
check_law(const double n, const unsigned int N)
{
  const perideal::BondSoftening law(n, N);
  deallog << "law n = " << n << ", N = " << N << ": s0 = " << law.elastic_limit(1.) << " s_G"
          << std::endl;
  double total = 0., worst_energy = 0., worst_ripple = 0.;
  for (unsigned int i = 0; i < N; ++i)
    {
      const double x0 = std::pow(n, double(i) / N), x1 = std::pow(n, double(i + 1) / N);
      const double exact = n * (x1 - x0) / (n - 1.);
      worst_energy       = std::max(worst_energy, std::abs(law.tooth_dissipation(i) - exact));
      total += law.tooth_dissipation(i);
      const double peak = law.secant_factor(i) * law.drop_stretch(i);
      worst_ripple =
        std::max(worst_ripple, std::abs(peak / law.envelope(x0) / std::pow(n, 0.5 / N) - 1.));
      deallog << "  tooth " << i << ": mu = " << std::setprecision(5) << law.secant_factor(i)
              << ", drop at x = " << law.drop_stretch(i) << ", force there " << peak
              << " (envelope at x_i " << law.envelope(x0) << "), dissipated "
              << law.tooth_dissipation(i) << std::setprecision(6) << std::endl;
    }
  deallog << "  sum of the teeth's energies / (1/2 k s0^2 |xi|) = " << total << " (n = " << n
          << ") " << pd_tests::ok(std::abs(total - n) < 1e-12 * n)
          << "; each tooth against the envelope's integral "
          << pd_tests::ok(worst_energy < 1e-12 * n)
          << "; each peak n^(1/(2N)) = " << std::pow(n, 0.5 / N)
          << " times the envelope at the start of its secant " << pd_tests::ok(worst_ripple < 1e-12)
          << std::endl;
}

// A PMB model of @p ps with horizon m dx and the law @p law; with @p surface_correction, the
// energy surface correction and the lattice calibration of the fracture energy.
template <int dim>
void
set_up(perideal::BondBased<dim>      &model,
       perideal::ParticleSystem<dim> &ps,
       const double                   m,
       const bool                     surface_correction,
       const perideal::BondSoftening &law)
{
  pd_tests::parse_model(model, {{"Young's modulus", "200e9"}});
  auto context = pd_tests::model_context(m * dx,
                                         thickness,
                                         dim == 2 ? perideal::PlanarAssumption::plane_stress :
                                                    perideal::PlanarAssumption::three_dimensional,
                                         surface_correction);
  // The lattice calibration needs interior particles (not the two of one bond).
  context.lattice_fracture = surface_correction;
  context.softening        = law;
  model.initialize(ps, context);
}

// The sum over the ranks of the owned particles' energy (where @p in_window) at @p u.
template <int dim, typename Window>
double
energy(perideal::ParticleSystem<dim>  &ps,
       perideal::BondBased<dim>       &model,
       const perideal::ParticleVector &u,
       const Window                   &in_window)
{
  perideal::ParticleVector f;
  ps.reinit_vector(f, dim);
  std::vector<double> w;
  model.compute_forces(ps, u, f, &w, std::numeric_limits<double>::infinity());
  double local = 0.;
  for (unsigned int i = 0; i < ps.n_owned(); ++i)
    if (in_window(ps.positions()[i]))
      local += w[i] * ps.volumes()[i];
  return Utilities::MPI::sum(local, MPI_COMM_WORLD);
}

// One bond pulled along itself through its teeth.
void
check_one_bond(const perideal::BondSoftening &law)
{
  perideal::ParticleSystem<2>                    ps(MPI_COMM_WORLD);
  typename perideal::ParticleSystem<2>::Settings s;
  s.spacing   = dx;
  s.horizon   = 1.5 * dx;
  s.thickness = thickness;
  pd_tests::generate_box<2>(ps, s, Point<2>(), Point<2>(2. * dx, dx));
  perideal::BondBased<2> model;
  set_up(model, ps, 1.5, false, law);
  const double s_G = model.critical_stretch(G0);
  // k of the one bond, on the rank(s) that store it.
  double k = 0.;
  for (unsigned int i = 0; i < ps.n_owned(); ++i)
    for (unsigned int b = ps.bonds().row_start[i]; b < ps.bonds().row_start[i + 1]; ++b)
      k = model.pair_coefficient(ps, i, b);
  k = Utilities::MPI::max(k, MPI_COMM_WORLD);

  perideal::ParticleVector u, f;
  ps.reinit_vector(u, 2);
  ps.reinit_vector(f, 2);
  // The pair force: |f_i| V_i at either end, summed over the owned ends and halved.
  const auto pair_force = [&]() {
    model.compute_forces(ps, u, f, nullptr, std::numeric_limits<double>::infinity());
    double local = 0.;
    for (unsigned int i = 0; i < ps.n_owned(); ++i)
      local += 0.5 * std::abs(f.local_element(2 * i)) * ps.volumes()[i];
    return Utilities::MPI::sum(local, MPI_COMM_WORLD);
  };
  const auto set_stretch = [&](const double stretch) {
    for (unsigned int i = 0; i < ps.n_local(); ++i)
      u.local_element(2 * i) = stretch * (ps.positions()[i][0] - 0.5 * dx);
  };
  const double L    = dx;
  double       work = 0., released = 0., last_stretch = 0., last_force = 0., worst_force = 0.;
  unsigned int drops = 0;
  for (;;)
    {
      // The stretch at which the bond reaches its limit: s_G / breaking factor.
      double limit = std::numeric_limits<double>::infinity();
      for (std::size_t b = 0; b < ps.bonds().size(); ++b)
        if (ps.bonds().intact[b] == 1)
          limit = s_G / model.breaking_factors(ps)[b];
      limit = Utilities::MPI::min(limit, MPI_COMM_WORLD);
      if (!std::isfinite(limit))
        break;
      set_stretch(limit);
      const double peak = pair_force();
      work += 0.5 * (last_force + peak) * (limit - last_stretch) * L;
      const double mu = law.secant_factor(drops);
      worst_force     = std::max(worst_force, std::abs(peak - mu * k * limit) / (k * limit));
      for (std::size_t b = 0; b < ps.bonds().size(); ++b)
        model.limit_reached(ps, u, b);
      released += Utilities::MPI::sum(model.released_energy(ps, u), MPI_COMM_WORLD);
      last_force   = pair_force();
      last_stretch = limit;
      worst_force =
        std::max(worst_force,
                 std::abs(last_force - law.secant_factor(drops + 1) * k * limit) / (k * limit));
      ++drops;
      deallog << "  drop " << drops << ": s / s_G = " << std::setprecision(5) << limit / s_G
              << ", force / (k s0) " << peak / (k * law.elastic_limit(s_G)) << " -> "
              << last_force / (k * law.elastic_limit(s_G)) << std::setprecision(6) << std::endl;
    }
  const double brittle = 0.5 * k * s_G * s_G * L;
  deallog << "one bond: " << drops << " drops " << pd_tests::ok(drops == law.teeth())
          << ", forces mu k s " << pd_tests::ok(worst_force < 1e-10)
          << ", work / (1/2 k s_G^2 |xi|) = " << work / brittle << " "
          << pd_tests::ok(std::abs(work / brittle - 1.) < 1e-10)
          << ", released / work = " << released / work << " "
          << pd_tests::ok(std::abs(released / work - 1.) < 1e-10) << std::endl;
}

// The cleave of the lattice: G / G_c of the window and the released energy of the box.
template <int dim>
void
check_cleave(const double m, const perideal::BondSoftening &law)
{
  perideal::ParticleSystem<dim>                    ps(MPI_COMM_WORLD);
  typename perideal::ParticleSystem<dim>::Settings s;
  s.spacing         = dx;
  s.horizon         = m * dx;
  s.thickness       = thickness;
  const double n    = dim == 2 ? 12. : 4.;
  const double side = (n + 2. * std::ceil(2. * m)) * dx, c = 0.5 * side;
  Point<dim>   upper;
  for (unsigned int d = 0; d < dim; ++d)
    upper[d] = side;
  pd_tests::generate_box<dim>(ps, s, Point<dim>(), upper);
  perideal::BondBased<dim> model;
  set_up(model, ps, m, true, law);
  const double s_G = model.critical_stretch(G0);

  const auto &x         = ps.positions();
  const auto  in_window = [&](const Point<dim> &p) {
    for (unsigned int b = 0; b + 1 < dim; ++b)
      if (std::abs(p[b] - c) >= 0.5 * n * dx)
        return false;
    return true;
  };
  const auto               everywhere = [](const Point<dim> &) { return true; };
  perideal::ParticleVector u;
  ps.reinit_vector(u, dim);
  double      G = 0., released = 0., box_drop = 0.;
  const auto &bonds = ps.bonds();
  for (unsigned int t = 0; t < law.teeth(); ++t)
    {
      const double eps = s_G * law.drop_over_brittle(t);
      for (unsigned int i = 0; i < ps.n_local(); ++i)
        for (unsigned int d = 0; d < dim; ++d)
          u.local_element(i * dim + d) = eps * x[i][d];
      const double window_before = energy<dim>(ps, model, u, in_window);
      const double box_before    = energy<dim>(ps, model, u, everywhere);
      for (unsigned int i = 0; i < ps.n_owned(); ++i)
        for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
          if (bonds.intact[b] == 1 &&
              (x[i][dim - 1] - c) * (x[bonds.neighbor[b]][dim - 1] - c) < 0.)
            model.limit_reached(ps, u, b);
      released += Utilities::MPI::sum(model.released_energy(ps, u), MPI_COMM_WORLD);
      G += window_before - energy<dim>(ps, model, u, in_window);
      box_drop += box_before - energy<dim>(ps, model, u, everywhere);
    }
  G /= std::pow(n * dx, dim - 1) * (dim == 2 ? thickness : 1.);
  unsigned long left = 0;
  for (unsigned int i = 0; i < ps.n_owned(); ++i)
    for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
      if (bonds.intact[b] == 1 && (x[i][dim - 1] - c) * (x[bonds.neighbor[b]][dim - 1] - c) < 0.)
        ++left;
  left = Utilities::MPI::sum(left, MPI_COMM_WORLD);
  deallog << dim << "D cleave, m = " << m << ": G/G_c = " << std::setprecision(5) << G / G0 << " "
          << pd_tests::ok(std::abs(G / G0 - 1.) < 1e-2) << ", released / energy drop "
          << released / box_drop << " " << pd_tests::ok(std::abs(released / box_drop - 1.) < 1e-10)
          << std::setprecision(6) << ", crossing bonds left intact " << left << " "
          << pd_tests::ok(left == 0) << std::endl;
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();
  check_law(4., 8);
  check_law(2., 3);
  const perideal::BondSoftening law(4., 8);
  check_one_bond(law);
  for (const double m : {2.015, 3.015, 4.015})
    check_cleave<2>(m, law);
  check_cleave<3>(3.015, law);
}
