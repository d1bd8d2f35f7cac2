// The lattice calibration of the fracture energy (<Material/critical stretch/Fracture energy
// calibration> = lattice, issue #40): the bonds that a straight cut breaks, each at the critical
// value of the model's calibration, dissipate G_c per unit crack area on the actual lattice
// (book partial volumes, the energy surface correction), measured through the force kernel.
// Models whose energy is a sum of bond energies (PMB, antiplane bond based, Timoshenko):
// - a field u that holds every bond at its critical value: the uniform expansion u = s0 x
//   (PMB, the Timoshenko bond's stretch mode); the uniform rotation theta = gamma0 with u = 0
//   (the Timoshenko bond's shear mode: |gamma| = gamma0 in 2D, gamma0 |e_a x n| in 3D, so the
//   three axes' rotations sum to twice the energy); the antiplane w = r0 x_a, whose bond slope
//   is r0 n_a, so that the dim axes' fields sum to r0^2 per bond;
// - the model's energy (compute_forces()' energy density) of the particles in a window whose
//   families are complete, with the bonds across the plane x_a = c intact and broken: the
//   difference over the window's area is G;
// G / G_c within 1e-2 for m = delta/dx = 2, 3, 4 in 2D and 3D, on the regular lattice (where the
// cut between two lattice planes is the mean over the cuts, so G = G_c to round-off) and a
// perturbed one (epsilon = 0.3, the mean of four cuts a quarter dx apart).
// State-based models (antiplane state based, LPS), whose energy is not a sum of bond energies:
// a rigid cleave through the kernel with breaking (mode III, mode I), on a box other than the
// calibration's; m = 2, 3, 4 in 2D and 3D.
// Beside each, the continuum calibration's G / G_c, the error the lattice calibration removes.
#include <perideal/pd/antiplane_bond_based.h>
#include <perideal/pd/antiplane_state_based.h>
#include <perideal/pd/bond_based.h>
#include <perideal/pd/linear_peridynamic_solid.h>
#include <perideal/pd/timoshenko_bond_based.h>

#include "../tests.h"
#include "pd_tests.h"

#include <algorithm>
#include <functional>
#include <iomanip>
#include <limits>
#include <type_traits>

using namespace dealii;
using Entries = std::vector<std::pair<std::string, std::string>>;

constexpr double dx = 1e-3, thickness = 1e-3, G0 = 100.;

// A field: component k at the point x.
using Field = std::function<double(const Point<3> &, unsigned int)>;

template <int dim>
Point<3>
to_3d(const Point<dim> &x)
{
  Point<3> p;
  for (unsigned int d = 0; d < dim; ++d)
    p[d] = x[d];
  return p;
}

// The energy the cut x_a = c releases at the field @p field, per unit crack area, counted at
// the particles of the window: |x_b - centre_b| < half_window for the axes b != a.
template <int dim, typename Model>
double
cut_energy(perideal::ParticleSystem<dim> &ps,
           Model                         &model,
           const unsigned int             n_components,
           const Field                   &field,
           const unsigned int             a,
           const double                   c,
           const Point<dim>              &centre,
           const double                   half_window)
{
  perideal::ParticleVector u, f;
  ps.reinit_vector(u, n_components);
  ps.reinit_vector(f, n_components);
  const auto &x = ps.positions();
  for (unsigned int i = 0; i < ps.n_local(); ++i)
    for (unsigned int k = 0; k < n_components; ++k)
      u.local_element(i * n_components + k) = field(to_3d<dim>(x[i]), k);
  const auto in_window = [&](const Point<dim> &p) {
    for (unsigned int b = 0; b < dim; ++b)
      if (b != a && std::abs(p[b] - centre[b]) >= half_window)
        return false;
    return true;
  };
  const auto window_energy = [&]() {
    std::vector<double> w;
    model.compute_forces(ps, u, f, &w, std::numeric_limits<double>::infinity());
    double local = 0.;
    for (unsigned int i = 0; i < ps.n_owned(); ++i)
      if (in_window(x[i]))
        local += w[i] * ps.volumes()[i];
    return Utilities::MPI::sum(local, MPI_COMM_WORLD);
  };
  perideal::BondList             &bonds  = ps.bonds();
  const std::vector<std::uint8_t> intact = bonds.intact;
  const double                    before = window_energy();
  for (unsigned int i = 0; i < ps.n_owned(); ++i)
    for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
      if ((x[i][a] - c) * (x[bonds.neighbor[b]][a] - c) < 0.)
        bonds.break_bond(b);
  const double after = window_energy();
  bonds.set_states(intact);
  const double area = std::pow(2. * half_window, dim - 1) * (dim == 2 ? thickness : 1.);
  return (before - after) / area;
}

