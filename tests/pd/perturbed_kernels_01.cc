// The force kernels on a perturbed lattice (ParticleSystem::Settings::perturbation = 1/2: every
// bond has its own reference vector, which the bond blocks stream per lane, BondBlocks::
// lane_bonds()) against each model's static linearization, which builds its rows from the
// particles' positions and BondList::length (an independent code path): for a small random
// field, max |f_kernel - f_linearized| / max |f_kernel| and the energies, for every model with a
// bond-block kernel, 2D and 3D, surface correction on, on 1 and 2 ranks (bonds to ghosts). The
// linear models (the Timoshenko bonds' kernel is linear too) agree to round-off (< 1e-10); PMB and
// LPS use the deformed bond (|xi + eta|) and agree to the order of the strain, 1e-6 here (< 1e-4;
// printed). The same comparison on the regular lattice (epsilon = 0) is printed as a control. A
// kernel that used its class's lattice vector instead of the bond's own fails by the size of the
// offsets (about 10 %).
#include <perideal/pd/anisotropic_bond_based.h>
#include <perideal/pd/anisotropic_plane_stress.h>
#include <perideal/pd/antiplane_bond_based.h>
#include <perideal/pd/antiplane_state_based.h>
#include <perideal/pd/bond_based.h>
#include <perideal/pd/linear_peridynamic_solid.h>
#include <perideal/pd/timoshenko_bond_based.h>

#include "../tests.h"
#include "pd_tests.h"

#include <limits>

namespace
{
  using namespace dealii;
  using Entries       = std::vector<std::pair<std::string, std::string>>;
  const MPI_Comm comm = MPI_COMM_WORLD;

  template <typename Model, int dim>
  void
  compare(const std::string               &label,
          const Entries                   &entries,
          const perideal::PlanarAssumption planar,
          const double                     tolerance)
  {
    for (const double epsilon : {0., 0.5})
      {
        const double                                     dx = 1e-3, n = (dim == 2 ? 16 : 9);
        typename perideal::ParticleSystem<dim>::Settings s;
        s.spacing           = dx;
        s.horizon           = 3.015 * dx;
        s.thickness         = 1e-3;
        s.partial_volume    = perideal::PartialVolume::book;
        s.perturbation      = epsilon;
        s.perturbation_seed = 3;
        perideal::ParticleSystem<dim> ps(comm);
        Point<dim>                    upper;
        for (unsigned int d = 0; d < dim; ++d)
          upper[d] = n * dx;
        pd_tests::generate_box<dim>(ps, s, Point<dim>(), upper);
        Model model;
        pd_tests::parse_model(model, entries);
        model.initialize(ps, pd_tests::model_context(s.horizon, s.thickness, planar, true));

        // Random field: translations and scalars 1e-9 m (strains about 1e-6), rotations 1e-6,
        // keyed by the rank-invariant index.
        const unsigned int       nc     = model.field_layout().n_components();
        const auto              &layout = model.field_layout();
        perideal::ParticleVector u, f, g;
        ps.reinit_vector(u, nc);
        ps.reinit_vector(f, nc);
        for (unsigned int i = 0; i < ps.n_local(); ++i)
          for (unsigned int c = 0; c < nc; ++c)
            u.local_element(i * nc + c) =
              (layout.kind(c) == perideal::ComponentKind::rotation ? 1e-6 : 1e-9) *
              pd_tests::random_number(nc * ps.invariant_index(i) + c);
        std::vector<double> w;
        model.compute_forces(ps, u, f, &w, std::numeric_limits<double>::infinity());
        perideal::LinearizedModel linearized;
        model.linearize(ps, linearized);
        const double energy_linear = pd_tests::linearized_forces(ps, linearized, u, g);
        double       difference = 0., scale = 0., energy = 0.;
        for (unsigned int i = 0; i < ps.n_owned(); ++i)
          {
            for (unsigned int c = 0; c < nc; ++c)
              {
                difference =
                  std::max(difference,
                           std::abs(f.local_element(i * nc + c) - g.local_element(i * nc + c)));
                scale = std::max(scale, std::abs(f.local_element(i * nc + c)));
              }
            energy += w[i] * ps.volumes()[i];
          }
        difference = Utilities::MPI::max(difference, comm) / Utilities::MPI::max(scale, comm);
        energy     = Utilities::MPI::sum(energy, comm);
        const double energy_error = std::abs(energy / energy_linear - 1.);
        deallog << label << " (" << dim << "D), epsilon = " << epsilon << ": "
                << ps.n_global_bonds() << " bonds; max |f - f_lin| / max |f| < " << tolerance << " "
                << pd_tests::ok(difference < tolerance) << ", |W / W_lin - 1| < " << tolerance
                << " " << pd_tests::ok(energy_error < tolerance);
        // The nonlinear kernels' differences (the order of the strain) are printed; round-off
        // is not.
        if (tolerance > 1e-6)
          deallog << " (" << std::setprecision(2) << difference << ", " << energy_error << ")"
                  << std::setprecision(6);
        deallog << std::endl;
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();
  using perideal::PlanarAssumption;
  const Entries &nacl         = pd_tests::nacl_entries;
  const Entries &nacl_about_z = pd_tests::nacl_about_z_entries;
  const Entries &timoshenko   = pd_tests::timoshenko_entries;

  compare<perideal::BondBased<2>, 2>("bond based",
                                     {{"Young's modulus", "2e11"}},
                                     PlanarAssumption::plane_stress,
                                     1e-4);
  compare<perideal::BondBased<3>, 3>("bond based",
                                     {{"Young's modulus", "2e11"}},
                                     PlanarAssumption::three_dimensional,
                                     1e-4);
  compare<perideal::LinearPeridynamicSolid<2>, 2>("linear peridynamic solid",
                                                  {{"Young's modulus", "70e9"},
                                                   {"Poisson's ratio", "0.3"}},
                                                  PlanarAssumption::plane_strain,
                                                  1e-4);
  compare<perideal::LinearPeridynamicSolid<3>, 3>("linear peridynamic solid",
                                                  {{"Young's modulus", "70e9"},
                                                   {"Poisson's ratio", "0.3"}},
                                                  PlanarAssumption::three_dimensional,
                                                  1e-4);
  compare<perideal::AnisotropicBondBased<2>, 2>("anisotropic bond based",
                                                nacl,
                                                PlanarAssumption::plane_strain,
                                                1e-10);
  compare<perideal::AnisotropicBondBased<3>, 3>("anisotropic bond based",
                                                nacl,
                                                PlanarAssumption::three_dimensional,
                                                1e-10);
  compare<perideal::AnisotropicPlaneStress, 2>("anisotropic plane stress",
                                               nacl_about_z,
                                               PlanarAssumption::plane_stress,
                                               1e-10);
  compare<perideal::AntiplaneBondBased<2>, 2>("antiplane bond based",
                                              {{"Shear modulus", "1e9"}},
                                              PlanarAssumption::plane_stress,
                                              1e-10);
  compare<perideal::AntiplaneStateBased<2>, 2>("antiplane state based",
                                               {{"Shear modulus", "1e9"}},
                                               PlanarAssumption::plane_stress,
                                               1e-10);
  compare<perideal::TimoshenkoBondBased<2>, 2>("timoshenko bond based",
                                               timoshenko,
                                               PlanarAssumption::plane_stress,
                                               1e-10);
  compare<perideal::TimoshenkoBondBased<3>, 3>("timoshenko bond based",
                                               timoshenko,
                                               PlanarAssumption::three_dimensional,
                                               1e-10);
}
