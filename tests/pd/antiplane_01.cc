// The bond-based antiplane model (one scalar w per particle, seed 000): its micromodulus and
// critical slope against integrals of the continuum micropotential, the energy of a uniform
// shear w = g . x (exact in the interior, and at every particle with surface correction for the
// test directions), the force of a quadratic field (mu laplace w), its linearization against
// its forces, and bond breaking at the critical slope; 2D and 3D, on 1 and 2 ranks.

#include <deal.II/base/mpi.h>
#include <deal.II/base/numbers.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <perideal/pd/antiplane_bond_based.h>
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

  template <int dim>
  std::unique_ptr<perideal::AntiplaneBondBased<dim>>
  make_model(Body<dim> &body, const bool correction)
  {
    auto model = std::make_unique<perideal::AntiplaneBondBased<dim>>();
    pd_tests::parse_model(*model, {{"Shear modulus", std::to_string(mu)}});
    model->initialize(body.ps,
                      pd_tests::model_context(body.delta,
                                              h,
                                              dim == 2 ?
                                                perideal::PlanarAssumption::plane_strain :
                                                perideal::PlanarAssumption::three_dimensional,
                                              correction));
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

  // 1. Micromodulus: W = 1/4 c g^2 int n_x^2 |xi| dV = mu g^2 / 2 for w = g x, the integral by
  // the midpoint rule in polar/spherical coordinates (not the closed form of the model).
  // Critical slope: the energy of the bonds that cross a unit area of a plane, each at slope r_c
  // and energy c r_c^2 |xi| / 2, is the fracture energy G (the same quadrature).
  template <int dim>
  void
  check_constants()
  {
    Body<dim>    body(8, 1e-3, 3.015, perideal::PartialVolume::none, h);
    const auto   model = make_model<dim>(body, false);
    const double c = model->micromodulus(), delta = body.delta;
    const int    n      = 400;
    double       moment = 0., crossing = 0.;
    // moment = int_H n_x^2 |xi| dV; crossing = int_0^delta dz int_{|xi| > z, n_z > z/|xi|} |xi| dV
    for (int a = 0; a < n; ++a)
      {
        const double r = (a + 0.5) * delta / n, dr = delta / n;
        for (int b = 0; b < n; ++b)
          {
            const double t = (b + 0.5) * pi / n;
            if (dim == 2)
              {
                const double dtheta = 2. * pi / n, theta = 2. * t;
                moment += std::pow(std::cos(theta), 2) * r * h * r * dr * dtheta;
              }
            else
              {
                const double dtheta = pi / n;
                // the azimuthal integral of cos^2(phi) is pi (n_x = sin(theta) cos(phi))
                moment += std::pow(std::sin(t), 2) * pi * r * r * r * std::sin(t) * dr * dtheta;
              }
          }
        // Bonds of length r across the plane from a point at depth z: the cap n_z > z / r.
        double cap = 0.;
        for (int b = 0; b < n; ++b)
          {
            const double z = (b + 0.5) * r / n, dz = r / n;
            cap += (dim == 2 ? 2. * std::acos(z / r) * h * r : 2. * pi * (1. - z / r) * r * r) * dz;
          }
        crossing += cap * r * dr;
      }
    const double W_pd = 0.25 * c * moment, W = 0.5 * mu;
    const double G   = 0.1; // J/m^2
    const double r_c = model->critical_stretch(G);
    // G = (1/A) int_{z<0} dV_i int_{above} c r_c^2 |xi| / 2 dV_j = c r_c^2 crossing / 2 (the
    // thickness of dV_i cancels the area of a 2D crack per unit length).
    const double G_pd = 0.5 * c * r_c * r_c * crossing;
    deallog << dim << "D: c = " << c << " N/m^6, |W(w = x) / (mu / 2) - 1| < 1e-4 "
            << ok(std::abs(W_pd / W - 1.) < 1e-4) << "; critical slope " << r_c << " for G = " << G
            << " J/m^2, crossing energy / G - 1 < 1e-3 " << ok(std::abs(G_pd / G - 1.) < 1e-3)
            << std::endl;
  }

  // Force density and energy density of the field w (no breaking).
  template <int dim>
  void
  evaluate(Body<dim>                         &body,
           perideal::AntiplaneBondBased<dim> &model,
           const perideal::ParticleVector    &w,
           perideal::ParticleVector          &f,
           std::vector<double>               &energy,
           const double critical_slope = std::numeric_limits<double>::infinity())
  {
    body.ps.reinit_vector(f, 1);
    model.compute_forces(body.ps, w, f, &energy, critical_slope);
  }

  double
  max_all(const double value)
  {
    return dealii::Utilities::MPI::max(value, comm);
  }

  // 2.-5. on a lattice body with partial volumes; particles at depth >= 6 layers (2 delta) have
  // only neighbours with complete families.
  template <int dim>
  void
  check_fields(const int n)
  {
    Body<dim>                body(n, 1e-3, 3.015, perideal::PartialVolume::book, h);
    const auto               plain     = make_model<dim>(body, false);
    const auto               corrected = make_model<dim>(body, true);
    const auto              &ps        = body.ps;
    perideal::ParticleVector f;
    std::vector<double>      energy;

    // 2. Uniform shear along a skew direction: interior W = mu |g|^2 / 2 with the correction;
    // w = s x: every particle's W against mu s^2 / 2, with and without the correction.
    dealii::Tensor<1, dim> g;
    g[0] = 0.3e-3;
    g[1] = -0.7e-3;
    if (dim == 3)
      g[dim - 1] = 0.5e-3;
    evaluate(body, *corrected, field<dim>(body, [&](const auto &x) { return g * x; }), f, energy);
    double interior_error = 0., interior_force = 0.;
    for (unsigned int i = 0; i < ps.n_owned(); ++i)
      if (body.depth(i) >= 6)
        {
          interior_error =
            std::max(interior_error, std::abs(energy[i] / (0.5 * mu * g.norm_square()) - 1.));
          interior_force = std::max(interior_force, std::abs(f.local_element(i)));
        }
    interior_error           = max_all(interior_error);
    interior_force           = max_all(interior_force);
    const double force_scale = mu * g.norm() / body.dx; // a one-spacing jump of the slope
    deallog << dim << "D uniform shear, corrected: interior |W / (mu |g|^2 / 2) - 1| < 1e-10 "
            << ok(interior_error < 1e-10) << ", interior |f| < 1e-10 mu |g| / dx "
            << ok(interior_force < 1e-10 * force_scale) << std::endl;
    for (const bool correction : {false, true})
      {
        const double s = 1e-3;
        evaluate(body,
                 correction ? *corrected : *plain,
                 field<dim>(body, [&](const auto &x) { return s * x[0]; }),
                 f,
                 energy);
        double largest = 0., sum = 0., total = 0.;
        for (unsigned int i = 0; i < ps.n_owned(); ++i)
          {
            largest = std::max(largest, std::abs(energy[i] / (0.5 * mu * s * s) - 1.));
            sum += energy[i] * ps.volumes()[i];
            total += 0.5 * mu * s * s * ps.volumes()[i];
          }
        largest = max_all(largest);
        sum     = dealii::Utilities::MPI::sum(sum, comm);
        total   = dealii::Utilities::MPI::sum(total, comm);
        deallog << "  w = s x, " << (correction ? "corrected" : "uncorrected")
                << ": largest |W / (mu s^2 / 2) - 1| " << std::setprecision(3) << largest
                << ", total energy / classical " << sum / total << std::setprecision(6)
                << std::endl;
      }

    // 3. Quadratic field w = kappa |x|^2 / 2: f = mu laplace w = dim mu kappa in the interior.
    const double kappa = 1.;
    evaluate(body,
             *corrected,
             field<dim>(body, [&](const auto &x) { return 0.5 * kappa * x.norm_square(); }),
             f,
             energy);
    double quadratic_error = 0.;
    for (unsigned int i = 0; i < ps.n_owned(); ++i)
      if (body.depth(i) >= 6)
        quadratic_error =
          std::max(quadratic_error, std::abs(f.local_element(i) / (dim * mu * kappa) - 1.));
    deallog << "  w = kappa |x|^2 / 2: interior |f / (mu laplace w) - 1| < 1e-9 "
            << ok(max_all(quadratic_error) < 1e-9) << std::endl;

    // 4. Linearization: f = -(1/V) G^T diag(weights) G w for a random w (the model is linear).
    perideal::ParticleVector w;
    ps.reinit_vector(w, 1);
    for (unsigned int i = 0; i < ps.n_local(); ++i)
      w.local_element(i) = 1e-6 * pd_tests::random_number(body.lattice_index(i));
    evaluate(body, *corrected, w, f, energy);
    perideal::LinearizedModel linearized;
    corrected->linearize(ps, linearized);
    perideal::ParticleVector f_linear;
    pd_tests::linearized_forces(ps, linearized, w, f_linear);
    double difference = 0., scale = 0.;
    for (unsigned int i = 0; i < ps.n_owned(); ++i)
      {
        difference = std::max(difference, std::abs(f_linear.local_element(i) - f.local_element(i)));
        scale      = std::max(scale, std::abs(f.local_element(i)));
      }
    deallog << "  linearization: one component per particle " << ok(linearized.n_components() == 1)
            << ", max |f_G - f| / max |f| < 1e-12 "
            << ok(max_all(difference) < 1e-12 * max_all(scale)) << std::endl;

    // 5. Breaking: w = s x with s = 1.55 r_c breaks exactly the bonds with |s n_x| > r_c
    // (with 1.5, the 3D lattice bonds with n_x = 2/3 would lie on the threshold).
    const double r_c = corrected->critical_stretch(0.1);
    const double s   = 1.55 * r_c;
    evaluate(body,
             *corrected,
             field<dim>(body, [&](const auto &x) { return s * x[0]; }),
             f,
             energy,
             r_c);
    const auto &bonds  = ps.bonds();
    double      broken = 0., expected = 0.;
    for (unsigned int i = 0; i < ps.n_owned(); ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        {
          const double n_x =
            (ps.positions()[bonds.neighbor[b]][0] - ps.positions()[i][0]) / bonds.length[b];
          broken += ps.bond_share(b) * (bonds.intact[b] == 0);
          expected += ps.bond_share(b) * (std::abs(s * n_x) > r_c);
        }
    broken   = dealii::Utilities::MPI::sum(broken, comm);
    expected = dealii::Utilities::MPI::sum(expected, comm);
    deallog << "  breaking at r_c = " << r_c << ": " << std::lround(broken) << " of "
            << ps.n_global_bonds() << " bonds broken, as |s n_x| > r_c "
            << ok(std::lround(broken) == std::lround(expected) && broken > 0.) << std::endl;
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
}
