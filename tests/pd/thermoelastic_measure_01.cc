// The thermoelastic measure of the particle models (MaterialModel::thermoelastic_measure(),
// doc/theory/thermoelasticity.md): m_i = -(1/V_i) dE/dDeltaT_i at no temperature change, the
// quantity whose rate heats a two-way coupled temperature. For PMB and LPS in 3D, plane strain
// and plane stress, the anisotropic bond-based model (cubic NaCl constants, an orthotropic
// expansion) in 3D and plane strain and its plane-stress counterpart (anisotropic plane
// stress, NaCl turned about z), and the Timoshenko bonds (rotations held at zero in the
// homogeneous strain) in 3D, plane strain and plane stress, with the surface correction:
//  - it is the exact derivative of the model's energy: under a random displacement, m_l V_l
//    against -dE/dDeltaT_l by central differences for particles on the surface, in the interior
//    and between (E is quadratic in DeltaT, so the difference is exact up to round-off);
//  - under a homogeneous strain eps the interior particles give beta : eps, beta = C : a of the
//    model's tensor C and in-plane expansion a, within the model's own interior error (the
//    strain-energy density against 1/2 eps : C : eps, printed beside it), more than two
//    horizons from the surface;
//  - bonds broken do not count: a cut through the body changes nothing beyond the model's
//    reach (one horizon for PMB, two for LPS) and a third or more at the cut.

#include <deal.II/base/mpi.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/utilities.h>

#include <perideal/pd/anisotropic_bond_based.h>
#include <perideal/pd/anisotropic_plane_stress.h>
#include <perideal/pd/bond_based.h>
#include <perideal/pd/linear_peridynamic_solid.h>
#include <perideal/pd/particle_system.h>
#include <perideal/pd/timoshenko_bond_based.h>

#include "../tests.h"
#include "pd_tests.h"