// Parse @p entries into @p model and initialize it on @p ps (horizon m dx, plane strain in 2D,
// the energy surface correction) with the lattice calibration if @p on_lattice.
template <int dim, typename Model>
void
set_up(Model                         &model,
       const Entries                 &entries,
       perideal::ParticleSystem<dim> &ps,
       const double                   m,
       const bool                     on_lattice)
{
  pd_tests::parse_model(model, entries);
  auto context             = pd_tests::model_context(m * dx,
                                         thickness,
                                         dim == 2 ? perideal::PlanarAssumption::plane_strain :
                                                                perideal::PlanarAssumption::three_dimensional,
                                         true);
  context.lattice_fracture = on_lattice;
  model.initialize(ps, context);
}

// G / G_c of @p Model (entries @p entries, calibration on the lattice or in the continuum) for
// the fields of @p mode (0: the expansion, or the antiplane slopes; 1: the rotations). The box
// is n + 2 ceil(2m) lattice spacings along every axis, the window n wide in its middle (n = 4 in
// 3D, 12 in 2D), so that every bond of the window's particles and across the cut joins
// particles at least a horizon from the faces (complete families, the surface factors of the
// interior); the cut is the middle plane normal to the last axis.
template <int dim, typename Model>
double
measured_ratio(const Entries &entries,
               const double   m,
               const double   perturbation,
               const bool     on_lattice,
               const unsigned mode)
{
  perideal::ParticleSystem<dim>                    ps(MPI_COMM_WORLD);
  typename perideal::ParticleSystem<dim>::Settings s;
  s.spacing         = dx;
  s.horizon         = m * dx;
  s.thickness       = thickness;
  s.perturbation    = perturbation;
  const double n    = dim == 2 ? 12. : 4.;
  const double side = (n + 2. * std::ceil(2. * m)) * dx;
  Point<dim>   middle, upper;
  for (unsigned int d = 0; d < dim; ++d)
    {
      middle[d] = 0.5 * side;
      upper[d]  = side;
    }
  pd_tests::generate_box<dim>(ps, s, Point<dim>(), upper);

  Model model;
  set_up(model, entries, ps, m, on_lattice);
  const double       s0 = model.critical_stretch(G0);
  const unsigned int nc = model.field_layout().n_components();

  const unsigned int n_cuts = perturbation > 0. ? 4 : 1;
  double             G      = 0.;
  for (unsigned int k = 0; k < n_cuts; ++k)
    {
      const double c   = 0.5 * side + 0.25 * k * dx;
      const auto   cut = [&](const Field &field) {
        return cut_energy<dim>(ps, model, nc, field, dim - 1, c, middle, 0.5 * n * dx);
      };
      if (nc == 1)
        for (unsigned int b = 0; b < dim; ++b)
          G += cut([&](const Point<3> &x, unsigned int) { return s0 * x[b]; });
      else if (mode == 0)
        G += cut([&](const Point<3> &x, unsigned int i) { return i < dim ? s0 * x[i] : 0.; });
      else if constexpr (std::is_same_v<Model, perideal::TimoshenkoBondBased<dim>>)
        {
          const double gamma0 = model.failure_limits(s0)[1];
          for (unsigned int r = 0; r < (dim == 2 ? 1 : 3); ++r)
            G += cut([&](const Point<3> &, unsigned int i) { return i == dim + r ? gamma0 : 0.; }) /
                 (dim == 2 ? 1. : 2.);
        }
    }
  return G / n_cuts / G0;
}

