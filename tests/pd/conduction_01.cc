// The bond-based conduction model (Bobaru & Duangpanya 2010): its micro-conductivity against a
// quadrature of the continuum functional, a linear temperature T = g . x (interior functional
// k |g|^2 / 2, heat source 0 and heat flux -k g to round-off with the surface correction; the
// surface values printed), the rate of a sine mode on the interior lattice against the exact
// lattice sum (the peridynamic series' nonlocal factor), its linearization against its heat
// flows, and a pre-crack that insulates; 2D and 3D, on 1 and 2 ranks.

#include <deal.II/base/mpi.h>
#include <deal.II/base/numbers.h>
#include <deal.II/base/utilities.h>

#include <perideal/pd/bond_based_conduction.h>
#include <perideal/pd/pre_crack.h>

#include "../tests.h"
#include "pd_tests.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <iomanip>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace
{
  using dealii::deallog;
  using pd_tests::Body;
  using pd_tests::ok;
  const double pi  = dealii::numbers::PI;
  const double k   = 45.;  // W/(m K)
  const double h   = 1e-3; // thickness [m]
  const double dx  = 1e-3; // lattice spacing [m]
  const double inf = std::numeric_limits<double>::infinity();

  template <int dim>
  std::unique_ptr<perideal::BondBasedConduction<dim>>
  make_model(perideal::ParticleSystem<dim> &ps, const double delta, const bool correction)
  {
    auto model = std::make_unique<perideal::BondBasedConduction<dim>>();
    pd_tests::parse_model(*model, {{"Conductivity", "45"}, {"Specific heat", "460"}});
    model->initialize(ps,
                      pd_tests::model_context(delta,
                                              h,
                                              dim == 2 ?
                                                perideal::PlanarAssumption::plane_strain :
                                                perideal::PlanarAssumption::three_dimensional,
                                              correction));
    return model;
  }

  template <int dim>
  perideal::ParticleVector
  field(const perideal::ParticleSystem<dim>                     &ps,
        const std::function<double(const dealii::Point<dim> &)> &T)
  {
    perideal::ParticleVector v;
    ps.reinit_vector(v, 1);
    for (unsigned int i = 0; i < ps.n_local(); ++i)
      v.local_element(i) = T(ps.positions()[i]);
    return v;
  }

  double
  max_all(const double value)
  {
    return dealii::Utilities::MPI::max(value, MPI_COMM_WORLD);
  }

  // 1. kappa: 1/4 kappa int n_x^2 |xi| dV (midpoint rule in polar/spherical coordinates) is k/2,
  // the functional of T = x.
  template <int dim>
  void
  check_constant()
  {
    Body<dim>    body(8, dx, 3.015, perideal::PartialVolume::none, h);
    const auto   model = make_model<dim>(body.ps, body.delta, false);
    const double kappa = model->micro_conductivity(), delta = body.delta;
    const int    n      = 400;
    double       moment = 0.;
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b)
        {
          const double r = (a + 0.5) * delta / n, dr = delta / n, t = (b + 0.5) * pi / n;
          moment += dim == 2 ?
                      std::pow(std::cos(2. * t), 2) * r * h * r * dr * 2. * pi / n :
                      std::pow(std::sin(t), 2) * pi * r * r * r * std::sin(t) * dr * pi / n;
        }
    deallog << dim << "D: kappa = " << kappa
            << ", |1/4 kappa int n_x^2 |xi| dV / (k/2) - 1| < 1e-4 "
            << ok(std::abs(0.25 * kappa * moment / (0.5 * k) - 1.) < 1e-4) << std::endl;
  }

  // 2. A linear temperature along a skew g, with the surface correction: interior particles
  // (depth >= 6 layers, two horizons: their neighbours have full families too, so every bond
  // has the interior correction factor) have the functional k |g|^2 / 2, no heat source and the
  // heat flux -k g; at the surface the functional of the axis fields T = s x_a and the flux of
  // T = s x through the faces normal to x are printed.
  template <int dim>
  void
  check_linear(const int n)
  {
    Body<dim>              body(n, dx, 3.015, perideal::PartialVolume::book, h);
    auto                  &ps    = body.ps;
    const auto             model = make_model<dim>(ps, body.delta, true);
    dealii::Tensor<1, dim> g;
    for (unsigned int d = 0; d < dim; ++d)
      g[d] = 100. * (1. + 0.5 * d); // K/m
    auto                     T = field<dim>(ps, [&](const dealii::Point<dim> &x) { return g * x; });
    perideal::ParticleVector q;
    ps.reinit_vector(q, 1);
    std::vector<double> functional;
    model->compute_forces(ps, T, q, &functional, inf);
    const auto   flux = model->derived_fields(ps, T)[0].values;
    const double W = 0.5 * k * g.norm_square(), scale = k * g.norm() / dx;
    double       w_error = 0., q_error = 0., flux_error = 0.;
    for (unsigned int i = 0; i < ps.n_owned(); ++i)
      if (body.depth(i) >= 6)
        {
          w_error = std::max(w_error, std::abs(functional[i] / W - 1.));
          q_error = std::max(q_error, std::abs(q.local_element(i)) / scale);
          for (unsigned int d = 0; d < dim; ++d)
            flux_error =
              std::max(flux_error, std::abs(flux[i * dim + d] + k * g[d]) / (k * g.norm()));
        }
    deallog << dim << "D linear T, interior: |W/(k|g|^2/2) - 1| < 1e-10 "
            << ok(max_all(w_error) < 1e-10) << ", |q| dx/(k|g|) < 1e-10 "
            << ok(max_all(q_error) < 1e-10) << ", |phi + k g|/(k|g|) < 1e-10 "
            << ok(max_all(flux_error) < 1e-10) << std::endl;

    // The surface: T = s x_a per axis; the x faces' flux of T = s x.
    double w_surface = 0., flux_face = 0.;
    for (unsigned int a = 0; a < dim; ++a)
      {
        const auto Ta = field<dim>(ps, [&](const dealii::Point<dim> &x) { return 100. * x[a]; });
        model->compute_forces(ps, Ta, q, &functional, inf);
        for (unsigned int i = 0; i < ps.n_owned(); ++i)
          w_surface = std::max(w_surface, std::abs(functional[i] / (0.5 * k * 100. * 100.) - 1.));
      }
    const auto Tx    = field<dim>(ps, [&](const dealii::Point<dim> &x) { return 100. * x[0]; });
    const auto phi_x = model->derived_fields(ps, Tx)[0].values;
    for (unsigned int i = 0; i < ps.n_owned(); ++i)
      {
        const double ratio = -phi_x[i * dim] / (k * 100.);
        const int    layer = static_cast<int>(std::lround(ps.positions()[i][0] / dx - 0.5));
        if (layer == 0 || layer == n - 1)
          flux_face = std::max(flux_face, std::abs(ratio - 1.));
      }
    deallog << std::fixed << std::setprecision(4) << dim
            << "D surface (correction on): largest |W/(k s^2/2) - 1| of T = s x_a "
            << max_all(w_surface) << ", largest |phi_x/(-k s) - 1| on the faces normal to x "
            << max_all(flux_face) << std::defaultfloat << std::setprecision(6) << std::endl;
  }

  // 3. The sine mode T = sin(K x) is an eigenfunction of the interior lattice operator (no
  // partial volumes, no correction): q_i = -lambda T_i, lambda = kappa sum_j (1 - cos(K xi_x))
  // / |xi| V_j, the nonlocal factor of the peridynamic series solution.
  template <int dim>
  void
  check_sine_mode(const int n)
  {
    Body<dim>    body(n, dx, 3.015, perideal::PartialVolume::none, h);
    auto        &ps    = body.ps;
    const auto   model = make_model<dim>(ps, body.delta, false);
    const double K     = 2. * pi / (n * dx);
    // The lattice sum over the offsets within the horizon.
    const double volume = dim == 2 ? dx * dx * h : dx * dx * dx;
    const int    reach  = static_cast<int>(std::floor(body.delta / dx));
    double       sum    = 0.;
    pd_tests::for_each_lattice_offset<dim>(reach, [&](const std::array<int, dim> &v) {
      double r2 = 0.;
      for (unsigned int d = 0; d < dim; ++d)
        r2 += v[d] * v[d] * dx * dx;
      if (r2 > 0. && r2 <= body.delta * body.delta)
        sum += (1. - std::cos(K * v[0] * dx)) / std::sqrt(r2) * volume;
    });
    const double lambda = model->micro_conductivity() * sum;
    auto T = field<dim>(ps, [&](const dealii::Point<dim> &x) { return std::sin(K * x[0]); });
    perideal::ParticleVector q;
    ps.reinit_vector(q, 1);
    model->compute_forces(ps, T, q, nullptr, inf);
    double error = 0.;
    for (unsigned int i = 0; i < ps.n_owned(); ++i)
      if (body.depth(i) >= 3)
        error =
          std::max(error, std::abs(q.local_element(i) + lambda * T.local_element(i)) / lambda);
    deallog << dim << "D sine mode, K delta = " << std::setprecision(4) << K * body.delta
            << ": lambda / (k K^2) = " << lambda / (k * K * K) << std::setprecision(6)
            << ", interior |q + lambda T| / lambda < 1e-10 " << ok(max_all(error) < 1e-10)
            << std::endl;
  }

  // 4. Linearization (the steady conductance matrix) against the heat flows of a random field,
  // and a pre-crack across the block that insulates: T = 1 on one side and 0 on the other gives
  // no heat flow anywhere (with the crack; without it, a flow).
  template <int dim>
  void
  check_linearization_and_crack(const int n)
  {
    Body<dim>                body(n, dx, 3.015, perideal::PartialVolume::book, h);
    auto                    &ps    = body.ps;
    const auto               model = make_model<dim>(ps, body.delta, true);
    perideal::ParticleVector T;
    ps.reinit_vector(T, 1);
    for (unsigned int i = 0; i < ps.n_local(); ++i)
      T.local_element(i) = pd_tests::random_number(body.lattice_index(i));
    perideal::ParticleVector q, q_linear;
    ps.reinit_vector(q, 1);
    model->compute_forces(ps, T, q, nullptr, inf);
    perideal::LinearizedModel linearized;
    model->linearize(ps, linearized);
    pd_tests::linearized_forces(ps, linearized, T, q_linear);
    double difference = 0., largest = 0.;
    for (unsigned int i = 0; i < ps.n_owned(); ++i)
      {
        difference = std::max(difference, std::abs(q.local_element(i) - q_linear.local_element(i)));
        largest    = std::max(largest, std::abs(q.local_element(i)));
      }
    deallog << dim << "D linearization: |q_linear - q| / max|q| < 1e-12 "
            << ok(max_all(difference) / max_all(largest) < 1e-12) << std::endl;

    // The crack: the plane x = n dx / 2 (between two lattice layers) through the whole block.
    perideal::PreCrack<dim> crack;
    const double            c = 0.5 * n * dx, out = 2. * n * dx;
    if constexpr (dim == 2)
      crack.vertices = {{dealii::Point<2>(c, -out), dealii::Point<2>(c, out)}};
    else
      crack.vertices = {{dealii::Point<3>(c, -out, -out),
                         dealii::Point<3>(c, 3. * out, -out),
                         dealii::Point<3>(c, -out, 3. * out)}};
    for (const bool cracked : {false, true})
      {
        perideal::ParticleSystem<dim>                    cut(MPI_COMM_WORLD);
        typename perideal::ParticleSystem<dim>::Settings s;
        s.spacing        = dx;
        s.horizon        = body.delta;
        s.thickness      = h;
        s.partial_volume = perideal::PartialVolume::book;
        dealii::Point<dim> upper;
        for (unsigned int d = 0; d < dim; ++d)
          upper[d] = n * dx;
        pd_tests::generate_box<dim>(cut,
                                    s,
                                    dealii::Point<dim>(),
                                    upper,
                                    cracked ? std::vector<perideal::PreCrack<dim>>{crack} :
                                              std::vector<perideal::PreCrack<dim>>{});
        const auto cut_model = make_model<dim>(cut, body.delta, true);
        const auto step =
          field<dim>(cut, [&](const dealii::Point<dim> &x) { return x[0] < c ? 1. : 0.; });
        perideal::ParticleVector flow;
        cut.reinit_vector(flow, 1);
        cut_model->compute_forces(cut, step, flow, nullptr, inf);
        double largest_flow = 0.;
        for (unsigned int i = 0; i < cut.n_owned(); ++i)
          largest_flow = std::max(largest_flow, std::abs(flow.local_element(i)));
        largest_flow = max_all(largest_flow);
        deallog << dim << "D temperature step across x = L/2, "
                << (cracked ? "pre-cracked: no heat flow (exactly 0) " :
                              "uncracked: heat flows (> 0) ")
                << ok(cracked ? largest_flow == 0. : largest_flow > 0.) << std::endl;
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();
  check_constant<2>();
  check_constant<3>();
  check_linear<2>(16);
  check_linear<3>(13);
  check_sine_mode<2>(16);
  check_sine_mode<3>(10);
  check_linearization_and_crack<2>(12);
  check_linearization_and_crack<3>(8);
}
