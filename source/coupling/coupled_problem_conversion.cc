// ---------------------------------------------------------------------
// PeriDeal: the conversion of FE cells into particles when the adaptive PD region grows.
// ---------------------------------------------------------------------
#include <deal.II/lac/vector.h>

#include <perideal/base/parameter_utilities.h>
#include <perideal/coupling/coupled_problem.h>
#include <perideal/coupling/transfer_operator.h>
#include <perideal/pd/damage_model.h>
#include <perideal/pd/lattice.h>

#include <map>
#include <set>
#include <sstream>
#include <unordered_map>
#include <utility>

namespace perideal
{
  using namespace dealii;

  template <int dim>
  bool
  CoupledProblem<dim>::convert_regions(const unsigned int step, const double time)
  {
    using Key = typename Lattice<dim>::Key;
    // Particles are matched by their lattice point across the regeneration.
    const Lattice<dim> lattice(pd.discretization().spacing);
    std::ostringstream when;
    when << "At step " << step << " (t = " << time << " s)";
    const auto seeds = adaptive.propose_seeds(
      state(),
      [this](const Point<dim> &x) { return blending(x); },
      [this](const Point<dim> &x) { return pd.in_body(x); },
      precrack_damage,
      when.str());
    if (seeds.empty())
      return false;
    adaptive.check_conditions_outside(fe, seeds, when.str());

    // What carries over, before anything changes: the unknowns of the free particles by lattice
    // point (the others are slaved to the FE field and take it again), their broken bonds (a
    // particle keeps its rank: ParticleSystem's bins do not depend on which lattice points exist),
    // and the FE dof values of each owned cell with unknowns (the mesh and its partition stay).
    const unsigned int nc     = layout.n_components();
    auto              &ps     = pd.particles();
    const auto        &x      = ps.positions();
    const auto        &slaved = method().slaved_particles();
    std::unordered_map<Key, std::vector<double>, typename Lattice<dim>::KeyHash> free_values;
    for (unsigned int i = 0; i < ps.n_owned(); ++i)
      if (!slaved[i])
        {
          std::vector<double> &values = free_values[lattice.key(x[i])];
          for (unsigned int c = 0; c < nc; ++c)
            {
              values.push_back(state().u.local_element(i * nc + c));
              values.push_back(state().v.local_element(i * nc + c));
            }
        }
    std::set<std::pair<Key, Key>> broken;
    {
      const auto &bonds = ps.bonds();
      for (unsigned int i = 0; i < ps.n_owned(); ++i)
        for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
          if (bonds.intact[b] == 0)
            broken.emplace(lattice.key(x[i]), lattice.key(x[bonds.neighbor[b]]));
    }
    const unsigned int n_particles_before = ps.n_global();
    const auto         n_dofs_before      = fe.n_dofs();
    const FEVector     U_before = state().U, V_before = state().V;
    U_before.update_ghost_values();
    V_before.update_ghost_values();
    std::map<CellId, std::pair<Vector<double>, Vector<double>>> cell_values;
    for (const auto &cell : fe.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned() && cell->active_fe_index() == 0)
        {
          auto &[u_cell, v_cell] = cell_values[cell->id()];
          u_cell.reinit(cell->get_fe().n_dofs_per_cell());
          v_cell.reinit(cell->get_fe().n_dofs_per_cell());
          cell->get_dof_values(U_before, u_cell);
          cell->get_dof_values(V_before, v_cell);
        }

    // The particles of the grown region, their unknowns from the FE field as it was (every new
    // particle lies in a cell that had FE unknowns) or their own (free particles).
    adaptive.add_seeds(seeds);
    setup_particles(false);
    ParticleVector u_new, v_new;
    {
      // Only the particles without values of their own need the old FE field.
      const auto       &y = ps.positions();
      std::vector<bool> without_values(ps.n_owned());
      for (unsigned int i = 0; i < ps.n_owned(); ++i)
        without_values[i] = free_values.count(lattice.key(y[i])) == 0;
      TransferOperator<dim> before;
      before.reinit(fe, ps, layout, without_values);
      ps.reinit_vector(u_new, nc);
      ps.reinit_vector(v_new, nc);
      before.interpolate(U_before, u_new);
      before.interpolate(V_before, v_new);
      for (unsigned int i = 0; i < ps.n_owned(); ++i)
        if (!before.is_slaved(i))
          {
            const auto found = free_values.find(lattice.key(y[i]));
            AssertThrow(found != free_values.end(),
                        ExcInternalError("A particle of the grown PD region is neither in a "
                                         "cell with FE unknowns nor a particle before."));
            for (unsigned int c = 0; c < nc; ++c)
              {
                u_new.local_element(i * nc + c) = found->second[2 * c];
                v_new.local_element(i * nc + c) = found->second[2 * c + 1];
              }
          }
      precrack_damage = damage_index(ps);
      auto &bonds     = ps.bonds();
      for (unsigned int i = 0; i < ps.n_owned(); ++i)
        for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
          if (bonds.intact[b] != 0 &&
              broken.count({lattice.key(y[i]), lattice.key(y[bonds.neighbor[b]])}))
            bonds.break_bond(b);
    }

    // The FE space without the cells that became PD only, the coupling and the state.
    fe.reweight([this](const Point<dim> &p) { return method().fe_weight(blending(p)); });
    method().initialize(coupled_regions(*physics[0]));
    state().setup();
    for (unsigned int k = 0; k < std::size_t(ps.n_owned()) * nc; ++k)
      {
        state().u.local_element(k) = u_new.local_element(k);
        state().v.local_element(k) = v_new.local_element(k);
      }
    state().u.update_ghost_values();
    state().v.update_ghost_values();
    std::vector<types::global_dof_index> dofs;
    for (const auto &cell : fe.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned() && cell->active_fe_index() == 0)
        {
          const auto found = cell_values.find(cell->id());
          AssertThrow(found != cell_values.end(),
                      ExcInternalError("A cell gained FE unknowns in a conversion."));
          dofs.resize(cell->get_fe().n_dofs_per_cell());
          cell->get_dof_indices(dofs);
          for (unsigned int k = 0; k < dofs.size(); ++k)
            if (state().U.locally_owned_elements().is_element(dofs[k]))
              {
                state().U(dofs[k]) = found->second.first[k];
                state().V(dofs[k]) = found->second.second[k];
              }
        }
    state().U.update_ghost_values();
    state().V.update_ghost_values();
    postprocessors().initialize(state());

    if (is_root)
      log << when.str() << ": the PD region grew by " << seeds.size() << " disk"
          << (seeds.size() == 1 ? "" : "s") << " (" << adaptive.seed_points().size()
          << " in all): particles " << n_particles_before << " -> " << ps.n_global() << ", FE dofs "
          << n_dofs_before << " -> " << fe.n_dofs() << std::endl;
    return true;
  }

  template bool
  CoupledProblem<2>::convert_regions(const unsigned int, const double);
  template bool
  CoupledProblem<3>::convert_regions(const unsigned int, const double);
} // namespace perideal
