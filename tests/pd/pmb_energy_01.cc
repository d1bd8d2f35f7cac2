// PMB model: micromodulus, energy density under homogeneous strain, equilibrium, momentum balance.

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/numbers.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/utilities.h>

#include <perideal/pd/bond_based.h>
#include <perideal/pd/particle_system.h>

#include "../tests.h"
#include "pd_tests.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace
{
  using dealii::deallog;
  const double pi = dealii::numbers::PI;
  const double E  = 192e9;
  const double h  = 1e-4;

  using pd_tests::Body;
  using pd_tests::planar_name;
  using pd_tests::random_number;

  template <int dim>
  std::unique_ptr<perideal::BondBased<dim>>
  make_model(Body<dim> &body, const perideal::PlanarAssumption planar, const bool correction)
  {
    auto model = std::make_unique<perideal::BondBased<dim>>();
    pd_tests::parse_model(*model, {{"Young's modulus", std::to_string(E)}});
    model->initialize(body.ps, pd_tests::model_context(body.delta, h, planar, correction));
    return model;
  }

  template <int dim>
  std::vector<double>
  energy(Body<dim> &body, perideal::BondBased<dim> &model, const perideal::ParticleVector &u)
  {
    perideal::ParticleVector f;
    body.ps.reinit_vector(f, dim);
    std::vector<double> w;
    model.compute_forces(body.ps, u, f, &w, std::numeric_limits<double>::infinity());
    return w;
  }

  // Sum over the lattice offsets of a full family: sum |v| beta (in units of dx).
  template <int dim>
  double
  lattice_sum(const double R, const perideal::PartialVolume partial_volume)
  {
    double sum = 0.;
    pd_tests::for_each_lattice_offset<dim>(
      static_cast<int>(R) + 2,
      [&](const std::array<int, dim> &v) {
        double r2 = 0.;
        for (unsigned int d = 0; d < dim; ++d)
          r2 += double(v[d]) * v[d];
        const double r         = std::sqrt(r2);
        const bool   geometric = (partial_volume == perideal::PartialVolume::geometric);
        if (r > 0. && (geometric ? r < R + 0.5 - 1e-10 : r <= R * (1. + 1e-10)))
          sum +=
            r *
            ((partial_volume == perideal::PartialVolume::none || r <= R - 0.5) ? 1. : R + 0.5 - r);
      });
    return sum;
  }

  // 1. The micromodulus from matching the continuum PD energy to the model's elasticity tensor.
  template <int dim>
  void
  check_micromodulus(const perideal::PlanarAssumption planar)
  {
    Body<dim>    body(9, 1e-4, 4., perideal::PartialVolume::none, h);
    const auto   model = make_model<dim>(body, planar, false);
    const double c = model->micromodulus(), delta = body.delta;
    const auto   C = model->elasticity_tensor();
    // Isotropic expansion eps: classical W = eps^2/2 sum_ij C_iijj; PD W = 1/4 c eps^2 int |xi| dV
    // = c eps^2 pi delta^4 / 4 (3D) or c eps^2 pi h delta^3 / 6 (2D) (seed note 002, sec. 2.3).
    double trace = 0.;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        trace += C[i][i][j][j];
    const double c_iso = (dim == 3 ? 2. * trace / (pi * std::pow(delta, 4)) :
                                     3. * trace / (pi * h * std::pow(delta, 3)));
    // Uniaxial stretch: PD W = 1/4 c eps^2 int |xi| n_x^4 dV with <n_x^4> = 1/5 (sphere) or
    // 3/8 (circle), so C_0000 = pi c delta^4 / 10 or pi c h delta^3 / 8: checks the implied
    // Poisson ratio of the elasticity tensor.
    const double C_uniaxial =
      (dim == 3 ? pi * c * std::pow(delta, 4) / 10. : pi * c * h * std::pow(delta, 3) / 8.);
    deallog << planar_name(planar) << ": c = " << c << " N/m^6, from isotropic expansion "
            << (std::abs(c / c_iso - 1.) < 1e-12 ? "ok" : "FAILED")
            << ", C_xxxx from uniaxial stretch "
            << (std::abs(C_uniaxial / C[0][0][0][0] - 1.) < 1e-12 ? "ok" : "FAILED") << std::endl;
    // Seed note 002, sec. 2.3: E = 192 GPa, h = 1e-4 m, delta = 4e-4 m, plane stress.
    if (planar == perideal::PlanarAssumption::plane_stress)
      deallog << "  thesis value 8.59437e25: relative error < 1e-5 "
              << (std::abs(c / 8.59437e25 - 1.) < 1e-5 ? "ok" : "FAILED") << std::endl;
  }

  // 2. Energy density of the centre particle under isotropic expansion, no surface correction.
  template <int dim>
  void
  check_interior_energy(const perideal::PlanarAssumption planar,
                        const double                     horizon_factor,
                        const perideal::PartialVolume    partial_volume)
  {
    const int                R = static_cast<int>(horizon_factor);
    Body<dim>                body(2 * R + 5, 1e-4, horizon_factor, partial_volume, h);
    const auto               model = make_model<dim>(body, planar, false);
    const double             eps   = 1e-6;
    perideal::ParticleVector u;
    body.set_field(u, [&](const unsigned int i) {
      return dealii::Tensor<1, dim>(eps * body.ps.positions()[i]);
    });
    const auto w = energy(body, *model, u);

    const auto   identity  = dealii::unit_symmetric_tensor<dim>();
    const auto   strain    = eps * identity;
    const double classical = 0.5 * strain * (model->elasticity_tensor() * strain);
    double       local     = 0.;
    for (unsigned int i = 0; i < body.ps.n_owned(); ++i)
      if (body.depth(i) == R + 2)
        local = w[i] / classical;
    const double ratio = dealii::Utilities::MPI::max(local, MPI_COMM_WORLD);
    // The one-point quadrature of the family: W_PD/W = sum |xi| beta V / int |xi| dV exactly,
    // because the stretch is eps for every bond of an isotropic expansion.
    const double continuum =
      (dim == 3 ? pi * std::pow(horizon_factor, 4) : 2. * pi * std::pow(horizon_factor, 3) / 3.);
    const double lattice = lattice_sum<dim>(horizon_factor, partial_volume) / continuum;
    deallog << planar_name(planar) << ", delta = " << horizon_factor << " dx, partial volume "
            << (partial_volume == perideal::PartialVolume::none ? "none" :
                partial_volume == perideal::PartialVolume::book ? "book" :
                                                                  "geometric")
            << ": interior W_PD/W_classical = " << ratio << ", lattice sum "
            << (std::abs(ratio - lattice) < 1e-8 ? "ok" : "FAILED");
    // Seed note 002 (sec. 8, T4) bounds the quadrature error at delta = 4 dx by 8 % without
    // partial volume (0.962 in 2D) and by 3 % with it (1.013 in 2D): that value counts neighbours
    // up to delta + dx/2, i.e. the 'geometric' variant. The 'book' variant stops the family at
    // delta, so its factors only remove volume (0.880 in 2D); see partial_volume_01.
    if (partial_volume == perideal::PartialVolume::none)
      deallog << ", |ratio - 1| < 0.08 " << (std::abs(ratio - 1.) < 0.08 ? "ok" : "FAILED");
    if (partial_volume == perideal::PartialVolume::geometric)
      deallog << ", |ratio - 1| < 0.03 " << (std::abs(ratio - 1.) < 0.03 ? "ok" : "FAILED");
    deallog << std::endl;
  }

  // 3. Surface correction: energy of uniaxial stretch at every particle.
  template <int dim>
  void
  check_surface_correction(const perideal::PlanarAssumption planar, const int n)
  {
    const double horizon_factor = (dim == 2 ? 4. : 3.);
    const int    R              = static_cast<int>(horizon_factor);
    Body<dim>    body(n, 1e-4, horizon_factor, perideal::PartialVolume::none, h);
    const double eps = 1e-6;
    deallog << planar_name(planar) << ", delta = " << horizon_factor << " dx, " << n << "^" << dim
            << " particles, uniaxial stretch " << eps << ':' << std::endl;
    for (const bool correction : {false, true})
      {
        const auto model = make_model<dim>(body, planar, correction);
        const auto C     = model->elasticity_tensor();
        for (unsigned int a = 0; a < dim; ++a)
          {
            perideal::ParticleVector u;
            body.set_field(u, [&](const unsigned int i) {
              dealii::Tensor<1, dim> v;
              v[a] = eps * body.ps.positions()[i][a];
              return v;
            });
            const auto   w         = energy(body, *model, u);
            const double classical = 0.5 * C[a][a][a][a] * eps * eps;
            double       deep = 0., all = 0., corner = 0.;
            for (unsigned int i = 0; i < body.ps.n_owned(); ++i)
              {
                const double error = std::abs(w[i] / classical - 1.);
                all                = std::max(all, error);
                // Particles whose neighbours all have full families: every bond carries the
                // same correction g, so g W_i = W exactly (seed note 000, sec. 2).
                if (body.depth(i) >= 2 * R)
                  deep = std::max(deep, error);
                if (body.lattice_index(i) == 0)
                  corner = w[i] / classical;
              }
            deep   = dealii::Utilities::MPI::max(deep, MPI_COMM_WORLD);
            all    = dealii::Utilities::MPI::max(all, MPI_COMM_WORLD);
            corner = dealii::Utilities::MPI::sum(corner, MPI_COMM_WORLD);
            deallog << "  correction " << (correction ? "on " : "off") << ", direction " << a
                    << ": corner W_PD/W = " << std::setprecision(4) << corner
                    << ", max |W_PD/W - 1| = " << all << std::setprecision(6);
            if (correction)
              deallog << ", 2 delta inside < 1e-10 " << (deep < 1e-10 ? "ok" : "FAILED");
            else
              deallog << ", 2 delta inside " << std::setprecision(4) << deep
                      << std::setprecision(6);
            deallog << std::endl;
          }
      }
  }

  // 4. Equilibrium of interior particles under a homogeneous deformation.
  template <int dim>
  void
  check_equilibrium(const perideal::PlanarAssumption planar, const bool correction)
  {
    const double horizon_factor = (dim == 2 ? 4. : 3.);
    const int    R              = static_cast<int>(horizon_factor);
    Body<dim>    body(dim == 2 ? 21 : 13, 1e-4, horizon_factor, perideal::PartialVolume::none, h);
    const auto   model = make_model<dim>(body, planar, correction);
    // A general homogeneous deformation u = H x; large enough (1e-4) that round-off in the
    // stretch, (|y| - |xi|)/|xi|, stays at 1e-12 of s.
    dealii::Tensor<2, dim> H;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        H[i][j] = 1e-4 * (i == j ? 1. + 0.5 * i : 0.3 - 0.1 * (i + 2 * j));
    perideal::ParticleVector u, f;
    body.set_field(u, [&](const unsigned int i) {
      return dealii::Tensor<1, dim>(H * body.ps.positions()[i]);
    });
    body.ps.reinit_vector(f, dim);
    model->compute_forces(body.ps, u, f, nullptr, std::numeric_limits<double>::infinity());
    // Each pair of opposite bonds cancels exactly (s even, direction odd in xi). Scale: the
    // force density of one side of the family, c |H| sum_j V_j.
    const double scale = model->micromodulus() * 1e-4 * body.ps.volumes()[0] *
                         (dim == 2 ? pi * R * R : 4. / 3. * pi * R * R * R);
    const int depth = correction ? 2 * R : R;
    double    worst = 0.;
    for (unsigned int i = 0; i < body.ps.n_owned(); ++i)
      if (body.depth(i) >= depth)
        for (unsigned int d = 0; d < dim; ++d)
          worst = std::max(worst, std::abs(f.local_element(i * dim + d)) / scale);
    worst = dealii::Utilities::MPI::max(worst, MPI_COMM_WORLD);
    deallog << planar_name(planar) << ", correction " << (correction ? "on" : "off")
            << ": interior force density under u = H x, max |f| / (c |H| sum V) < 1e-10 "
            << (worst < 1e-10 ? "ok" : "FAILED") << std::endl;
  }

  // 5. Linear and angular admissibility for a random displacement.
  template <int dim>
  void
  check_balance(const perideal::PlanarAssumption planar)
  {
    Body<dim>  body(dim == 2 ? 17 : 9, 1e-4, 3.015, perideal::PartialVolume::geometric, h);
    const auto model = make_model<dim>(body, planar, true);
    perideal::ParticleVector u, f;
    body.set_field(u, [&](const unsigned int i) {
      dealii::Tensor<1, dim> v;
      for (unsigned int d = 0; d < dim; ++d)
        v[d] = 1e-3 * body.dx * random_number(body.lattice_index(i) * dim + d);
      return v;
    });
    body.ps.reinit_vector(f, dim);
    model->compute_forces(body.ps, u, f, nullptr, std::numeric_limits<double>::infinity());
    std::array<double, dim> momentum{};
    std::array<double, 3>   angular{};
    double                  size = 0., angular_size = 0.;
    for (unsigned int i = 0; i < body.ps.n_owned(); ++i)
      {
        const double           V = body.ps.volumes()[i];
        dealii::Tensor<1, dim> fi, yi;
        for (unsigned int d = 0; d < dim; ++d)
          {
            fi[d] = f.local_element(i * dim + d) * V;
            yi[d] = body.ps.positions()[i][d] + u.local_element(i * dim + d);
            momentum[d] += fi[d];
          }
        if (dim == 2)
          angular[2] += yi[0] * fi[1] - yi[1] * fi[0];
        else
          for (unsigned int d = 0; d < 3; ++d)
            angular[d] +=
              yi[(d + 1) % dim] * fi[(d + 2) % dim] - yi[(d + 2) % dim] * fi[(d + 1) % dim];
        size += fi.norm();
        angular_size += yi.norm() * fi.norm();
      }
    size                = dealii::Utilities::MPI::sum(size, MPI_COMM_WORLD);
    angular_size        = dealii::Utilities::MPI::sum(angular_size, MPI_COMM_WORLD);
    double linear_error = 0., angular_error = 0.;
    for (unsigned int d = 0; d < dim; ++d)
      linear_error =
        std::max(linear_error, std::abs(dealii::Utilities::MPI::sum(momentum[d], MPI_COMM_WORLD)));
    for (unsigned int d = 0; d < 3; ++d)
      angular_error =
        std::max(angular_error, std::abs(dealii::Utilities::MPI::sum(angular[d], MPI_COMM_WORLD)));
    // Round-off only: each bond adds equal and opposite forces along the deformed bond
    // (seed note 002, sec. 8, T6: 1e-12).
    deallog << planar_name(planar)
            << ", random displacement, corrections on: |sum f V| / sum |f| V < 1e-12 "
            << (linear_error / size < 1e-12 ? "ok" : "FAILED")
            << ", |sum y x f V| / sum |y||f| V < 1e-12 "
            << (angular_error / angular_size < 1e-12 ? "ok" : "FAILED") << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();

  using P = perideal::PlanarAssumption;
  check_micromodulus<3>(P::three_dimensional);
  check_micromodulus<2>(P::plane_stress);
  check_micromodulus<2>(P::plane_strain);

  for (const auto partial_volume : {perideal::PartialVolume::none,
                                    perideal::PartialVolume::book,
                                    perideal::PartialVolume::geometric})
    {
      check_interior_energy<3>(P::three_dimensional, 4., partial_volume);
      check_interior_energy<2>(P::plane_stress, 4., partial_volume);
      check_interior_energy<2>(P::plane_strain, 4., partial_volume);
    }

  check_surface_correction<2>(P::plane_stress, 21);
  check_surface_correction<3>(P::three_dimensional, 13);

  for (const bool correction : {false, true})
    {
      check_equilibrium<2>(P::plane_stress, correction);
      check_equilibrium<3>(P::three_dimensional, correction);
    }

  check_balance<2>(P::plane_stress);
  check_balance<2>(P::plane_strain);
  check_balance<3>(P::three_dimensional);
}