// The lattice and the continuum calibration's G / G_c for m = 2, 3, 4 (and @p perturbed: on the
// perturbed lattice at m = 3).
template <int dim, typename Model>
void
check(const std::string &name,
      const Entries     &entries,
      const unsigned int mode      = 0,
      const bool         perturbed = false)
{
  const auto report = [&](const double m, const double perturbation) {
    const double lattice   = measured_ratio<dim, Model>(entries, m, perturbation, true, mode);
    const double continuum = measured_ratio<dim, Model>(entries, m, perturbation, false, mode);
    deallog << dim << "D " << name << (perturbation > 0. ? ", perturbed" : "") << ", m = " << m
            << ": G/G_c = " << std::setprecision(5) << lattice << " "
            << pd_tests::ok(std::abs(lattice - 1.) < 1e-2) << " (continuum calibration "
            << continuum << ")" << std::setprecision(6) << std::endl;
  };
  for (const double m : {2.015, 3.015, 4.015})
    report(m, 0.);
  if (perturbed)
    report(3.015, 0.3);
}

// The state-based models, whose energy is not a sum of bond energies: a cleave through the
// kernel with breaking at the critical value c = critical_stretch(G_c), mode III for the
// antiplane model (the upper half's w jumps; a bond across the cut reaches the critical slope at
// Delta = c |xi|), mode I for LPS (the upper half's u_y, u_z in 3D, jumps; the stretch reaches c
// at Delta = sqrt(xi_n^2 + (2 c + c^2) |xi|^2) - xi_n). A box 24 dx high (the cut in its
// middle) and 40 dx wide in 2D, the window the middle 16 dx; in 3D 20 dx wide, the window
// 4 dx x 4 dx. Delta takes these values of the lattice's bonds in turn (times 1 + 1e-9), so every
// bond across the cut breaks just above its critical value; the drops of the window's energy at
// each jump sum to G.
template <int dim, typename Model>
double
cleave(const Entries &entries, const double m, const bool on_lattice)
{
  perideal::ParticleSystem<dim>                    ps(MPI_COMM_WORLD);
  typename perideal::ParticleSystem<dim>::Settings s;
  s.spacing          = dx;
  s.horizon          = m * dx;
  s.thickness        = thickness;
  const double width = (dim == 2 ? 40. : 20.) * dx, window = (dim == 2 ? 16. : 4.) * dx;
  Point<dim>   upper;
  for (unsigned int d = 0; d < dim; ++d)
    upper[d] = d + 1 < dim ? width : 24. * dx;
  pd_tests::generate_box<dim>(ps, s, Point<dim>(), upper);
  Model model;
  set_up(model, entries, ps, m, on_lattice);
  const double             c  = model.critical_stretch(G0);
  const unsigned int       nc = model.field_layout().n_components();
  perideal::ParticleVector u, f;
  ps.reinit_vector(u, nc);
  ps.reinit_vector(f, nc);
  const auto &x             = ps.positions();
  const auto  window_energy = [&]() {
    std::vector<double> w;
    model.compute_forces(ps, u, f, &w, std::numeric_limits<double>::infinity());
    double local = 0.;
    for (unsigned int i = 0; i < ps.n_owned(); ++i)
      {
        bool inside = true;
        for (unsigned int a = 0; a + 1 < dim; ++a)
          inside = inside && std::abs(x[i][a] - 0.5 * width) < 0.5 * window;
        if (inside)
          local += w[i] * ps.volumes()[i];
      }
    return Utilities::MPI::sum(local, MPI_COMM_WORLD);
  };
  std::vector<Tensor<1, dim>> xi;
  std::vector<double>         weight;
  ps.lattice_family(xi, weight);
  std::vector<double> jumps;
  for (const auto &v : xi)
    if (v[dim - 1] > 0.)
      {
        const double r = v.norm(), n = v[dim - 1];
        jumps.push_back(nc == 1 ? c * r : std::sqrt(n * n + (2. + c) * c * r * r) - n);
      }
  std::sort(jumps.begin(), jumps.end());
  double G = 0., last = 0.;
  for (const double jump : jumps)
    if (jump > last * (1. + 1e-9))
      {
        last = jump;
        for (unsigned int i = 0; i < ps.n_local(); ++i)
          u.local_element(i * nc + (nc == 1 ? 0 : dim - 1)) =
            x[i][dim - 1] > 12. * dx ? jump * (1. + 1e-9) : 0.;
        const double before = window_energy();
        model.compute_forces(ps, u, f, nullptr, c);
        G += before - window_energy();
      }
  return G / (std::pow(window, dim - 1) * (dim == 2 ? thickness : 1.)) / G0;
}

