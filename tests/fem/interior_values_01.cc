// ---------------------------------------------------------------------
// FERegion::set_interior_values(): dofs inside the body prescribed like those of a 'value'
// condition (Dirichlet data inside the body, as overlapping Schwarz needs). A bar 0 <= x <= 1,
// height 0.1, 10 x 1 cells, FE physics 'scalar laplace' with k = 2, no source, w = 0 at both
// ends (boundary ids 0 and 1) and the two nodes at x = 0.3 held at w = 1: the exact solution
// is w = x / 0.3 left of them and (1 - x) / 0.7 right of them, piecewise linear, so Q1 holds it.
// The region's prescribe(), prescribed_mask() and stiffness are solved here with a direct
// solver (prescribed rows replaced by the identity). Printed: the number of prescribed dofs,
// the largest nodal error (round-off), and the reactions per unit thickness: k H / 0.3 =
// 0.6667 and k H / 0.7 = 0.2857 pulling the ends in (negative), their sum at the interior dofs
// (interior_reactions()), which balance.
// ---------------------------------------------------------------------
#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/trilinos_solver.h>

#include <perideal/fem/fe_region.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include <tests.h>

using namespace dealii;
using FEVector = LinearAlgebra::distributed::Vector<double>;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();
  const MPI_Comm   comm = MPI_COMM_WORLD;
  ParameterHandler prm;
  perideal::FERegion<2>::declare_parameters(prm, {"left", "right"});
  prm.parse_input_from_string("subsection Finite elements\n"
                              "  set Physics = scalar laplace\n"
                              "  set Generator = subdivided_hyper_rectangle\n"
                              "  set Generator arguments = 10, 1 : 0, 0 : 1, 0.1 : true\n"
                              "  subsection scalar laplace\n"
                              "    set Coefficient = 2\n"
                              "  end\n"
                              "  subsection Boundary conditions\n"
                              "    set Names = left, right\n"
                              "    subsection left\n"
                              "      set Boundary ids = 0\n"
                              "      set Type = value\n"
                              "    end\n"
                              "    subsection right\n"
                              "      set Boundary ids = 1\n"
                              "      set Type = value\n"
                              "    end\n"
                              "  end\n"
                              "end\n");
  perideal::FERegion<2> fe(comm);
  fe.parse_parameters(prm, perideal::PlanarAssumption::plane_stress, 1.);
  fe.setup();

  // The dofs at x = 0.3, the same list on every rank.
  std::vector<types::global_dof_index> local, dofs;
  for (const auto &cell : fe.get_dof_handler().active_cell_iterators())
    if (cell->is_locally_owned())
      for (const unsigned int v : cell->vertex_indices())
        if (std::abs(cell->vertex(v)[0] - 0.3) < 1e-12)
          local.push_back(cell->vertex_dof_index(v, 0));
  for (const auto &part : Utilities::MPI::all_gather(comm, local))
    dofs.insert(dofs.end(), part.begin(), part.end());
  std::sort(dofs.begin(), dofs.end());
  dofs.erase(std::unique(dofs.begin(), dofs.end()), dofs.end());
  fe.set_interior_values(dofs, std::vector<double>(dofs.size(), 1.));

  // K z = f - K g on the free dofs, z = 0 on the prescribed ones; w = g + z.
  FEVector g, v, f, Kg, z, rhs;
  for (FEVector *x : {&g, &v, &f, &Kg, &z, &rhs})
    fe.initialize_vector(*x);
  fe.prescribe(0., g, v);
  fe.assemble_load(0., f);
  fe.stiffness_matrix().vmult(Kg, g);
  rhs = f;
  rhs -= Kg;
  const auto                          &mask  = fe.prescribed_mask();
  const auto                           owned = fe.get_dof_handler().locally_owned_dofs();
  std::vector<types::global_dof_index> rows;
  for (unsigned int k = 0; k < mask.size(); ++k)
    if (mask[k])
      {
        rows.push_back(owned.nth_index_in_set(k));
        rhs.local_element(k) = 0.;
      }
  const unsigned int     n_prescribed = Utilities::MPI::sum<unsigned int>(rows.size(), comm);
  perideal::SparseMatrix A;
  A.copy_from(fe.stiffness_matrix());
  A.clear_rows(rows, 1.);
  SolverControl                  control(1, 0., false, false);
  TrilinosWrappers::SolverDirect direct(control);
  direct.solve(A, z, rhs);
  FEVector w = g;
  w += z;
  w.update_ghost_values();

  double error = 0.;
  for (const auto &cell : fe.get_dof_handler().active_cell_iterators())
    if (cell->is_locally_owned())
      for (const unsigned int vertex : cell->vertex_indices())
        {
          const double x     = cell->vertex(vertex)[0];
          const double exact = x <= 0.3 ? x / 0.3 : (1. - x) / 0.7;
          error = std::max(error, std::abs(w(cell->vertex_dof_index(vertex, 0)) - exact));
        }
  error = Utilities::MPI::max(error, comm);

  FEVector residual;
  fe.initialize_vector(residual);
  fe.stiffness_matrix().vmult(residual, w);
  residual -= f;
  const auto   ends     = fe.reactions(residual);
  const auto   interior = fe.interior_reactions(residual);
  const double sum      = std::accumulate(interior.begin(), interior.end(), 0.);
  deallog << "prescribed dofs: " << n_prescribed << " (2 at each end, " << dofs.size() << " inside)"
          << std::endl;
  deallog << "largest nodal error: " << (error < 1e-12 ? "below 1e-12" : std::to_string(error))
          << std::endl;
  deallog << "reactions: left " << ends[0][0] << " (exact " << -2. * 0.1 / 0.3 << "), right "
          << ends[1][0] << " (exact " << -2. * 0.1 / 0.7 << "), interior " << sum << " (exact "
          << 2. * 0.1 * (1. / 0.3 + 1. / 0.7) << ")" << std::endl;
  const double imbalance = std::abs(ends[0][0] + ends[1][0] + sum);
  deallog << "balance |sum of reactions|: " << (imbalance < 1e-12 ? "below 1e-12" : "ABOVE")
          << std::endl;
}
