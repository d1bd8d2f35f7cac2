// The ordinary state-based antiplane model (seed 000, sec. 3 and 5.1): its constant b against
// the integral of the influence function by quadrature; a uniform shear w = g . x (interior
// W = mu |g|^2 / 2, zero interior force); the seed's per-point surface correction (the shear
// angle of w = s x exact at every particle, the interior factor of seed note 000, sec. 2); the
// force of a quadratic field (mu laplace w, which needs the factor b that the seed's eq. 30
// omits); its linearization against finite differences of its forces and energy, and its
// stiffness bound against the largest eigenvalue; the zero-energy odd-even mode without
// stabilization and its removal with it; bond breaking at the critical slope (irreversible);
// the range of the stabilization entry. 2D and 3D, on 1 and 2 ranks.

#include <deal.II/base/mpi.h>
#include <deal.II/base/numbers.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <perideal/pd/antiplane_bond_based.h>
#include <perideal/pd/antiplane_state_based.h>
#include <perideal/pd/particle_system.h>

#include "../tests.h"
#include "pd_tests.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace
{
  using dealii::deallog;
  using pd_tests::Body;
  using pd_tests::ok;
  const double   pi   = dealii::numbers::PI;
  const double   mu   = 26e9;
  const double   h    = 1e-3;
  const MPI_Comm comm = MPI_COMM_WORLD;
  // The stabilization of the checks with a bond-based term.
  const double alpha = 0.3;

  template <int dim>
  perideal::ModelContext
  context(const Body<dim> &body, const bool correction)
  {
    return pd_tests::model_context(body.delta,
                                   h,
                                   dim == 2 ? perideal::PlanarAssumption::plane_strain :
                                              perideal::PlanarAssumption::three_dimensional,
                                   correction);
  }

  template <int dim>
  std::unique_ptr<perideal::AntiplaneStateBased<dim>>
  make_model(Body<dim> &body, const bool correction, const double stabilization)
  {
    auto model = std::make_unique<perideal::AntiplaneStateBased<dim>>();
    pd_tests::parse_model(*model,
                          {{"Shear modulus", std::to_string(mu)},
                           {"Stabilization", std::to_string(stabilization)}});
    model->initialize(body.ps, context(body, correction));
    return model;
  }

  // w(x) on all local particles.
  template <int dim>
  perideal::ParticleVector
  field(const Body<dim> &body, const std::function<double(const dealii::Point<dim> &)> &w)
  {
    perideal::ParticleVector v;
    body.ps.reinit_vector(v, 1);
    for (unsigned int i = 0; i < body.ps.n_local(); ++i)
      v.local_element(i) = w(body.ps.positions()[i]);
    return v;
  }

  // Force density and energy density of the field w.
  template <int dim>
  void
  evaluate(Body<dim>                      &body,
           perideal::MaterialModel<dim>   &model,
           const perideal::ParticleVector &w,
           perideal::ParticleVector       &f,
           std::vector<double>            &energy,
           const double                    critical_slope = std::numeric_limits<double>::infinity())
  {
    body.ps.reinit_vector(f, 1);
    model.compute_forces(body.ps, w, f, &energy, critical_slope);
  }

  double
  max_all(const double value)
  {
    return dealii::Utilities::MPI::max(value, comm);
  }

  double
  sum_all(const double value)
  {
    return dealii::Utilities::MPI::sum(value, comm);
  }

  // 1. b: the shear angle of w = x in a full horizon is b delta int_H n_x^2 dV = 1, the
  // integral by the midpoint rule in polar/spherical coordinates (not the closed form of the
  // model). The critical slope is the bond-based model's.
  template <int dim>
  void
  check_constants()
  {
    Body<dim>    body(8, 1e-3, 3.015, perideal::PartialVolume::none, h);
    const auto   model  = make_model<dim>(body, false, 0.);
    const double delta  = body.delta;
    const int    n      = 400;
    double       moment = 0.; // int_H n_x^2 dV
    for (int a = 0; a < n; ++a)
      {
        const double r = (a + 0.5) * delta / n, dr = delta / n;
        for (int b = 0; b < n; ++b)
          {
            const double t = (b + 0.5) * pi / n;
            if (dim == 2)
              moment += std::pow(std::cos(2. * t), 2) * h * r * dr * (2. * pi / n);
            else
              // the azimuthal integral of cos^2(phi) is pi (n_x = sin(theta) cos(phi))
              moment += std::pow(std::sin(t), 2) * pi * r * r * std::sin(t) * dr * (pi / n);
          }
      }
    perideal::AntiplaneBondBased<dim> bond_based;
    pd_tests::parse_model(bond_based, {{"Shear modulus", std::to_string(mu)}});
    bond_based.initialize(body.ps, context(body, false));
    const double b = model->shear_angle_constant();
    deallog << dim << "D: b = " << b << ", |b delta int n_x^2 dV - 1| < 1e-4 "
            << ok(std::abs(b * delta * moment - 1.) < 1e-4)
            << "; critical slope that of the bond-based model "
            << ok(model->critical_stretch(0.1) == bond_based.critical_stretch(0.1)) << std::endl;
  }

  // The largest |value_i| over the owned particles at depth >= 6 layers (2 delta: their
  // neighbours have complete families).
  template <int dim>
  double
  interior_max(const Body<dim> &body, const std::function<double(const unsigned int)> &value)
  {
    double largest = 0.;
    for (unsigned int i = 0; i < body.ps.n_owned(); ++i)
      if (body.depth(i) >= 6)
        largest = std::max(largest, std::abs(value(i)));
    return max_all(largest);
  }

  // 2. Uniform shear along a skew direction, with and without stabilization: interior
  // W = mu |g|^2 / 2 and f = 0.
  template <int dim>
  void
  check_uniform_shear(Body<dim> &body)
  {
    dealii::Tensor<1, dim> g;
    g[0] = 0.3e-3;
    g[1] = -0.7e-3;
    if (dim == 3)
      g[dim - 1] = 0.5e-3;
    const double force_scale = mu * g.norm() / body.dx; // a one-spacing jump of the slope
    for (const double stabilization : {0., alpha})
      {
        const auto               model = make_model<dim>(body, true, stabilization);
        perideal::ParticleVector f;
        std::vector<double>      energy;
        evaluate(body, *model, field<dim>(body, [&](const auto &x) { return g * x; }), f, energy);
        const double W_error = interior_max<dim>(body, [&](const unsigned int i) {
          return energy[i] / (0.5 * mu * g.norm_square()) - 1.;
        });
        const double f_max =
          interior_max<dim>(body, [&](const unsigned int i) { return f.local_element(i); });
        deallog << dim << "D uniform shear, alpha = " << stabilization
                << ": interior |W / (mu |g|^2 / 2) - 1| < 1e-10 " << ok(W_error < 1e-10)
                << ", interior |f| < 1e-10 mu |g| / dx " << ok(f_max < 1e-10 * force_scale)
                << std::endl;
      }
  }

  // 3. Surface correction (seed eqs. 50-56): for w = s x, the largest error of W against
  // mu s^2 / 2 and the total energy against the classical one, without and with the
  // correction; with it, the shear angle r_x = s at every particle (exact by construction);
  // the interior factor g = s / r_x of the uncorrected model against seed note 000, sec. 2
  // (2D, delta = 3.015 dx, book partial volumes: 1.151231).
  template <int dim>
  void
  check_surface_correction(Body<dim> &body)
  {
    const double             s = 1e-3;
    const auto               w = field<dim>(body, [&](const auto &x) { return s * x[0]; });
    perideal::ParticleVector f;
    std::vector<double>      energy;
    for (const bool correction : {false, true})
      {
        const auto model = make_model<dim>(body, correction, 0.);
        evaluate(body, *model, w, f, energy);
        double largest = 0., sum = 0., total = 0., angle_error = 0.;
        for (unsigned int i = 0; i < body.ps.n_owned(); ++i)
          {
            largest = std::max(largest, std::abs(energy[i] / (0.5 * mu * s * s) - 1.));
            sum += energy[i] * body.ps.volumes()[i];
            total += 0.5 * mu * s * s * body.ps.volumes()[i];
            angle_error = std::max(angle_error,
                                   std::abs(model->shear_angles().local_element(i * dim) / s - 1.));
          }
        deallog << "  w = s x, " << (correction ? "corrected" : "uncorrected")
                << ": largest |W / (mu s^2 / 2) - 1| " << std::setprecision(3) << max_all(largest)
                << ", total energy / classical " << sum_all(sum) / sum_all(total)
                << std::setprecision(6);
        if (correction)
          deallog << ", r_x = s at every particle (< 1e-12) " << ok(max_all(angle_error) < 1e-12);
        else
          {
            // r_x / s = 1 / g, the same at every interior particle
            const double g = 1. / interior_max<dim>(body, [&](const unsigned int i) {
                               return model->shear_angles().local_element(i * dim) / s;
                             });
            deallog << ", interior factor " << std::setprecision(7) << g << std::setprecision(6);
            if (dim == 2)
              deallog << ", seed note 1.151231 (< 1e-6) " << ok(std::abs(g - 1.151231) < 1e-6);
          }
        deallog << std::endl;
      }
  }

  // 4. Quadratic field w = kappa |x|^2 / 2: f = mu laplace w = dim mu kappa in the interior,
  // with and without stabilization (the seed's eq. 30 without b gives mu laplace w / b).
  template <int dim>
  void
  check_quadratic(Body<dim> &body)
  {
    const double kappa = 1.;
    const auto   w = field<dim>(body, [&](const auto &x) { return 0.5 * kappa * x.norm_square(); });
    for (const double stabilization : {0., alpha})
      {
        const auto               model = make_model<dim>(body, true, stabilization);
        perideal::ParticleVector f;
        std::vector<double>      energy;
        evaluate(body, *model, w, f, energy);
        const double error = interior_max<dim>(body, [&](const unsigned int i) {
          return f.local_element(i) / (dim * mu * kappa) - 1.;
        });
        deallog << "  w = kappa |x|^2 / 2, alpha = " << stabilization
                << ": interior |f / (mu laplace w) - 1| < 1e-9 " << ok(error < 1e-9) << std::endl;
      }
  }

  // 5. Linearization (stabilized: both kinds of rows): the forces of the rows for a random v
  // against the finite difference (f(w0 + eps v) - f(w0)) / eps of the model's forces (exact up
  // to round-off: the model is linear), the rows' energy against the model's; the Gershgorin
  // bound of stiffness_bound() against the largest eigenvalue of the force operator (Rayleigh
  // quotient after power iteration: it must not exceed the bound).
  template <int dim>
  void
  check_linearization(Body<dim> &body)
  {
    const auto  model        = make_model<dim>(body, true, alpha);
    const auto &ps           = body.ps;
    const auto  random_field = [&](const unsigned int seed) {
      perideal::ParticleVector v;
      ps.reinit_vector(v, 1);
      for (unsigned int i = 0; i < ps.n_local(); ++i)
        v.local_element(i) = 1e-6 * pd_tests::random_number(2 * body.lattice_index(i) + seed);
      return v;
    };
    const perideal::ParticleVector w0 = random_field(0), v = random_field(1);
    const double                   eps = 1e-3;
    perideal::ParticleVector       w1  = v;
    w1.sadd(eps, 1., w0);
    w1.update_ghost_values();
    perideal::ParticleVector f0, f1, f_linear;
    std::vector<double>      energy;
    evaluate(body, *model, w0, f0, energy);
    evaluate(body, *model, w1, f1, energy);
    evaluate(body, *model, v, f_linear, energy);
    double total = 0.;
    for (unsigned int i = 0; i < ps.n_owned(); ++i)
      total += energy[i] * ps.volumes()[i];
    total = sum_all(total);
    perideal::LinearizedModel linearized;
    model->linearize(ps, linearized);
    perideal::ParticleVector f_rows;
    const double             energy_rows = pd_tests::linearized_forces(ps, linearized, v, f_rows);
    double                   difference = 0., scale = 0.;
    for (unsigned int i = 0; i < ps.n_owned(); ++i)
      {
        const double fd = (f1.local_element(i) - f0.local_element(i)) / eps;
        difference      = std::max(difference, std::abs(f_rows.local_element(i) - fd));
        scale           = std::max(scale, std::abs(fd));
      }
    deallog << "  linearization: one component per particle " << ok(linearized.n_components() == 1)
            << ", max |f_G - finite difference| / max |f| < 1e-9 "
            << ok(max_all(difference) < 1e-9 * max_all(scale)) << ", |E_G / E - 1| < 1e-12 "
            << ok(std::abs(energy_rows / total - 1.) < 1e-12) << std::endl;

    // Power iteration on A w = -f(w) (symmetric: equal volumes), from v.
    std::vector<double> bound;
    model->stiffness_bound(ps, bound);
    const double largest_bound =
      max_all(bound.empty() ? 0. : *std::max_element(bound.begin(), bound.end()));
    perideal::ParticleVector x        = v, Ax;
    double                   rayleigh = 0.;
    for (unsigned int k = 0; k < 200; ++k)
      {
        evaluate(body, *model, x, Ax, energy);
        Ax *= -1.;
        double xx = 0., xAx = 0.;
        for (unsigned int i = 0; i < ps.n_owned(); ++i)
          {
            xx += x.local_element(i) * x.local_element(i);
            xAx += x.local_element(i) * Ax.local_element(i);
          }
        rayleigh = sum_all(xAx) / sum_all(xx);
        x        = Ax;
        x /= x.l2_norm();
        x.update_ghost_values();
      }
    deallog << "  stiffness bound: largest eigenvalue / Gershgorin bound " << std::setprecision(2)
            << rayleigh / largest_bound << std::setprecision(6) << " <= 1 "
            << ok(rayleigh <= largest_bound) << std::endl;
  }

  // 6. Zero-energy mode: the odd-even field w = e (-1)^(k_1 + ... + k_dim) (k the lattice
  // indices) has r = 0 at every particle with a symmetric family, so the interior energy and
  // force of the unstabilized model vanish; with alpha > 0 they are alpha times those of the
  // bond-based model (surface-corrected the same way), which are positive.
  template <int dim>
  void
  check_zero_energy_mode(Body<dim> &body)
  {
    const double eps     = 1e-6;
    const auto   w       = field<dim>(body, [&](const auto &x) {
      int parity = 0;
      for (unsigned int d = 0; d < dim; ++d)
        parity += static_cast<int>(std::lround(x[d] / body.dx - 0.5));
      return (parity % 2 == 0) ? eps : -eps;
    });
    const double W_scale = 0.5 * mu * std::pow(2. * eps / body.dx, 2);
    const double f_scale = mu * 2. * eps / (body.dx * body.dx);

    perideal::AntiplaneBondBased<dim> bond_based;
    pd_tests::parse_model(bond_based, {{"Shear modulus", std::to_string(mu)}});
    bond_based.initialize(body.ps, context(body, true));
    perideal::ParticleVector f_bond, f;
    std::vector<double>      W_bond, W;
    evaluate(body, bond_based, w, f_bond, W_bond);
    double W_bond_min = std::numeric_limits<double>::infinity();
    for (unsigned int i = 0; i < body.ps.n_owned(); ++i)
      if (body.depth(i) >= 6)
        W_bond_min = std::min(W_bond_min, W_bond[i]);
    W_bond_min = dealii::Utilities::MPI::min(W_bond_min, comm);

    for (const double stabilization : {0., alpha})
      {
        const auto model = make_model<dim>(body, true, stabilization);
        evaluate(body, *model, w, f, W);
        const double W_max =
          interior_max<dim>(body, [&](const unsigned int i) { return W[i]; }) / W_scale;
        const double f_max =
          interior_max<dim>(body, [&](const unsigned int i) { return f.local_element(i); }) /
          f_scale;
        deallog << "  odd-even field, alpha = " << stabilization
                << ": largest interior W / (mu (2 e / dx)^2 / 2) " << std::setprecision(4)
                << (W_max < 1e-20 ? 0. : W_max) << std::setprecision(6);
        if (stabilization == 0.)
          deallog << ", zero energy and force (< 1e-20, < 1e-12) "
                  << ok(W_max < 1e-20 && f_max < 1e-12) << std::endl;
        else
          {
            const double W_error = interior_max<dim>(body, [&](const unsigned int i) {
              return W[i] / (stabilization * W_bond[i]) - 1.;
            });
            const double f_error = interior_max<dim>(body, [&](const unsigned int i) {
              return (f.local_element(i) - stabilization * f_bond.local_element(i)) / f_scale;
            });
            deallog << ", W = alpha W_bond > 0 and f = alpha f_bond (< 1e-12) "
                    << ok(W_bond_min > 0. && W_error < 1e-12 && f_error < 1e-12) << std::endl;
          }
      }
  }

  // 7. Breaking: w = s x with s = 1.55 r_c breaks exactly the bonds with |s n_x| > r_c (with
  // 1.5, the 3D lattice bonds with n_x = 2/3 would lie on the threshold); w = 0 afterwards
  // restores none.
  template <int dim>
  void
  check_breaking(Body<dim> &body)
  {
    const auto               model = make_model<dim>(body, true, 0.);
    const auto              &ps    = body.ps;
    const double             r_c   = model->critical_stretch(0.1);
    const double             s     = 1.55 * r_c;
    perideal::ParticleVector f;
    std::vector<double>      energy;
    const auto               count_broken = [&]() {
      double broken = 0.;
      for (std::size_t b = 0; b < ps.bonds().size(); ++b)
        broken += ps.bond_share(b) * (ps.bonds().intact[b] == 0);
      return std::lround(sum_all(broken));
    };
    evaluate(body,
             *model,
             field<dim>(body, [&](const auto &x) { return s * x[0]; }),
             f,
             energy,
             r_c);
    const auto &bonds    = ps.bonds();
    double      expected = 0.;
    for (unsigned int i = 0; i < ps.n_owned(); ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        {
          const double n_x =
            (ps.positions()[bonds.neighbor[b]][0] - ps.positions()[i][0]) / bonds.length[b];
          expected += ps.bond_share(b) * (std::abs(s * n_x) > r_c);
        }
    const long broken = count_broken();
    evaluate(body, *model, field<dim>(body, [](const auto &) { return 0.; }), f, energy, r_c);
    deallog << "  breaking at r_c = " << r_c << ": " << broken << " of " << ps.n_global_bonds()
            << " bonds broken, as |s n_x| > r_c "
            << ok(broken == std::lround(sum_all(expected)) && broken > 0)
            << "; still broken at w = 0 " << ok(count_broken() == broken) << std::endl;
  }

  template <int dim>
  void
  check_fields(const int n)
  {
    Body<dim> body(n, 1e-3, 3.015, perideal::PartialVolume::book, h);
    check_uniform_shear<dim>(body);
    check_surface_correction<dim>(body);
    check_quadratic<dim>(body);
    check_linearization<dim>(body);
    check_zero_energy_mode<dim>(body);
    check_breaking<dim>(body);
  }

  // 8. The stabilization entry out of range.
  void
  check_bad_input()
  {
    for (const std::string value : {"1", "1.5"})
      try
        {
          perideal::AntiplaneStateBased<2> model;
          pd_tests::parse_model(model,
                                {{"Shear modulus", std::to_string(mu)}, {"Stabilization", value}});
          deallog << "Stabilization = " << value << ": accepted (wrong)" << std::endl;
        }
      catch (const dealii::ExceptionBase &exc)
        {
          deallog << "Stabilization = " << value << ": " << perideal_tests::exception_text(exc)
                  << std::endl;
        }
  }
} // namespace

int
main(int argc, char *argv[])
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();
  check_constants<2>();
  check_constants<3>();
  check_fields<2>(16);
  check_fields<3>(14);
  check_bad_input();
}
