// The state-based models with a temperature change (doc/theory/thermal_strain_state_based.md):
// LPS in 3D, plane strain and plane stress, and the anisotropic plane-stress model (an
// orthotropic expansion turned about z). The in-plane expansion; free expansion under a uniform
// and a linear temperature change (no force at any particle, no bond broken by the thermal
// stretch, no energy released by bonds broken in it); the constrained body (energy density 1/2
// a:C:a DeltaT^2, forces only near the surfaces, the thermal stress across a mid-plane); force =
// -grad E by finite differences with a random temperature change; the linearization's energy and
// forces with its offsets against the model at small u, and its rows at their offsets under the
// free field of a linear DeltaT. Bad input: an expansion tensor for LPS, an expansion without z = 0
// as a mirror plane for the plane-stress model.

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/utilities.h>

#include <perideal/base/elasticity.h>
#include <perideal/pd/anisotropic_plane_stress.h>
#include <perideal/pd/linear_peridynamic_solid.h>
#include <perideal/pd/particle_system.h>

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
  using pd_tests::random_number;

  const double E      = 200e9;
  const double nu     = 0.3;
  const double alpha  = 1.2e-5;
  const double dx     = 1e-3;
  const double h      = 1e-3;
  const double inf    = std::numeric_limits<double>::infinity();
  const double dT_ref = 50.;

  // The body of a check: 20^2 particles at delta = 3.015 dx in 2D, 14^3 at 2.015 dx in 3D.
  template <int dim>
  std::unique_ptr<Body<dim>>
  make_body()
  {
    return std::make_unique<Body<dim>>(dim == 2 ? 20 : 14,
                                       dx,
                                       dim == 2 ? 3.015 : 2.015,
                                       perideal::PartialVolume::book,
                                       h);
  }

  // A model under test: its name, its planar assumption, whether its kinematics are linearized
  // (the anisotropic plane-stress model) and its material entries (ElasticMaterial's, which
  // give the expected expansion).
  template <int dim>
  struct Case
  {
    std::string                                      name;
    perideal::PlanarAssumption                       planar;
    bool                                             linearized_kinematics;
    std::vector<std::pair<std::string, std::string>> entries;

    std::unique_ptr<perideal::MaterialModel<dim>>
    make(Body<dim> &body) const
    {
      std::unique_ptr<perideal::MaterialModel<dim>> model;
      if constexpr (dim == 2)
        if (linearized_kinematics)
          {
            auto aniso = std::make_unique<perideal::AnisotropicPlaneStress>();
            pd_tests::parse_model(*aniso, entries);
            model = std::move(aniso);
          }
      if (!model)
        {
          auto lps = std::make_unique<perideal::LinearPeridynamicSolid<dim>>();
          pd_tests::parse_model(*lps, entries);
          model = std::move(lps);
        }
      model->initialize(body.ps, pd_tests::model_context(body.delta, h, planar, true));
      return model;
    }
  };

  // DeltaT(x) at every local particle (owned and ghost), one component per particle.
  template <int dim>
  void
  set_temperature(const Body<dim>                                 &body,
                  perideal::ParticleVector                        &delta_T,
                  const std::function<double(const unsigned int)> &value)
  {
    body.ps.reinit_vector(delta_T, 1);
    for (unsigned int i = 0; i < body.ps.n_local(); ++i)
      delta_T.local_element(i) = value(i);
  }

  // max |f| over the owned particles that @p select takes, over the ranks.
  template <int dim>
  double
  max_force(const Body<dim>                               &body,
            const perideal::ParticleVector                &f,
            const std::function<bool(const unsigned int)> &select)
  {
    double result = 0.;
    for (unsigned int i = 0; i < body.ps.n_owned(); ++i)
      if (select(i))
        for (unsigned int d = 0; d < dim; ++d)
          result = std::max(result, std::abs(f.local_element(i * dim + d)));
    return dealii::Utilities::MPI::max(result, MPI_COMM_WORLD);
  }

  template <int dim>
  unsigned int
  broken_bonds(const Body<dim> &body)
  {
    const auto  &bonds  = body.ps.bonds();
    unsigned int broken = 0;
    for (std::size_t b = 0; b < bonds.row_start[body.ps.n_owned()]; ++b)
      broken += bonds.intact[b] ? 0 : 1;
    return dealii::Utilities::MPI::sum(broken, MPI_COMM_WORLD);
  }

  // The force scale of the thermal load: the largest force density of the constrained body
  // (u = 0) under the uniform DeltaT_ref, at its surface.
  template <int dim>
  double
  thermal_force_scale(const Case<dim> &c)
  {
    auto                     body  = make_body<dim>();
    auto                     model = c.make(*body);
    perideal::ParticleVector u, f, delta_T;
    body->set_field(u, [](const unsigned int) { return dealii::Tensor<1, dim>(); });
    body->ps.reinit_vector(f, dim);
    set_temperature<dim>(*body, delta_T, [](const unsigned int) { return dT_ref; });
    model->set_temperature_change(&delta_T);
    model->compute_forces(body->ps, u, f, nullptr, inf);
    return max_force<dim>(*body, f, [](const unsigned int) { return true; });
  }

  // The model's expansion against planar_thermal_expansion() of the same material.
  template <int dim>
  void
  check_expansion(const Case<dim> &c)
  {
    dealii::ParameterHandler prm;
    perideal::ElasticMaterial::declare_parameters(prm);
    for (const auto &entry : c.entries)
      if (entry.first != "Influence function")
        prm.set(entry.first, entry.second);
    perideal::ElasticMaterial material;
    material.parse_parameters(prm, "Finite elements/Elasticity");
    const auto expected = perideal::planar_thermal_expansion<dim>(material.thermal_expansion(),
                                                                  material.voigt_stiffness(),
                                                                  c.planar);
    auto       body     = make_body<dim>();
    auto       model    = c.make(*body);
    const auto a        = model->thermal_expansion();
    deallog << c.name << ": thermal_expansion() = planar_thermal_expansion() "
            << ok((a - expected).norm() < 1e-12 * expected.norm())
            << ", a_11 / alpha = " << std::setprecision(4) << a[0][0] / alpha
            << ", a_22 / alpha = " << a[1][1] / alpha << ", a_12 / alpha = " << a[0][1] / alpha
            << std::setprecision(6) << ", capabilities().thermal_strain "
            << ok(model->capabilities().thermal_strain) << std::endl;
  }

  // The free field of DeltaT = T0 + g . x, whose strain a DeltaT is compatible for a linear
  // DeltaT: u = DeltaT(x) a x - (x . a x) g / 2 (its gradient is a DeltaT plus a rotation); a
  // uniform DeltaT if g = 0.
  template <int dim>
  dealii::Tensor<1, dim>
  free_field(const dealii::Point<dim>              &x,
             const dealii::SymmetricTensor<2, dim> &a,
             const double                           T0,
             const dealii::Tensor<1, dim>          &g)
  {
    const dealii::Tensor<1, dim> ax = a * dealii::Tensor<1, dim>(x);
    return (T0 + g * x) * ax - 0.5 * (x * ax) * g;
  }

  // A temperature gradient of DeltaT_ref over the body's diagonal.
  template <int dim>
  dealii::Tensor<1, dim>
  diagonal_gradient(const Body<dim> &body)
  {
    dealii::Tensor<1, dim> g;
    for (unsigned int d = 0; d < dim; ++d)
      g[d] = dT_ref / (dim * body.n * dx);
    return g;
  }

  // Free expansion: the free field under a uniform DeltaT (exact, also for the geometrically
  // exact extension |y| - |xi|) and a linear one; and no bond breaks by the thermal stretch.
  template <int dim>
  void
  check_free(const Case<dim> &c)
  {
    const double             scale = thermal_force_scale<dim>(c);
    const auto               body  = make_body<dim>();
    const auto               model = c.make(*body);
    const auto               a     = model->thermal_expansion();
    const auto              &x     = body->ps.positions();
    perideal::ParticleVector u, f, delta_T;
    body->ps.reinit_vector(f, dim);
    const auto free_force = [&](const double T0, const dealii::Tensor<1, dim> &g) {
      set_temperature<dim>(*body, delta_T, [&](const unsigned int i) { return T0 + g * x[i]; });
      body->set_field(u, [&](const unsigned int i) { return free_field<dim>(x[i], a, T0, g); });
      model->set_temperature_change(&delta_T);
      std::vector<double> w;
      model->compute_forces(body->ps, u, f, &w, inf);
      return max_force<dim>(*body, f, [](const unsigned int) { return true; }) / scale;
    };
    const double uniform = free_force(dT_ref, dealii::Tensor<1, dim>());
    const auto   g       = diagonal_gradient(*body);
    const double linear  = free_force(0., g);
    deallog << c.name << ", free body: uniform DeltaT, max |f| / thermal force < 1e-10 "
            << ok(uniform < 1e-10);
    if (c.linearized_kinematics)
      deallog << "; linear DeltaT < 1e-10 " << ok(linear < 1e-10) << std::endl;
    else
      {
        // What is left is the geometric nonlinearity of |y| - |xi| under the field's rotations
        // (of order a g L): second order in the temperature, a hundredth at a tenth of it (the
        // linearization has none: check_linearization()).
        const double tenth = free_force(0., 0.1 * g);
        deallog << "; linear DeltaT < 1e-3 " << ok(linear < 1e-3)
                << ", a hundred times less at a tenth of DeltaT "
                << ok(std::abs(linear / tenth / 100. - 1.) < 0.01) << std::endl;
      }

    // Bonds broken in the free expansion of a uniform DeltaT, which stores no energy, release
    // none (released_energy(): the energy with and without them, thermal terms included). The
    // bonds are chosen by their ends' lattice indices, the same on every rank.
    set_temperature<dim>(*body, delta_T, [](const unsigned int) { return dT_ref; });
    body->set_field(u, [&](const unsigned int i) {
      return free_field<dim>(x[i], a, dT_ref, dealii::Tensor<1, dim>());
    });
    model->set_temperature_change(&delta_T);
    auto        &bonds  = body->ps.bonds();
    unsigned int broken = 0;
    for (unsigned int i = 0; i < body->ps.n_owned(); ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        if ((body->lattice_index(i) + body->lattice_index(bonds.neighbor[b])) % 7 == 0)
          {
            bonds.break_bond(b, true);
            ++broken;
          }
    const double released = model->released_energy(body->ps, u);
    const double e_scale  = 0.5 * (a * dT_ref) * (model->elasticity_tensor() * (a * dT_ref)) *
                           std::pow(body->n * dx, dim) * (dim == 2 ? h : 1.);
    deallog << "  bonds broken in the free expansion release no energy (< 1e-10 of the "
               "constrained body's) "
            << ok(dealii::Utilities::MPI::sum(broken, MPI_COMM_WORLD) > 0 &&
                  std::abs(released) < 1e-10 * e_scale)
            << std::endl;

    // The mechanical stretch breaks bonds: none under the free expansion at a critical stretch
    // of half the smallest thermal stretch, which the same expansion without a temperature
    // change exceeds.
    const double s0 = 0.5 * dT_ref * std::min(a[0][0], a[1][1]);
    bonds.set_states(std::vector<std::uint8_t>(bonds.size(), 1));
    model->compute_forces(body->ps, u, f, nullptr, s0);
    const unsigned int thermal_broken = broken_bonds<dim>(*body);
    model->set_temperature_change(nullptr);
    model->compute_forces(body->ps, u, f, nullptr, s0);
    deallog << "  critical stretch of half the thermal stretch: no bond broken by the free "
               "expansion "
            << ok(thermal_broken == 0) << ", the expansion without temperature breaks bonds "
            << ok(broken_bonds<dim>(*body) > 0) << std::endl;
  }

  // The constrained body (u = 0) under a uniform DeltaT. W = 1/2 a:C:a DeltaT^2 in the interior
  // (LPS: at every particle, since the mechanical dilatation is -n a DeltaT with the discrete
  // weighted volume and the deviatoric extension vanishes); the forces vanish where the
  // neighbours' families are complete, and the resultant on the half body x_0 > L/2 is the
  // thermal stress -C:a DeltaT across the mid-plane (to the accuracy of the surface layer).
  template <int dim>
  void
  check_constrained(const Case<dim> &c)
  {
    const auto               body  = make_body<dim>();
    const auto               model = c.make(*body);
    const auto               a     = model->thermal_expansion();
    perideal::ParticleVector u, f, delta_T;
    body->set_field(u, [](const unsigned int) { return dealii::Tensor<1, dim>(); });
    body->ps.reinit_vector(f, dim);
    set_temperature<dim>(*body, delta_T, [](const unsigned int) { return dT_ref; });
    model->set_temperature_change(&delta_T);
    std::vector<double> w;
    model->compute_forces(body->ps, u, f, &w, inf);
    const auto   C              = model->elasticity_tensor();
    const double classical      = 0.5 * (a * dT_ref) * (C * (a * dT_ref));
    const int    reach          = 2 * static_cast<int>(body->delta / dx);
    double       interior_error = 0., surface_error = 0.;
    for (unsigned int i = 0; i < body->ps.n_owned(); ++i)
      {
        double &error = body->depth(i) >= reach ? interior_error : surface_error;
        error         = std::max(error, std::abs(w[i] / classical - 1.));
      }
    interior_error = dealii::Utilities::MPI::max(interior_error, MPI_COMM_WORLD);
    surface_error  = dealii::Utilities::MPI::max(surface_error, MPI_COMM_WORLD);

    const double scale = max_force<dim>(*body, f, [](const unsigned int) { return true; });
    const double interior =
      max_force<dim>(*body, f, [&](const unsigned int i) { return body->depth(i) >= reach; });
    const double L         = body->n * dx;
    double       resultant = 0.;
    for (unsigned int i = 0; i < body->ps.n_owned(); ++i)
      if (body->ps.positions()[i][0] > 0.5 * L)
        resultant += f.local_element(i * dim) * body->ps.volumes()[i];
    resultant          = dealii::Utilities::MPI::sum(resultant, MPI_COMM_WORLD);
    const double area  = dim == 2 ? L * h : L * L;
    const double ratio = resultant / ((C * (a * dT_ref))[0][0] * area);
    deallog << c.name << ", constrained: W = 1/2 a:C:a DeltaT^2 in the interior (< 1e-10) "
            << ok(interior_error < 1e-10);
    if (!c.linearized_kinematics)
      deallog << " and at the surface " << ok(surface_error < 1e-10);
    deallog << ", interior max |f| / max |f| < 1e-10 " << ok(interior < 1e-10 * scale)
            << ", mid-plane resultant / (-sigma_11 A), sigma = -C:a DeltaT: "
            << std::setprecision(3) << ratio << std::setprecision(6) << " (within 10 % "
            << ok(std::abs(ratio - 1.) < 0.1) << ")" << std::endl;
  }

  // The total energy sum_i W_i V_i of the field @p u.
  template <int dim>
  double
  total_energy(Body<dim>                      &body,
               perideal::MaterialModel<dim>   &model,
               const perideal::ParticleVector &u)
  {
    perideal::ParticleVector f;
    body.ps.reinit_vector(f, dim);
    std::vector<double> w;
    model.compute_forces(body.ps, u, f, &w, inf);
    double energy = 0.;
    for (unsigned int i = 0; i < body.ps.n_owned(); ++i)
      energy += w[i] * body.ps.volumes()[i];
    return dealii::Utilities::MPI::sum(energy, MPI_COMM_WORLD);
  }

  // A random temperature change (0 ... 2 DeltaT_ref per particle) and a random displacement
  // of size @p u_size.
  template <int dim>
  void
  random_state(const Body<dim>          &body,
               perideal::ParticleVector &u,
               perideal::ParticleVector &delta_T,
               const double              u_size)
  {
    set_temperature<dim>(body, delta_T, [&](const unsigned int i) {
      return dT_ref * (1. + random_number(7 * body.lattice_index(i) + 5));
    });
    body.set_field(u, [&](const unsigned int i) {
      dealii::Tensor<1, dim> v;
      for (unsigned int d = 0; d < dim; ++d)
        v[d] = u_size * random_number(body.lattice_index(i) * dim + d);
      return v;
    });
  }

  // f V = -dE/du by central differences at a corner, on two edges (3D) or surfaces (2D) and in
  // the interior, with a random DeltaT and a random u of the size of the thermal strain.
  template <int dim>
  void
  check_gradient(const Case<dim> &c)
  {
    const auto               body  = make_body<dim>();
    const auto               model = c.make(*body);
    perideal::ParticleVector u, f, delta_T, v;
    random_state<dim>(*body, u, delta_T, alpha * dT_ref * dx);
    model->set_temperature_change(&delta_T);
    body->ps.reinit_vector(f, dim);
    model->compute_forces(body->ps, u, f, nullptr, inf);
    const double        scale = max_force<dim>(*body, f, [](const unsigned int) { return true; });
    const std::uint64_t n = body->n, m = n / 2;
    double              error = 0.;
    for (const std::uint64_t q :
         {std::uint64_t(0), m, n * m, m + n * m + (dim == 3 ? n * n * m : 0)})
      for (unsigned int component = 0; component < dim; ++component)
        {
          const double step   = 1e-4 * alpha * dT_ref * dx;
          const auto   energy = [&](const double shift) {
            body->set_field(v, [&](const unsigned int i) {
              dealii::Tensor<1, dim> value;
              for (unsigned int d = 0; d < dim; ++d)
                value[d] = u.local_element(i * dim + d);
              if (body->lattice_index(i) == q)
                value[component] += shift;
              return value;
            });
            return total_energy<dim>(*body, *model, v);
          };
          const double derivative = (energy(step) - energy(-step)) / (2. * step);
          double       nodal      = 0.;
          for (unsigned int i = 0; i < body->ps.n_owned(); ++i)
            if (body->lattice_index(i) == q)
              nodal = f.local_element(i * dim + component) * body->ps.volumes()[i];
          nodal = dealii::Utilities::MPI::sum(nodal, MPI_COMM_WORLD);
          error = std::max(error, std::abs(nodal + derivative) / (scale * body->ps.volumes()[0]));
        }
    deallog << c.name
            << ", random DeltaT: f V = -dE/du by central differences (< 1e-6 of max |f| V) "
            << ok(error < 1e-6) << std::endl;
  }

  // E = 1/2 sum_r w_r (G_r u - o_r)^2 and f = -(1/V) G^T diag(w) (G u - o) of a linearization.
  template <int dim>
  double
  linearized_state(const perideal::ParticleSystem<dim> &ps,
                   const perideal::LinearizedModel     &linearized,
                   const perideal::ParticleVector      &u,
                   perideal::ParticleVector            &f)
  {
    ps.reinit_vector(f, dim);
    double energy = 0.;
    for (std::size_t r = 0; r < linearized.n_rows(); ++r)
      {
        double e = -linearized.offset(r);
        for (auto entry = linearized.row_begin(r); entry != linearized.row_end(r); ++entry)
          e += entry->coefficient * u.local_element(dim * entry->particle + entry->component);
        energy += 0.5 * linearized.weight(r) * e * e;
        for (auto entry = linearized.row_begin(r); entry != linearized.row_end(r); ++entry)
          f.local_element(dim * entry->particle + entry->component) -=
            linearized.weight(r) * e * entry->coefficient / ps.volumes()[entry->particle];
      }
    f.compress(dealii::VectorOperation::add);
    return dealii::Utilities::MPI::sum(energy, ps.get_communicator());
  }

  // The linearization with its offsets against the model, with a random DeltaT: at u = 0 (the
  // energy of the offsets alone: exact) and at a random u of 1e-3 of the thermal strain (LPS:
  // its geometric nonlinearity, of that relative order, is what is left); and the free field of
  // a linear DeltaT, where every row is at its offset (no energy, no force).
  template <int dim>
  void
  check_linearization(const Case<dim> &c)
  {
    const auto                body  = make_body<dim>();
    const auto                model = c.make(*body);
    perideal::ParticleVector  u, f, f_lin, delta_T;
    perideal::LinearizedModel linearized;
    body->ps.reinit_vector(f, dim);
    const auto compare = [&](const double u_size) {
      random_state<dim>(*body, u, delta_T, u_size);
      model->set_temperature_change(&delta_T);
      model->linearize(body->ps, linearized);
      const double e_lin   = linearized_state<dim>(body->ps, linearized, u, f_lin);
      const double e_model = total_energy<dim>(*body, *model, u);
      model->compute_forces(body->ps, u, f, nullptr, inf);
      f_lin -= f;
      const double scale = max_force<dim>(*body, f, [](const unsigned int) { return true; });
      return std::max(std::abs(e_lin / e_model - 1.),
                      max_force<dim>(*body, f_lin, [](const unsigned int) { return true; }) /
                        scale);
    };
    const double at_zero  = compare(0.);
    const double at_small = compare(1e-3 * alpha * dT_ref * dx);

    const auto  a = model->thermal_expansion();
    const auto  g = diagonal_gradient(*body);
    const auto &x = body->ps.positions();
    set_temperature<dim>(*body, delta_T, [&](const unsigned int i) { return g * x[i]; });
    body->set_field(u, [&](const unsigned int i) { return free_field<dim>(x[i], a, 0., g); });
    model->linearize(body->ps, linearized);
    const double e_free = linearized_state<dim>(body->ps, linearized, u, f_lin);
    const double f_free = max_force<dim>(*body, f_lin, [](const unsigned int) { return true; });
    const double e_scale =
      0.5 * E * std::pow(alpha * dT_ref, 2) * std::pow(body->n * dx, dim) * (dim == 2 ? h : 1.);
    deallog << c.name
            << ", linearization with offsets, random DeltaT: energy and forces as the model's at "
               "u = 0 (< 1e-12) "
            << ok(at_zero < 1e-12) << " and at a small u (< 1e-5) " << ok(at_small < 1e-5)
            << "; linear DeltaT free field: no energy, no force (< 1e-12) "
            << ok(e_free < 1e-12 * e_scale && f_free < 1e-12 * thermal_force_scale<dim>(c))
            << std::endl;
  }

  template <int dim>
  void
  check_all(const Case<dim> &c)
  {
    check_expansion<dim>(c);
    check_free<dim>(c);
    check_constrained<dim>(c);
    check_gradient<dim>(c);
    check_linearization<dim>(c);
  }

  // LPS's entries; the expansion once isotropic.
  std::vector<std::pair<std::string, std::string>>
  lps_entries()
  {
    return {{"Young's modulus", std::to_string(E)},
            {"Poisson's ratio", std::to_string(nu)},
            {"Thermal expansion", std::to_string(alpha)}};
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();

  using P = perideal::PlanarAssumption;
  check_all<2>({"LPS plane stress", P::plane_stress, false, lps_entries()});
  check_all<2>({"LPS plane strain", P::plane_strain, false, lps_entries()});
  check_all<3>({"LPS 3D", P::three_dimensional, false, lps_entries()});
  // NaCl turned by 20 degrees about z with an orthotropic expansion (1, 2, 3) alpha.
  auto entries = pd_tests::nacl_about_z_entries;
  entries.push_back({"Thermal expansion",
                     std::to_string(alpha) + ", " + std::to_string(2. * alpha) + ", " +
                       std::to_string(3. * alpha)});
  check_all<2>({"anisotropic plane stress", P::plane_stress, true, entries});

  pd_tests::check_refused("LPS, three values", [] {
    perideal::LinearPeridynamicSolid<2> model;
    pd_tests::parse_model(model, {{"Thermal expansion", "1e-5, 2e-5, 3e-5"}});
  });
  pd_tests::check_refused("anisotropic plane stress, expansion turned about x", [] {
    perideal::AnisotropicPlaneStress model;
    pd_tests::parse_model(model,
                          {{"Young's modulus", "2e11"},
                           {"Poisson's ratio", "0.25"},
                           {"Orientation", "0, 30, 0"},
                           {"Thermal expansion", "1e-5, 2e-5, 3e-5"}});
  });
}
