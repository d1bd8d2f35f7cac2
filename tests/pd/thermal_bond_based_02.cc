// Thermal strain of the bond-based models (doc/theory/thermal_strain.md), energy and statics:
//  - force = -grad E with a nonuniform temperature change (a random Delta T of up to 100 K per
//    particle, thermal stretches up to 3e-3) and a random field u of strains about 1e-3 (as
//    energy_balance_01): the directional derivative of the
//    total energy by central differences against -sum_i f_i . v_i V_i, relative 1e-8, for bond
//    based, anisotropic bond based and timoshenko bond based in 2D and 3D;
//  - linearize() with its offsets against compute_forces() for the models that are linear
//    (anisotropic, Timoshenko) with the same Delta T: -(1/V) G^T diag(w) (G u - o) equals the
//    force density, and 1/2 sum w (G u - o)^2 the energy, relative 1e-10 of the largest force;
//  - the PD static solver (StaticSolver, the load G^T diag(w) o of the offsets) on a free block
//    (2D 12 x 12, 3D 8^3 particles) under a uniform Delta T = 10 K held by minimal supports (one
//    particle fixed, one particle's transverse components on a line and, in 3D, one component of
//    a third particle; the values of the exact field there): u = alpha_p Delta T x to the
//    solver's tolerance, max |u - u_exact| / max |u_exact| < 1e-7, rotations 0 for Timoshenko.
// Dropping the offsets (or the thermal term of the kernels) makes each check fail.
//
// With the environment variable PERIDEAL_THERMAL_BENCHMARK=N (not in ctest), the program also
// times PMB's compute_forces() on the 41^3 lattice of doc/benchmarks/performance/pmb_lattice_3d.prm
// (book partial volumes, surface correction, critical stretch 5e-4, u = 0) in N alternating
// rounds of 50 evaluations without and with a uniform temperature change, and prints the bond
// updates per second of each round to std::cout (doc/benchmarks/performance/README.md).
#include <perideal/pd/anisotropic_bond_based.h>
#include <perideal/pd/bond_based.h>
#include <perideal/pd/static_solver.h>
#include <perideal/pd/timoshenko_bond_based.h>

#include "../tests.h"
#include "pd_tests.h"

#include <chrono>
#include <cstdlib>
#include <iostream>
#include <limits>

namespace
{
  using namespace dealii;
  using Entries       = std::vector<std::pair<std::string, std::string>>;
  const MPI_Comm comm = MPI_COMM_WORLD;
  const double   inf  = std::numeric_limits<double>::infinity();

  std::string
  label_of(const std::string &name, const int dim, const perideal::PlanarAssumption planar)
  {
    return name + " (" + std::to_string(dim) + "D, " + pd_tests::planar_name(planar) + ")";
  }

  template <int dim>
  double
  total_energy(perideal::MaterialModel<dim>   &model,
               perideal::ParticleSystem<dim>  &ps,
               const perideal::ParticleVector &u,
               perideal::ParticleVector       &f)
  {
    std::vector<double> w;
    ps.reinit_vector(f, model.field_layout().n_components());
    model.compute_forces(ps, u, f, &w, inf);
    double energy = 0.;
    for (unsigned int i = 0; i < ps.n_owned(); ++i)
      energy += w[i] * ps.volumes()[i];
    return Utilities::MPI::sum(energy, comm);
  }

  template <int dim>
  void
  random_field(const perideal::ParticleSystem<dim> &ps,
               const unsigned int                   nc,
               const double                         scale,
               const double                         dx,
               const unsigned int                   seed,
               perideal::ParticleVector            &u)
  {
    ps.reinit_vector(u, nc);
    for (unsigned int i = 0; i < ps.n_local(); ++i)
      for (unsigned int c = 0; c < nc; ++c)
        u.local_element(i * nc + c) =
          (c >= unsigned(dim) ? scale / dx : scale) *
          pd_tests::random_number((seed * 1000003ULL + ps.invariant_index(i)) * nc + c);
  }