#include <cmath>
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

  const double alpha = 1.2e-5, dx = 1e-3, h = 1e-3;
  const double inf = std::numeric_limits<double>::infinity();

  template <int dim>
  std::unique_ptr<perideal::MaterialModel<dim>>
  make_model(const std::string &name, Body<dim> &body, const perideal::PlanarAssumption planar)
  {
    std::unique_ptr<perideal::MaterialModel<dim>> model;
    if (name == "bond based")
      {
        auto pmb = std::make_unique<perideal::BondBased<dim>>();
        pd_tests::parse_model(*pmb,
                              {{"Young's modulus", "200e9"}, {"Thermal expansion", "1.2e-5"}});
        model = std::move(pmb);
      }
    else if (name == "anisotropic bond based")
      {
        auto aniso   = std::make_unique<perideal::AnisotropicBondBased<dim>>();
        auto entries = pd_tests::nacl_entries;
        entries.push_back({"Thermal expansion", "1e-5, 2e-5, 3e-5"});
        pd_tests::parse_model(*aniso, entries);
        model = std::move(aniso);
      }
    else if (name == "anisotropic plane stress")
      {
        if constexpr (dim == 2)
          {
            auto plane   = std::make_unique<perideal::AnisotropicPlaneStress>();
            auto entries = pd_tests::nacl_about_z_entries;
            entries.push_back({"Thermal expansion", "1e-5, 2e-5, 3e-5"});
            pd_tests::parse_model(*plane, entries);
            model = std::move(plane);
          }
      }
    else if (name == "timoshenko bond based")
      {
        auto timoshenko = std::make_unique<perideal::TimoshenkoBondBased<dim>>();
        auto entries    = pd_tests::timoshenko_entries;
        entries.push_back({"Thermal expansion", "1.2e-5"});
        pd_tests::parse_model(*timoshenko, entries);
        model = std::move(timoshenko);
      }
    else
      {
        auto lps = std::make_unique<perideal::LinearPeridynamicSolid<dim>>();
        pd_tests::parse_model(*lps,
                              {{"Young's modulus", "200e9"},
                               {"Poisson's ratio", "0.3"},
                               {"Thermal expansion", "1.2e-5"}});
        model = std::move(lps);
      }
    model->initialize(body.ps, pd_tests::model_context(body.delta, h, planar, true));
    return model;
  }

  // @p u (dim components, every local value set) widened in place to the unknowns of @p model:
  // the rotations of the Timoshenko bonds random (of the size of the strains) if
  // @p random_rotations, else zero.
  template <int dim>
  void
  widen(const Body<dim>                    &body,
        const perideal::MaterialModel<dim> &model,
        perideal::ParticleVector           &u,
        const bool                          random_rotations)
  {
    const unsigned int nc = model.field_layout().n_components();
    if (nc == dim)
      return;
    perideal::ParticleVector v;
    body.ps.reinit_vector(v, nc);
    for (unsigned int i = 0; i < body.ps.n_local(); ++i)
      for (unsigned int c = 0; c < nc; ++c)
        v.local_element(i * nc + c) =
          c < dim          ? u.local_element(i * dim + c) :
          random_rotations ? 1e-3 * random_number(body.lattice_index(i) * nc + c) :
                             0.;
    // A swap keeps the ghost values (an assignment would not).
    u.swap(v);
  }

  // The energy sum_i W_i V_i of @p u with the temperature change @p delta_T (nullptr: none).
  template <int dim>
  double
  energy(Body<dim>                      &body,
         perideal::MaterialModel<dim>   &model,
         const perideal::ParticleVector &u,
         const perideal::ParticleVector *delta_T)
  {
    perideal::ParticleVector f;
    body.ps.reinit_vector(f, model.field_layout().n_components());
    std::vector<double> w;
    model.set_temperature_change(delta_T);
    model.compute_forces(body.ps, u, f, &w, inf);
    model.set_temperature_change(nullptr);
    double e = 0.;
    for (unsigned int i = 0; i < body.ps.n_owned(); ++i)
      e += w[i] * body.ps.volumes()[i];
    return dealii::Utilities::MPI::sum(e, MPI_COMM_WORLD);
  }

  // m_l V_l of the particle with lattice index @p index (summed over the ranks: one owns it).
  template <int dim>
  double
  measure_of(const Body<dim> &body, const std::vector<double> &m, const std::uint64_t index)
  {
    double value = 0.;
    for (unsigned int i = 0; i < body.ps.n_owned(); ++i)
      if (body.lattice_index(i) == index)
        value = m[i] * body.ps.volumes()[i];
    return dealii::Utilities::MPI::sum(value, MPI_COMM_WORLD);
  }

  template <int dim>
  void
  check(const std::string &name, const perideal::PlanarAssumption planar)
  {
    // The anisotropic model's discrete calibration needs more than the 3D lattice's 2.015 dx
    // (its mean micromodulus is not positive there): 3.015 dx and a larger block for an interior.
    const bool wide = dim == 3 && name == "anisotropic bond based";
    const int  n    = dim == 2 ? 24 : wide ? 16 : 12;
    Body<dim>  body(n, dx, dim == 2 || wide ? 3.015 : 2.015, perideal::PartialVolume::book, h);
    auto       model = make_model<dim>(name, body, planar);
    deallog << name << ", " << pd_tests::planar_name(planar) << ": thermoelastic_heating "
            << ok(model->capabilities().thermoelastic_heating) << std::endl;

    // The derivative of the energy under a random displacement.
    perideal::ParticleVector u;
    body.set_field(u, [&](const unsigned int i) {
      dealii::Tensor<1, dim> v;
      for (unsigned int d = 0; d < dim; ++d)
        v[d] = 1e-3 * dx * random_number(body.lattice_index(i) * dim + d);
      return v;
    });
    widen<dim>(body, *model, u, true);
    std::vector<double> m;
    model->thermoelastic_measure(body.ps, u, m);
    double scale = 0.;
    for (unsigned int i = 0; i < body.ps.n_owned(); ++i)
      scale = std::max(scale, std::abs(m[i] * body.ps.volumes()[i]));
    scale        = dealii::Utilities::MPI::max(scale, MPI_COMM_WORLD);
    double worst = 0.;
    // A corner, a face, the middle (lattice indices).
    std::uint64_t middle = 0, face = 0;
    for (unsigned int d = dim; d-- > 0;)
      {
        middle = middle * n + n / 2;
        face   = face * n + (d == 0 ? 0 : n / 2);
      }
    for (const std::uint64_t index : {std::uint64_t(0), face, middle})
      {
        perideal::ParticleVector delta_T;
        const double             step    = 1.;
        const auto               shifted = [&](const double value) {
          body.ps.reinit_vector(delta_T, 1);
          for (unsigned int i = 0; i < body.ps.n_local(); ++i)
            delta_T.local_element(i) = body.lattice_index(i) == index ? value : 0.;
          return energy<dim>(body, *model, u, &delta_T);
        };
        const double derivative = (shifted(step) - shifted(-step)) / (2. * step);
        worst = std::max(worst, std::abs(measure_of<dim>(body, m, index) + derivative));
      }
    deallog << "  m V = -dE/dDeltaT (corner, face, middle) to round-off (< 1e-9 of max |m V|) "
            << ok(worst < 1e-9 * scale) << std::endl;

    // A homogeneous strain: beta : eps in the interior.
    dealii::SymmetricTensor<2, dim> eps;
    eps[0][0] = 1e-4;
    eps[1][1] = -0.3e-4;
    eps[0][1] = 0.5e-4;
    if (dim == 3)
      eps[2][2] = 0.7e-4;
    body.set_field(u, [&](const unsigned int i) {
      return dealii::Tensor<1, dim>(eps * dealii::Tensor<1, dim>(body.ps.positions()[i]));
    });
    widen<dim>(body, *model, u, false);
    model->thermoelastic_measure(body.ps, u, m);
    perideal::ParticleVector f;
    body.ps.reinit_vector(f, model->field_layout().n_components());
    std::vector<double> w;
    model->compute_forces(body.ps, u, f, &w, inf);
    const auto   C             = model->elasticity_tensor();
    const double expected      = (C * model->thermal_expansion()) * eps;
    const double W             = 0.5 * eps * (C * eps);
    double       measure_error = 0., energy_error = 0.;
    for (unsigned int i = 0; i < body.ps.n_owned(); ++i)
      if (body.depth(i) * dx > 2. * body.delta)
        {
          measure_error = std::max(measure_error, std::abs(m[i] / expected - 1.));
          energy_error  = std::max(energy_error, std::abs(w[i] / W - 1.));
        }
    measure_error = dealii::Utilities::MPI::max(measure_error, MPI_COMM_WORLD);
    energy_error  = dealii::Utilities::MPI::max(energy_error, MPI_COMM_WORLD);
    deallog << "  homogeneous strain, interior: m / (beta : eps) - 1 = " << std::setprecision(3)
            << measure_error << " (energy density: " << energy_error << ") "
            << ok(measure_error < 1.5e-2) << std::setprecision(6) << std::endl;

    // Broken bonds: cut every bond across the plane x = n dx / 2 of a uniform dilatation.
    body.set_field(u, [&](const unsigned int i) {
      return dealii::Tensor<1, dim>(1e-4 * body.ps.positions()[i]);
    });
    widen<dim>(body, *model, u, false);
    model->thermoelastic_measure(body.ps, u, m);
    const std::vector<double> intact = m;
    auto                     &bonds  = body.ps.bonds();
    std::vector<std::uint8_t> states(bonds.intact.begin(), bonds.intact.end());
    const double              plane = n * dx / 2.;
    for (unsigned int i = 0; i < body.ps.n_owned(); ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        if ((body.ps.positions()[i][0] - plane) *
              (body.ps.positions()[bonds.neighbor[b]][0] - plane) <
            0.)
          states[b] = 0;
    bonds.set_states(states);
    model->thermoelastic_measure(body.ps, u, m);
    double change_far = 0., change_near = 0.;
    for (unsigned int i = 0; i < body.ps.n_owned(); ++i)
      {
        const double distance = std::abs(body.ps.positions()[i][0] - plane);
        const double change   = std::abs(m[i] / intact[i] - 1.);
        if (distance > model->force_reach() * body.delta)
          change_far = std::max(change_far, change);
        else if (distance < dx)
          change_near = std::max(change_near, change);
      }
    change_far  = dealii::Utilities::MPI::max(change_far, MPI_COMM_WORLD);
    change_near = dealii::Utilities::MPI::max(change_near, MPI_COMM_WORLD);
    deallog << "  a cut: unchanged beyond the model's reach " << ok(change_far < 1e-12)
            << ", the layer at the cut loses " << std::setprecision(2) << change_near
            << std::setprecision(6) << " of its measure " << ok(change_near > 0.3) << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();
  for (const std::string name : {"bond based", "linear peridynamic solid"})
    {
      check<3>(name, perideal::PlanarAssumption::three_dimensional);
      check<2>(name, perideal::PlanarAssumption::plane_strain);
      check<2>(name, perideal::PlanarAssumption::plane_stress);
    }
  // Its plane-stress counterpart is a model of its own: NaCl turned about z, an orthotropic
  // expansion.
  check<3>("anisotropic bond based", perideal::PlanarAssumption::three_dimensional);
  check<2>("anisotropic bond based", perideal::PlanarAssumption::plane_strain);
  check<2>("anisotropic plane stress", perideal::PlanarAssumption::plane_stress);
  check<3>("timoshenko bond based", perideal::PlanarAssumption::three_dimensional);
  check<2>("timoshenko bond based", perideal::PlanarAssumption::plane_strain);
  check<2>("timoshenko bond based", perideal::PlanarAssumption::plane_stress);
}
