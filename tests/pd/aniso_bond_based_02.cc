// Anisotropic linearized bond-based PD (seed 004): Cauchy's relations refused or symmetrized,
// bad input, the sign of the micromodulus and the Fourier symbol for cubic C11/C12 around
// [2.2, 5] (seed note 004, sec. 3.3), the critical stretch of an isotropic C against PMB's and
// the bonds a uniaxial strain breaks with the direction-dependent critical stretch.
#include <deal.II/base/parameter_handler.h>

#include <perideal/pd/anisotropic_bond_based.h>

#include "../tests.h"
#include "pd_tests.h"

#include <iomanip>
#include <limits>

using namespace dealii;
namespace am = perideal::anisotropic_micromodulus;

using Entries = std::vector<std::pair<std::string, std::string>>;

// A 9^3 lattice, delta = 3 dx, spacing 1 mm.
struct Lattice
{
  Lattice()
    : ps(MPI_COMM_WORLD)
  {
    perideal::ParticleSystem<3>::Settings s;
    s.spacing        = 1e-3;
    s.horizon        = 3e-3;
    s.partial_volume = perideal::PartialVolume::geometric;
    pd_tests::generate_box<3>(ps, s, Point<3>(), Point<3>(9e-3, 9e-3, 9e-3));
  }

  void
  initialize(perideal::AnisotropicBondBased<3> &model)
  {
    model.initialize(
      ps,
      pd_tests::model_context(3e-3, 1., perideal::PlanarAssumption::three_dimensional, false));
  }

  perideal::ParticleSystem<3> ps;
};

// Parse (and initialize, if @p initialize) a model from @p entries; print the message of the
// exception if one is thrown.
void
check_input(const std::string &label, const Entries &entries, const bool initialize)
{
  try
    {
      perideal::AnisotropicBondBased<3> model;
      pd_tests::parse_model(model, entries);
      if (initialize)
        {
          Lattice lattice;
          lattice.initialize(model);
        }
      deallog << label << ": accepted (wrong)" << std::endl;
    }
  catch (const ExceptionBase &exc)
    {
      deallog << label << ": " << perideal_tests::exception_text(exc) << std::endl;
    }
}