  template <typename Model, int dim>
  void
  check_energy(const std::string               &name,
               const Entries                   &entries,
               const perideal::PlanarAssumption planar,
               const bool                       linear)
  {
    const std::string   label = label_of(name, dim, planar);
    const double        dx    = 1e-3;
    pd_tests::Body<dim> body(dim == 2 ? 12 : 6,
                             dx,
                             3.015,
                             perideal::PartialVolume::geometric,
                             1e-3);
    Model model;
    pd_tests::parse_model(model, entries);
    model.initialize(body.ps, pd_tests::model_context(body.delta, 1e-3, planar, true));
    const unsigned int       nc = model.field_layout().n_components();
    perideal::ParticleVector delta_T, u, v, f, g, u_plus, u_minus;
    random_field<dim>(body.ps, 1, 100., 1., 3, delta_T);
    model.set_temperature_change(&delta_T);
    random_field<dim>(body.ps, nc, 1e-3 * dx, dx, 1, u);
    random_field<dim>(body.ps, nc, 1e-3 * dx, dx, 2, v);
    const double energy = total_energy(model, body.ps, u, f);
    const double h      = 1e-4;
    u_plus              = u;
    u_plus.add(h, v);
    u_minus = u;
    u_minus.add(-h, v);
    u_plus.update_ghost_values();
    u_minus.update_ghost_values();
    const double difference =
      (total_energy(model, body.ps, u_plus, g) - total_energy(model, body.ps, u_minus, g)) /
      (2. * h);
    double work = 0.;
    for (unsigned int i = 0; i < body.ps.n_owned(); ++i)
      for (unsigned int c = 0; c < nc; ++c)
        work -= f.local_element(i * nc + c) * v.local_element(i * nc + c) * body.ps.volumes()[i];
    work               = Utilities::MPI::sum(work, comm);
    const double error = std::abs(difference - work) / std::abs(work);
    deallog << label << ", random Delta T: |dE/dv + F.v| / |F.v| < 1e-8 "
            << pd_tests::ok(error < 1e-8);
    if (!(error < 1e-8))
      deallog << " (" << error << ")";
    deallog << std::endl;
    if (!linear)
      return;

    // linearize() with its offsets against the kernel.
    perideal::LinearizedModel linearized;
    model.linearize(body.ps, linearized);
    perideal::ParticleVector f_linear;
    body.ps.reinit_vector(f_linear, nc);
    double energy_linear = 0.;
    for (std::size_t r = 0; r < linearized.n_rows(); ++r)
      {
        double e = -linearized.offset(r);
        for (auto entry = linearized.row_begin(r); entry != linearized.row_end(r); ++entry)
          e += entry->coefficient * u.local_element(nc * entry->particle + entry->component);
        energy_linear += 0.5 * linearized.weight(r) * e * e;
        for (auto entry = linearized.row_begin(r); entry != linearized.row_end(r); ++entry)
          f_linear.local_element(nc * entry->particle + entry->component) -=
            linearized.weight(r) * e * entry->coefficient / body.ps.volumes()[entry->particle];
      }
    f_linear.compress(VectorOperation::add);
    energy_linear  = Utilities::MPI::sum(energy_linear, comm);
    double largest = 0., miss = 0.;
    for (unsigned int k = 0; k < body.ps.n_owned() * nc; ++k)
      {
        largest = std::max(largest, std::abs(f.local_element(k)));
        miss    = std::max(miss, std::abs(f.local_element(k) - f_linear.local_element(k)));
      }
    miss                     = Utilities::MPI::max(miss, comm) / Utilities::MPI::max(largest, comm);
    const double energy_miss = std::abs(energy_linear / energy - 1.);
    deallog << label << ", linearize() with offsets = kernel: forces " << pd_tests::ok(miss < 1e-10)
            << ", energy " << pd_tests::ok(energy_miss < 1e-10);
    if (!(miss < 1e-10 && energy_miss < 1e-10))
      deallog << " (" << miss << ", " << energy_miss << ")";
    deallog << std::endl;
  }

