// Quasi-static bad input stops with a message: adaptive dynamic relaxation that does not converge
// within <Solver/Maximum iterations> lists its residual history, with step cutting after the
// allowed cuts; a static or relaxation run
// without any displacement condition (rigid-body modes free, singular system) and one with a
// velocity condition are refused. The entries of <Solver/Control> (the fracture control) are
// checked before any solve: sequentially linear without a load point, with a load point that
// names no displacement condition or a load component the field does not have, with adaptive
// dynamic relaxation, or without bonds that break; a separation load fraction, a step-cut
// threshold or a number of step cuts outside its range. Linear softening of the bonds
// (<Material/critical stretch/Failure law>) with load steps (its saw teeth need the sequentially
// linear control), for a model without it, and with a softening ratio of 1.
#include <deal.II/base/parameter_handler.h>

#include <perideal/coupling/coupled_problem.h>

#include "../tests.h"
#include "pd_tests.h"

#include <sstream>

using namespace dealii;

const std::string base = R"(
set Dimension = 2
subsection Discretization
  set Lattice spacing = 1e-3
  set Horizon factor = 3.015
  set Thickness = 1e-3
  set Body = plate
end
subsection Regions
  set Names = plate, top, bottom
  subsection plate
    set Lower corner = 0, 0
    set Upper corner = 0.02, 0.01
  end
  subsection top
    set Lower corner = 0, 0.006
    set Upper corner = 0.02, 0.01
  end
  subsection bottom
    set Lower corner = 0, 0
    set Upper corner = 0.02, 0.004
  end
end
subsection Material
  set Density = 7800
  subsection bond based
    set Young's modulus = 200e9
  end
end
subsection Boundary conditions
  set Names = pull, hold
  subsection pull
    set Region = top
    set Type = displacement
    set Components = y
    set Function = 1e-6
  end
  subsection hold
    set Region = bottom
    set Type = displacement
    set Components = x, y
    set Function = 0; 0
  end
end
subsection Solver
  set Type = adaptive dynamic relaxation
  set Maximum iterations = 20
end
subsection Output
  set Directory = output-quasi-static-bad-input
  set Write HDF5 = false
  set Progress = false
end
)";

// Check base with the changes applied.
void
check(const std::string &name, const std::string &changes)
{
  pd_tests::check_bad_input(name,
                            base + changes,
                            {"plate", "top", "bottom"},
                            {"pull", "hold"},
                            true);
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();
  check("relaxation without convergence", "");
  check("relaxation without convergence after the allowed step cuts",
        "subsection Solver\n subsection Control\n set Cut above broken bonds = 1\n"
        " set Maximum step cuts = 2\n end\nend\n");
  const std::string traction_only =
    "subsection Boundary conditions\n subsection pull\n set Type = traction\n set Components = "
    "x, y\n set Function = 0; 1e6\n set Layer thickness = 4e-3\n end\n subsection hold\n set "
    "Type = traction\n set Components = x, y\n set Function = 0; -1e6\n set Layer thickness = "
    "4e-3\n end\nend\n";
  check("static without displacement condition",
        traction_only + "subsection Solver\n set Type = static\nend\n");
  check("relaxation without displacement condition", traction_only);
  check("static with a free translation",
        "subsection Boundary conditions\n subsection hold\n set Components = y\n set Function "
        "= 0\n end\nend\nsubsection Solver\n set Type = static\nend\n");
  const std::string sequentially_linear =
    "subsection Material\n set Damage model = critical stretch\n subsection critical stretch\n"
    " set Critical stretch = 1e-3\n end\nend\nsubsection Solver\n set Type = static\n"
    " subsection Control\n set Method = sequentially linear\n";
  check("sequentially linear without a load point", sequentially_linear + " end\nend\n");
  check("load point that names no condition",
        sequentially_linear + " set Load point = nowhere\n end\nend\n");
  check("load component the field does not have",
        sequentially_linear + " set Load point = pull\n set Load component = z\n end\nend\n");
  check("sequentially linear with relaxation",
        sequentially_linear +
          " set Load point = pull\n end\n set Type = adaptive dynamic relaxation\nend\n");
  check("sequentially linear without bonds that break",
        sequentially_linear + " set Load point = pull\n end\nend\n"
                              "subsection Material\n set Damage model = none\nend\n");
  check("separation load fraction above 1",
        sequentially_linear + " set Load point = pull\n set Separation load fraction = 1.5\n"
                              " end\nend\n");
  check("negative step-cut threshold",
        "subsection Solver\n subsection Control\n set Cut above broken bonds = -1\n end\nend\n");
  check("too many step cuts",
        "subsection Solver\n subsection Control\n set Maximum step cuts = 60\n end\nend\n");
  check("velocity condition in a quasi-static run",
        "subsection Boundary conditions\n subsection pull\n set Type = velocity\n end\nend\n"
        "subsection Solver\n set Type = static\nend\n");
  const std::string softening =
    "subsection Material\n set Damage model = critical stretch\n subsection critical stretch\n"
    " set Fracture energy = 1000\n set Failure law = linear softening\n";
  check("linear softening with load steps",
        softening + " end\nend\nsubsection Solver\n set Type = static\n set Linear solver = "
                    "direct\nend\n");
  check("linear softening of a model without it",
        softening + " end\n set Model = linear peridynamic solid\n subsection linear "
                    "peridynamic solid\n set Young's modulus = 200e9\n set Poisson's ratio = "
                    "0.3\n end\nend\n");
  check("softening ratio 1", softening + " set Softening ratio = 1\n end\nend\n");
}