// The lines of the model's summary that contain @p word.
void
print_summary_lines(const perideal::AnisotropicBondBased<3> &model, const std::string &word)
{
  std::istringstream lines(model.summary());
  for (std::string line; std::getline(lines, line);)
    if (line.find(word) != std::string::npos)
      deallog << line << std::endl;
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();
  const Entries nu03 = {{"Symmetry", "isotropic"},
                        {"Young's modulus", "26e9"},
                        {"Poisson's ratio", "0.3"}};

  // Refused: isotropic nu = 0.3 has C66 = mu = 10 GPa, C12 = lambda = 15 GPa.
  check_input("isotropic nu = 0.3", nu03, false);

  // Symmetrized: lambda_sym = mu_sym = (lambda + 2 mu)/3 = 35/3 GPa.
  {
    perideal::AnisotropicBondBased<3> model;
    Entries                           e = nu03;
    e.emplace_back("Cauchy relations", "symmetrize");
    pd_tests::parse_model(model, e);
    Lattice lattice;
    lattice.initialize(model);
    const auto   C        = model.elasticity_tensor();
    const double expected = 35e9 / 3.;
    const double error    = std::max({std::abs(C[0][0][1][1] - expected),
                                      std::abs(C[0][1][0][1] - expected),
                                      std::abs(C[0][0][0][0] - 3. * expected)}) /
                         expected;
    deallog << "isotropic nu = 0.3 symmetrized: C12 = C66 = (lambda + 2 mu)/3, C11 = 3 C12: "
            << pd_tests::ok(error < 1e-14) << std::endl;
    print_summary_lines(model, "Cauchy");
  }

  // Bad input: the FE side's checks, reached through the PD model's entries.
  check_input("cubic with two constants",
              {{"Symmetry", "cubic"}, {"Cubic constants", "49.1e9, 12.8e9"}},
              false);
  check_input("cubic C11 < C12 (not positive definite)",
              {{"Symmetry", "cubic"}, {"Cubic constants", "10e9, 12.8e9, 12.8e9"}},
              false);

  // The sign of c(n) (continuum calibration: exactly the note's bounds 2.2 <= C11/C12 <= 5) and
  // of the Fourier symbol of the lattice operator, for both calibrations.
  for (const double ratio : {1.01, 1.1, 1.5, 2.0, 2.15, 2.25, 3.0, 4.9, 5.1, 6.0, 8.0})
    for (const std::string calibration : {"continuum", "discrete"})
      {
        const Entries e = {{"Symmetry", "cubic"},
                           {"Cubic constants", std::to_string(ratio * 10e9) + ", 10e9, 10e9"},
                           {"Calibration", calibration}};
        try
          {
            perideal::AnisotropicBondBased<3> model;
            pd_tests::parse_model(model, e);
            Lattice lattice;
            lattice.initialize(model);
            const auto &directions = model.direction_scan();
            deallog << "cubic C11/C12 = " << ratio << ", " << calibration << ": lambda < 0 in "
                    << std::setprecision(3) << 100. * directions.negative_fraction
                    << " % of the directions"
                    << (directions.negative_fraction > 0. ? " (warned)" : "")
                    << ", symbol positive definite (smallest/largest eigenvalue "
                    << model.symbol_scan().relative_minimum << ")" << std::setprecision(6)
                    << std::endl;
          }
        catch (const ExceptionBase &exc)
          {
            deallog << "cubic C11/C12 = " << ratio << ", " << calibration << ": "
                    << perideal_tests::exception_text(exc) << std::endl;
          }
      }

  // Critical stretch: an isotropic C with Cauchy's relations (continuum calibration) gives
  // PMB's s0 = sqrt(5 G0 / (6 E delta)) for every bond.
  {
    perideal::AnisotropicBondBased<3> model;
    pd_tests::parse_model(model,
                          {{"Symmetry", "isotropic"},
                           {"Young's modulus", "25e9"},
                           {"Poisson's ratio", "0.25"},
                           {"Calibration", "continuum"}});
    Lattice lattice;
    lattice.initialize(model);
    const double s0  = model.critical_stretch(100.);
    const double pmb = std::sqrt(5. * 100. / (6. * 25e9 * 3e-3));
    deallog << "isotropic critical stretch (G0 = 100 J/m^2) / PMB's: " << s0 / pmb << " "
            << pd_tests::ok(std::abs(s0 / pmb - 1.) < 1e-12) << std::endl;
  }

  // Fracture: cubic C11/C12 = 4 (continuum calibration), G0 = 100 J/m^2. A uniaxial strain
  // eps e_x e_x stretches a bond of direction n by eps n_x^2; it breaks iff that exceeds
  // s0(n) = s_ref sqrt(c_mean / |c(n)|). eps = 0.99 and 1.01 times s0(e_x).
  for (const double factor : {0.99, 1.01})
    {
      perideal::AnisotropicBondBased<3> model;
      pd_tests::parse_model(model,
                            {{"Symmetry", "cubic"},
                             {"Cubic constants", "40e9, 10e9, 10e9"},
                             {"Calibration", "continuum"}});
      Lattice lattice;
      lattice.initialize(model);
      const auto  &Lambda = model.micromodulus_tensor();
      const double c_mean = am::mean_directional_modulus(Lambda);
      const double s_ref  = model.critical_stretch(100.);
      const double eps =
        factor * s_ref * std::sqrt(c_mean / am::directional_modulus(Lambda, Point<3>(1, 0, 0)));
      perideal::ParticleSystem<3> &ps = lattice.ps;
      perideal::ParticleVector     u, f;
      ps.reinit_vector(u, 3);
      ps.reinit_vector(f, 3);
      for (unsigned int i = 0; i < ps.n_local(); ++i)
        u.local_element(3 * i) = eps * ps.positions()[i][0];
      model.compute_forces(ps, u, f, nullptr, s_ref);
      const perideal::BondList &bonds   = ps.bonds();
      double                    along_x = 0., broken_along_x = 0., broken = 0., mismatched = 0.;
      for (unsigned int i = 0; i < ps.n_owned(); ++i)
        for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
          {
            const Tensor<1, 3> n =
              (ps.positions()[bonds.neighbor[b]] - ps.positions()[i]) / bonds.length[b];
            const bool predicted =
              eps * n[0] * n[0] * std::sqrt(std::abs(am::directional_modulus(Lambda, n)) / c_mean) >
              s_ref;
            const bool   is_broken = bonds.intact[b] == 0;
            const double share     = ps.bond_share(b);
            broken += is_broken ? share : 0.;
            mismatched += is_broken != predicted ? share : 0.;
            if (std::abs(n[0]) > 1. - 1e-12)
              {
                along_x += share;
                broken_along_x += is_broken ? share : 0.;
              }
          }
      const MPI_Comm comm = MPI_COMM_WORLD;
      deallog << "uniaxial strain " << factor << " s0(e_x): broken bonds along x "
              << Utilities::MPI::sum(broken_along_x, comm) << " of "
              << Utilities::MPI::sum(along_x, comm) << ", broken in all "
              << Utilities::MPI::sum(broken, comm) << ", against the rule "
              << pd_tests::ok(Utilities::MPI::sum(mismatched, comm) == 0.) << std::endl;
    }
}
