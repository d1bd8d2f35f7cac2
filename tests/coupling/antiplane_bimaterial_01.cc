// ---------------------------------------------------------------------
// Dissimilar antiplane materials (<Shear moduli by region>) and the short variant of the
// benchmark antiplane_bimaterial (doc/benchmarks/antiplane_bimaterial: seed 000, example 8.2).
//  1. The interface rule (seed eq. 60, RegionModuli::bond_modulus()): mu1 = 12e6 below y = 0,
//     mu2 = 6e6 above; a bond half in each material has 2 mu1 mu2/(mu1 + mu2) = 8e6 (seed note
//     000, sec. 6 test 11), a quarter in mu1 1/(0.25/mu1 + 0.75/mu2), a bond inside one material
//     that material's modulus; accepted to 1e-9 (regions hold points up to 1e-10 of their size
//     beyond their faces, which moves the interface by that much).
//  2. The benchmark's files at dx = 0.02 (10 x 50 particles, six fictitious layers held at 0
//     below the bar) and the FE file on its coarse mesh: the largest error against the exact
//     piecewise-linear solution, relative to w(top) = 1.5e-3, and the top row against the exact
//     value there. Tolerances from the benchmark's convergence table (README.md; the error
//     falls like dx, from the held clamp layers and the surface correction of the free sides):
//     bond-based 2.78 % at dx = 0.02, accepted 3.5 %; state-based with stabilization 0.1
//     3.15 %, accepted 4 %; the paper's state-based model (stabilization 0) is wrong by about
//     100 % at every dx (its zero-energy modes, seed note 000 E1): accepted only above 50 %,
//     without its numbers (the singular solve's oscillation is not reproducible across ranks);
//     FE exact (the solution is in the Q1 space), accepted 1e-8.
//  3. Bad input, before any heavy work: a non-positive modulus and a malformed item (when the
//     file is read), a region that does not exist, region moduli with a twist.
// ---------------------------------------------------------------------
#include <perideal/coupling/coupled_problem.h>
#include <perideal/pd/region_moduli.h>

#include "coupling_tests.h"

#include <cstdio>
#include <iostream>

#include <antiplane_benchmarks.h>
#include <tests.h>

using namespace dealii;
namespace ab = antiplane_benchmarks;

namespace
{
  const std::string benchmark = SOURCE_DIR "/../../doc/benchmarks/antiplane_bimaterial/";