  template <typename Model, int dim>
  void
  check_static(const std::string               &name,
               const Entries                   &entries,
               const perideal::PlanarAssumption planar)
  {
    const std::string   label = label_of(name, dim, planar);
    const double        dx    = 1e-3;
    const int           n     = dim == 2 ? 12 : 8;
    pd_tests::Body<dim> body(n, dx, 3.015, perideal::PartialVolume::geometric, 1e-3);
    Model               model;
    pd_tests::parse_model(model, entries);
    model.initialize(body.ps, pd_tests::model_context(body.delta, 1e-3, planar, true));
    const unsigned int       nc    = model.field_layout().n_components();
    const auto               alpha = model.thermal_expansion();
    const double             T     = 10.;
    perideal::ParticleVector delta_T, prescribed, zero, u;
    body.ps.reinit_vector(delta_T, 1);
    for (unsigned int i = 0; i < body.ps.n_local(); ++i)
      delta_T.local_element(i) = T;
    model.set_temperature_change(&delta_T);
    body.ps.reinit_vector(prescribed, nc);
    body.ps.reinit_vector(zero, nc);
    body.ps.reinit_vector(u, nc);
    // Supports: the particle at lattice (0, 0, 0) holds all translations, (n - 1, 0, 0) the
    // transverse ones, (0, n - 1, 0) the z component (3D).
    const auto exact = [&](const unsigned int i) { return T * (alpha * body.ps.positions()[i]); };
    for (unsigned int i = 0; i < body.ps.n_owned(); ++i)
      {
        const std::uint64_t       index = body.lattice_index(i);
        std::vector<unsigned int> held;
        if (index == 0)
          for (unsigned int d = 0; d < dim; ++d)
            held.push_back(d);
        else if (index == std::uint64_t(n - 1))
          for (unsigned int d = 1; d < dim; ++d)
            held.push_back(d);
        else if (dim == 3 && index == std::uint64_t(n) * (n - 1))
          held.push_back(dim - 1);
        const auto value = exact(i);
        for (const unsigned int d : held)
          {
            prescribed.local_element(i * nc + d) = 1.;
            u.local_element(i * nc + d)          = value[d];
          }
      }
    typename perideal::StaticSolver<dim>::Settings settings;
    settings.tolerance = 1e-12;
    perideal::StaticSolver<dim> solver(settings);
    solver.solve(body.ps, model, prescribed, zero, u, "minimal supports");
    double miss = 0., largest = 0., rotation = 0.;
    for (unsigned int i = 0; i < body.ps.n_owned(); ++i)
      {
        const auto value = exact(i);
        for (unsigned int d = 0; d < dim; ++d)
          {
            miss    = std::max(miss, std::abs(u.local_element(i * nc + d) - value[d]));
            largest = std::max(largest, std::abs(value[d]));
          }
        for (unsigned int c = dim; c < nc; ++c)
          rotation = std::max(rotation, std::abs(u.local_element(i * nc + c)) * dx);
      }
    miss     = Utilities::MPI::max(miss, comm) / Utilities::MPI::max(largest, comm);
    rotation = Utilities::MPI::max(rotation, comm) / Utilities::MPI::max(largest, comm);
    deallog << label << ", static solve of the free block, uniform Delta T: "
            << "max |u - alpha Delta T x| / max |u| < 1e-7 " << pd_tests::ok(miss < 1e-7);
    if (nc > unsigned(dim))
      deallog << ", rotations dx / max |u| < 1e-7 " << pd_tests::ok(rotation < 1e-7);
    if (!(miss < 1e-7 && rotation < 1e-7))
      deallog << " (" << miss << ", " << rotation << ")";
    deallog << std::endl;
  }
  // The timing of PERIDEAL_THERMAL_BENCHMARK (see the head of the file).
  void
  benchmark(const unsigned int rounds)
  {
    const double                          dx = 5e-4;
    perideal::ParticleSystem<3>::Settings settings;
    settings.spacing        = dx;
    settings.horizon        = 3.015 * dx;
    settings.partial_volume = perideal::PartialVolume::book;
    perideal::ParticleSystem<3> ps(comm);
    pd_tests::generate_box<3>(ps, settings, Point<3>(), Point<3>(41 * dx, 41 * dx, 41 * dx));
    perideal::BondBased<3> model;
    pd_tests::parse_model(model, {{"Young's modulus", "72e9"}, {"Thermal expansion", "1e-5"}});
    model.initialize(ps,
                     pd_tests::model_context(settings.horizon,
                                             1.,
                                             perideal::PlanarAssumption::three_dimensional,
                                             true));
    double bonds = 0.;
    for (std::size_t b = 0; b < ps.bonds().size(); ++b)
      bonds += ps.bond_share(b);
    bonds = Utilities::MPI::sum(bonds, comm);
    perideal::ParticleVector u, f, delta_T;
    ps.reinit_vector(u, 3);
    ps.reinit_vector(f, 3);
    ps.reinit_vector(delta_T, 1);
    for (unsigned int i = 0; i < ps.n_local(); ++i)
      delta_T.local_element(i) = 10.;
    const unsigned int evaluations = 50;
    for (unsigned int r = 0; r < rounds; ++r)
      for (const bool thermal : {false, true})
        {
          model.set_temperature_change(thermal ? &delta_T : nullptr);
          const auto start = std::chrono::steady_clock::now();
          for (unsigned int e = 0; e < evaluations; ++e)
            model.compute_forces(ps, u, f, nullptr, 5e-4);
          const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
          if (Utilities::MPI::this_mpi_process(comm) == 0)
            std::cout << "round " << r << (thermal ? ", with Delta T" : ", without Delta T")
                      << ": bond updates per second " << bonds * evaluations / seconds << std::endl;
        }
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();
  deallog.depth_file(1);
  using perideal::PlanarAssumption;
  const Entries pmb   = {{"Young's modulus", "2e11"}, {"Thermal expansion", "1e-5"}};
  Entries       aniso = pd_tests::nacl_entries;
  aniso.push_back({"Thermal expansion", "1e-5, 2e-5, 3e-5"});
  Entries timoshenko = pd_tests::timoshenko_entries;
  timoshenko.push_back({"Thermal expansion", "1e-5"});

  check_energy<perideal::BondBased<2>, 2>("bond based", pmb, PlanarAssumption::plane_stress, false);
  check_energy<perideal::BondBased<3>, 3>("bond based",
                                          pmb,
                                          PlanarAssumption::three_dimensional,
                                          false);
  check_energy<perideal::AnisotropicBondBased<2>, 2>("anisotropic bond based",
                                                     aniso,
                                                     PlanarAssumption::plane_strain,
                                                     true);
  check_energy<perideal::AnisotropicBondBased<3>, 3>("anisotropic bond based",
                                                     aniso,
                                                     PlanarAssumption::three_dimensional,
                                                     true);
  check_energy<perideal::TimoshenkoBondBased<2>, 2>("timoshenko bond based",
                                                    timoshenko,
                                                    PlanarAssumption::plane_strain,
                                                    true);
  check_energy<perideal::TimoshenkoBondBased<3>, 3>("timoshenko bond based",
                                                    timoshenko,
                                                    PlanarAssumption::three_dimensional,
                                                    true);

  check_static<perideal::BondBased<2>, 2>("bond based", pmb, PlanarAssumption::plane_stress);
  check_static<perideal::BondBased<3>, 3>("bond based", pmb, PlanarAssumption::three_dimensional);
  check_static<perideal::AnisotropicBondBased<2>, 2>("anisotropic bond based",
                                                     aniso,
                                                     PlanarAssumption::plane_strain);
  check_static<perideal::AnisotropicBondBased<3>, 3>("anisotropic bond based",
                                                     aniso,
                                                     PlanarAssumption::three_dimensional);
  check_static<perideal::TimoshenkoBondBased<2>, 2>("timoshenko bond based",
                                                    timoshenko,
                                                    PlanarAssumption::plane_stress);
  check_static<perideal::TimoshenkoBondBased<3>, 3>("timoshenko bond based",
                                                    timoshenko,
                                                    PlanarAssumption::three_dimensional);

  if (const char *rounds = std::getenv("PERIDEAL_THERMAL_BENCHMARK"))
    benchmark(std::atoi(rounds));
}