template <int dim, typename Model>
void
check_cleave(const std::string &name, const Entries &entries, const std::vector<double> &ms)
{
  for (const double m : ms)
    {
      const double lattice   = cleave<dim, Model>(entries, m, true);
      const double continuum = cleave<dim, Model>(entries, m, false);
      deallog << dim << "D " << name << ", m = " << m
              << ", cleave: G/G_c = " << std::setprecision(5) << lattice << " "
              << pd_tests::ok(std::abs(lattice - 1.) < 1e-2) << " (continuum calibration "
              << continuum << ")" << std::setprecision(6) << std::endl;
    }
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();

  const Entries pmb       = {{"Young's modulus", "1e9"}};
  const Entries antiplane = {{"Shear modulus", "1e9"}};
  check<2, perideal::BondBased<2>>("PMB", pmb, 0, true);
  check<3, perideal::BondBased<3>>("PMB", pmb);
  check<2, perideal::AntiplaneBondBased<2>>("antiplane bond based", antiplane, 0, true);
  check<3, perideal::AntiplaneBondBased<3>>("antiplane bond based", antiplane);
  check<2, perideal::TimoshenkoBondBased<2>>("Timoshenko, stretch", pd_tests::timoshenko_entries);
  check<2, perideal::TimoshenkoBondBased<2>>("Timoshenko, shear", pd_tests::timoshenko_entries, 1);
  check<3, perideal::TimoshenkoBondBased<3>>("Timoshenko, stretch", pd_tests::timoshenko_entries);
  check<3, perideal::TimoshenkoBondBased<3>>("Timoshenko, shear", pd_tests::timoshenko_entries, 1);
  const Entries sb  = {{"Shear modulus", "1e9"}, {"Stabilization", "0.1"}};
  const Entries lps = {{"Young's modulus", "1e9"}, {"Poisson's ratio", "0.3"}};
  check_cleave<2, perideal::AntiplaneStateBased<2>>("antiplane state based, alpha = 0.1",
                                                    sb,
                                                    {2.015, 3.015, 4.015});
  check_cleave<2, perideal::AntiplaneStateBased<2>>("antiplane state based, alpha = 0",
                                                    {{"Shear modulus", "1e9"},
                                                     {"Stabilization", "0"}},
                                                    {3.015});
  check_cleave<3, perideal::AntiplaneStateBased<3>>("antiplane state based, alpha = 0.1",
                                                    sb,
                                                    {2.015, 3.015, 4.015});
  check_cleave<2, perideal::LinearPeridynamicSolid<2>>("LPS, nu = 0.3", lps, {2.015, 3.015, 4.015});
  check_cleave<3, perideal::LinearPeridynamicSolid<3>>("LPS, nu = 0.3", lps, {2.015, 3.015, 4.015});
}