  // The benchmark's PD file at dx = 0.02 (six layers below the bar, the top row) with the model
  // MODEL and stabilization ALPHA, without the exact-displacement summary.
  const std::string pd_short = "include " + benchmark + "bimaterial_pd.prm" + R"(
subsection Regions
  subsection clamp
    set Lower corner = -0.1, -0.62
  end
  subsection top
    set Lower corner = -0.1, 0.48
  end
end
subsection Coupling
  set Exact displacement =
end
)" + ab::short_variant;

  void
  interface_rule()
  {
    ParameterHandler prm;
    perideal::RegionCollection<2>::declare_parameters(prm, {"upper"});
    prm.enter_subsection("Material");
    perideal::RegionModuli<2>::declare_parameters(prm, "Shear moduli by region", "Pa");
    prm.leave_subsection();
    prm.parse_input_from_string("subsection Regions\n set Names = upper\n subsection upper\n"
                                "  set Shape = box\n  set Lower corner = -1, 0\n"
                                "  set Upper corner = 1, 1\n end\nend\n"
                                "subsection Material\n set Shear moduli by region = upper: 6e6\n"
                                "end\n");
    perideal::RegionCollection<2> regions;
    regions.parse_parameters(prm);
    perideal::RegionModuli<2> moduli;
    prm.enter_subsection("Material");
    moduli.parse_parameters(prm, "Shear moduli by region", "Material");
    prm.leave_subsection();
    moduli.resolve(regions);
    const double mu1 = ab::mu, mu2 = ab::mu2;
    const struct
    {
      const char *name;
      Point<2>    a, b;
      double      expected;
    } cases[] = {
      {"half in each", {0., -0.5}, {0.3, 0.5}, 2. * mu1 * mu2 / (mu1 + mu2)},
      {"a quarter in mu1", {0., -0.25}, {0., 0.75}, 1. / (0.25 / mu1 + 0.75 / mu2)},
      {"a quarter in mu1, reversed", {0., 0.75}, {0., -0.25}, 1. / (0.25 / mu1 + 0.75 / mu2)},
      {"inside mu1", {0., -0.5}, {0.2, -0.1}, mu1},
      {"inside mu2", {0., 0.1}, {-0.2, 0.5}, mu2}};
    for (const auto &c : cases)
      {
        const double value = moduli.bond_modulus(c.a, c.b, mu1);
        char         line[200];
        std::snprintf(line,
                      sizeof(line),
                      "interface rule, %s: mu_ij = %.6e (expected %.6e: %s)",
                      c.name,
                      value,
                      c.expected,
                      coupling_tests::ok(std::abs(value / c.expected - 1.) < 1e-9));
        deallog << line << std::endl;
      }
  }

  // The short PD variant of @p model with stabilization @p alpha: accepted within @p tolerance,
  // or, for a @p known_failure, above 50 %.
  void
  pd_run(const std::string &model,
         const std::string &alpha,
         const double       tolerance,
         const bool         known_failure = false)
  {
    const auto measured =
      ab::measure("bimaterial.prm",
                  coupling_tests::substitute(pd_short, {{"MODEL", model}, {"ALPHA", alpha}}),
                  ab::bimaterial,
                  [](const Point<2> &p) { return p[1] > -0.5; });
    const double      w_top     = ab::bimaterial(Point<2>(0., 0.5));
    const double      exact_top = ab::bimaterial(Point<2>(0., 0.49));
    const double      error = measured.largest_error, top = measured.top;
    const std::string name = model + " (stabilization " + alpha + "), dx = 0.02";
    if (known_failure)
      {
        deallog << ab::known_failure(name, "", "w(top)", error / w_top, 0.5) << std::endl;
        return;
      }
    char line[300];
    std::snprintf(line,
                  sizeof(line),
                  "%s: largest error %.2f %% of w(top) (within %.1f %%: %s); top row w = "
                  "%.4e, exact %.4e (%+.1f %%)",
                  name.c_str(),
                  100. * error / w_top,
                  100. * tolerance,
                  coupling_tests::ok(error / w_top < tolerance),
                  top,
                  exact_top,
                  100. * (top / exact_top - 1.));
    deallog << line << std::endl;
  }

  void
  fe_run()
  {
    const std::string log =
      coupling_tests::run("bimaterial_fe.prm",
                          "include " + benchmark +
                            "bimaterial_fe.prm\n"
                            "subsection Finite elements\n"
                            "  set Mesh file          = " SOURCE_DIR
                            "/../../meshes/bimaterial_bar.msh\n"
                            "  set Global refinements = 0\n"
                            "end\n"
                            "subsection Output\n  set Directory  = results\n"
                            "  set Write HDF5 = false\n  set Progress   = false\nend\n");
    const auto error = coupling_tests::numbers_of(log, "Displacement error");
    deallog << "FE Q1 on the 2 x 10 mesh: largest nodal error relative to w(top) below 1e-8: "
            << coupling_tests::ok(error.at(0) < 1e-8) << std::endl;
  }

  void
  bad_input(const std::string &name, const std::string &model, const std::string &entries)
  {
    const std::string file = "bimaterial_bad.prm";
    coupling_tests::write_file(file,
                               coupling_tests::substitute(pd_short,
                                                          {{"MODEL", model}, {"ALPHA", "0"}}) +
                                 "subsection Material\n  subsection " + model + "\n" + entries +
                                 "  end\nend\n");
    try
      {
        std::ostringstream          log;
        perideal::CoupledProblem<2> problem(MPI_COMM_WORLD, log);
        coupling_tests::parse(problem, file);
        deallog << name << ": accepted" << std::endl;
      }
    catch (const ExceptionBase &exc)
      {
        deallog << name << ": " << perideal_tests::exception_text(exc) << std::endl;
      }
    MPI_Barrier(MPI_COMM_WORLD);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();
  deallog.depth_file(1);
  interface_rule();
  pd_run("antiplane bond based", "0", 0.035);
  pd_run("antiplane state based", "0.1", 0.04);
  pd_run("antiplane state based", "0", 0., true);
  fe_run();
  for (const std::string model : {"antiplane bond based", "antiplane state based"})
    {
      bad_input(model + ", modulus 0", model, "    set Shear moduli by region = upper: 0\n");
      bad_input(model + ", negative modulus",
                model,
                "    set Shear moduli by region = upper: -6e6\n");
    }
  bad_input("malformed item",
            "antiplane bond based",
            "    set Shear moduli by region = upper 6e6\n");
  bad_input("unknown region",
            "antiplane state based",
            "    set Shear moduli by region = lower: 6e6\n");
  bad_input("region moduli with a twist",
            "antiplane bond based",
            "    set Twist per unit length = 1\n");
}
