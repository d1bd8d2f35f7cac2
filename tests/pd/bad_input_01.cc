// Bad input stops before any work with a message naming the entry and the accepted values, and
// leaves no output behind.
#include <deal.II/base/parameter_handler.h>

#include "../tests.h"
#include "pd_tests.h"

#include <filesystem>
#include <sstream>

using namespace dealii;

const std::string base = R"(
set Dimension = 2
subsection Discretization
  set Lattice spacing = 1e-3
  set Horizon factor = 3
  set Thickness = 1e-3
  set Body = plate
end
subsection Regions
  set Names = plate, top
  subsection plate
    set Lower corner = 0, 0
    set Upper corner = 0.02, 0.01
  end
  subsection top
    set Lower corner = 0, 0.009
    set Upper corner = 0.02, 0.01
  end
end
subsection Material
  set Density = 7800
  subsection bond based
    set Young's modulus = 200e9
  end
end
subsection Boundary conditions
  set Names = pull
  subsection pull
    set Region = top
    set Type = velocity
    set Components = y
    set Function = 1
  end
end
subsection Time stepping
  set End time = 1e-6
end
subsection Output
  set Directory = output-bad-input
  set Progress = false
end
)";

// Check base with the changes applied.
void
check(const std::string &name, const std::string &changes)
{
  pd_tests::check_bad_input(name,
                            base + changes,
                            {"plate", "top"},
                            {"pull", "hold", "cool"},
                            false);
  deallog << "  output written: " << std::filesystem::exists("output-bad-input") << std::endl;
}

// The plate as a conduction problem: conductivity and specific heat, the top held at 300 K.
const std::string conduction =
  "subsection Material\n set Model = bond based conduction\n subsection bond based "
  "conduction\n set Conductivity = 45\n set Specific heat = 460\n end\nend\n"
  "subsection Boundary conditions\n subsection pull\n set Type = value\n set Components =\n "
  "set Function = 300\n end\nend\n";

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();
  check("negative modulus",
        "subsection Material\n subsection bond based\n set Young's modulus = -1\n end\nend\n");
  check("zero density", "subsection Material\n set Density = 0\nend\n");
  check("horizon below spacing", "subsection Discretization\n set Horizon factor = 0.8\nend\n");
  check("region without particles",
        "subsection Regions\n subsection top\n set Lower corner = 1, 1\n set Upper corner = 2, "
        "2\n end\nend\n");
  check("undefined region",
        "subsection Boundary conditions\n subsection pull\n set Region = topp\n end\nend\n");
  check("missing mesh file",
        "subsection Regions\n subsection top\n set Shape = mesh\n set Mesh file = none.msh\n "
        "end\nend\n");
  check("time step above the limit", "subsection Time stepping\n set Time step = 1e-6\nend\n");
  check("bad function",
        "subsection Boundary conditions\n subsection pull\n set Function = 1; 2\n end\nend\n");
  check("conflicting conditions",
        "subsection Boundary conditions\n set Names = pull, hold\n subsection hold\n set Region = "
        "top\n set Type = displacement\n set Components = x, y\n set Function = 0; 0\n "
        "end\nend\n");
  check("damage without energy",
        "subsection Material\n set Damage model = critical stretch\nend\n");
  check("probe point with one coordinate", "subsection Output\n set Probe points = 0.01\nend\n");
  check("probe point off the particles",
        "subsection Output\n set Probe points = 0.01, 0.005; 0.01, 0.0125\nend\n");
  check("blending function without a mesh",
        "subsection Coupling\n set Blending function = 0.5\nend\n");
  check("no particles and no mesh", "subsection Discretization\n set Body =\nend\n");
  check("FE boundary condition without a mesh",
        "subsection Finite elements\n subsection Boundary conditions\n set Names = clamp\n "
        "end\nend\n");
  check("stiffness fit for a model without it",
        "subsection Discretization\n set Surface correction method = stiffness fit\nend\n"
        "subsection Material\n set Model = linear peridynamic solid\n subsection linear "
        "peridynamic solid\n set Young's modulus = 200e9\n end\nend\n");
  check("conductivity not positive",
        conduction + "subsection Material\n subsection bond based conduction\n set "
                     "Conductivity = 0\n end\nend\n");
  check("specific heat not positive",
        conduction + "subsection Material\n subsection bond based conduction\n set Specific "
                     "heat = -1\n end\nend\n");
  check("convection without ambient temperature",
        conduction + "subsection Boundary conditions\n set Names = pull, cool\n subsection "
                     "cool\n set Region = plate\n set Type = convection\n set Layer thickness "
                     "= 1e-3\n set Heat transfer coefficient = 10\n end\nend\n");
  check("density by region not positive",
        conduction + "subsection Material\n subsection bond based conduction\n set Densities "
                     "by region = top: 0\n end\nend\n");
  check("specific heat by region not positive",
        conduction + "subsection Material\n subsection bond based conduction\n set Specific "
                     "heats by region = top: -460\n end\nend\n");
  check("particle convection under adaptive dynamic relaxation",
        conduction + "subsection Boundary conditions\n set Names = pull, cool\n subsection "
                     "cool\n set Region = plate\n set Type = convection\n set Layer thickness "
                     "= 1e-3\n set Heat transfer coefficient = 10\n set Ambient temperature = "
                     "290\n end\nend\nsubsection Solver\n set Type = adaptive dynamic "
                     "relaxation\nend\n");
  check("thermal time step above the stable one",
        conduction + "subsection Time stepping\n set Time step = 1\n set End time = 10\nend\n");
  check("temperature condition on a displacement",
        "subsection Boundary conditions\n subsection pull\n set Type = convection\n end\nend\n");
  check("mechanical condition on a temperature",
        conduction + "subsection Boundary conditions\n subsection pull\n set Type = "
                     "traction\n set Layer thickness = 1e-3\n end\nend\n");
  check("lattice fracture calibration for a model without it",
        conduction + "subsection Material\n set Damage model = critical stretch\n subsection "
                     "critical stretch\n set Fracture energy = 100\n set Fracture energy "
                     "calibration = lattice\n end\nend\n");
  check("lattice fracture calibration with a given critical stretch",
        "subsection Material\n set Damage model = critical stretch\n subsection critical "
        "stretch\n set Critical stretch = 0.01\n set Fracture energy calibration = lattice\n "
        "end\nend\n");
}
