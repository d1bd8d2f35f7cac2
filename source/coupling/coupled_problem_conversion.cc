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

  namespace
  {
    /// What a conversion carries over of one physics' state (the same for every layout).
    template <int dim>
    struct CarriedState
    {
      /// The unknowns of the free particles by lattice point: (u, v) per component.
      std::unordered_map<typename Lattice<dim>::Key,
                         std::vector<double>,
                         typename Lattice<dim>::KeyHash>
        free_values;
      /// The FE unknowns before the conversion, and the dof values (U, V) of each owned cell
      /// with unknowns by CellId (the mesh and its partition do not change).
      ///@{
      FEVector                                                    U, V;
      std::map<CellId, std::pair<Vector<double>, Vector<double>>> cell_values;
      ///@}
      /// The unknowns of the particles of the grown region (carry_to_particles()).
      ParticleVector u, v;
    };

    /// What carries over of @p field's state, before anything changes.
    template <int dim>
    CarriedState<dim>
    keep(const Physics<dim> &field, const Lattice<dim> &lattice)
    {
      CarriedState<dim>  carried;
      const auto        &state  = field.state();
      const unsigned int nc     = state.n_components();
      const auto        &ps     = field.pd.particles();
      const auto        &x      = ps.positions();
      const auto        &slaved = field.method().slaved_particles();
      for (unsigned int i = 0; i < ps.n_owned(); ++i)
        if (!slaved[i])
          {
            std::vector<double> &values = carried.free_values[lattice.key(x[i])];
            for (unsigned int c = 0; c < nc; ++c)
              {
                values.push_back(state.u.local_element(i * nc + c));
                values.push_back(state.v.local_element(i * nc + c));
              }
          }
      carried.U = state.U;
      carried.V = state.V;
      carried.U.update_ghost_values();
      carried.V.update_ghost_values();
      for (const auto &cell : field.fe.get_dof_handler().active_cell_iterators())
        if (cell->is_locally_owned() && cell->active_fe_index() == 0)
          {
            auto &[u_cell, v_cell] = carried.cell_values[cell->id()];
            u_cell.reinit(cell->get_fe().n_dofs_per_cell());
            v_cell.reinit(cell->get_fe().n_dofs_per_cell());
            cell->get_dof_values(carried.U, u_cell);
            cell->get_dof_values(carried.V, v_cell);
          }
      return carried;
    }

    /**
     * The unknowns of the particles of the grown region: a free particle's own, the old FE
     * field's (@p field's FE space before its reweight) for the others (every new particle lies
     * in a cell that had FE unknowns).
     */
    template <int dim>
    void
    carry_to_particles(const Physics<dim> &field,
                       const Lattice<dim> &lattice,
                       CarriedState<dim>  &carried)
    {
      const unsigned int nc = field.layout.n_components();
      const auto        &ps = field.pd.particles();
      const auto        &y  = ps.positions();
      // Only the particles without values of their own need the old FE field.
      std::vector<bool> without_values(ps.n_owned());
      for (unsigned int i = 0; i < ps.n_owned(); ++i)
        without_values[i] = carried.free_values.count(lattice.key(y[i])) == 0;
      TransferOperator<dim> before;
      before.reinit(field.fe, ps, field.layout, without_values);
      ps.reinit_vector(carried.u, nc);
      ps.reinit_vector(carried.v, nc);
      before.interpolate(carried.U, carried.u);
      before.interpolate(carried.V, carried.v);
      for (unsigned int i = 0; i < ps.n_owned(); ++i)
        if (!before.is_slaved(i))
          {
            const auto found = carried.free_values.find(lattice.key(y[i]));
            AssertThrow(found != carried.free_values.end(),
                        ExcInternalError("A particle of the grown PD region is neither in a "
                                         "cell with FE unknowns nor a particle before."));
            for (unsigned int c = 0; c < nc; ++c)
              {
                carried.u.local_element(i * nc + c) = found->second[2 * c];
                carried.v.local_element(i * nc + c) = found->second[2 * c + 1];
              }
          }
    }

    /// Put the carried unknowns into @p field's state, set up on the new regions.
    template <int dim>
    void
    restore(Physics<dim> &field, const CarriedState<dim> &carried)
    {
      auto &state = field.state();
      for (unsigned int k = 0; k < carried.u.locally_owned_size(); ++k)
        {
          state.u.local_element(k) = carried.u.local_element(k);
          state.v.local_element(k) = carried.v.local_element(k);
        }
      state.u.update_ghost_values();
      state.v.update_ghost_values();
      std::vector<types::global_dof_index> dofs;
      for (const auto &cell : field.fe.get_dof_handler().active_cell_iterators())
        if (cell->is_locally_owned() && cell->active_fe_index() == 0)
          {
            const auto found = carried.cell_values.find(cell->id());
            AssertThrow(found != carried.cell_values.end(),
                        ExcInternalError("A cell gained FE unknowns in a conversion."));
            dofs.resize(cell->get_fe().n_dofs_per_cell());
            cell->get_dof_indices(dofs);
            for (unsigned int k = 0; k < dofs.size(); ++k)
              if (state.U.locally_owned_elements().is_element(dofs[k]))
                {
                  state.U(dofs[k]) = found->second.first[k];
                  state.V(dofs[k]) = found->second.second[k];
                }
          }
      state.U.update_ghost_values();
      state.V.update_ghost_values();
    }
  } // namespace

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
    for (unsigned int k = 0; k < physics.size(); ++k)
      adaptive.check_conditions_outside(physics[k]->fe,
                                        seeds,
                                        when.str(),
                                        k == 0 ? "" :
                                                 Physics<dim>::section(physics[k]->name) + "/");

    // The bonds the first physics broke since the other physics last advanced are recorded by
    // their index in the bond list, which the rebuild renumbers: share them now, while the
    // indices hold (a quasi-static run converts after its load step, before the other physics
    // advance to the next one; shared later, the old indices would break other bonds).
    exchange.share_broken_bonds(pd.particles().bonds());

    // What carries over, before anything changes: per physics the unknowns of the free
    // particles by lattice point (the others are slaved to the FE field and take it again) and
    // the FE dof values of each owned cell with unknowns (the mesh and its partition stay); the
    // broken bonds once (a particle keeps its rank: ParticleSystem's bins do not depend on
    // which lattice points exist); the heat stored by the other physics.
    auto                          &ps = pd.particles();
    std::vector<CarriedState<dim>> carried;
    std::vector<double>            stored_before;
    for (const auto &field : physics)
      {
        carried.push_back(keep(*field, lattice));
        stored_before.push_back(field->layout.has_temperature() ? field->state().stored_heat() :
                                                                  0.);
      }
    std::set<std::pair<Key, Key>> broken;
    {
      const auto &x     = ps.positions();
      const auto &bonds = ps.bonds();
      for (unsigned int i = 0; i < ps.n_owned(); ++i)
        for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
          if (bonds.intact[b] == 0)
            broken.emplace(lattice.key(x[i]), lattice.key(x[bonds.neighbor[b]]));
    }
    const unsigned int n_particles_before = ps.n_global();
    const auto         n_dofs_before      = fe.n_dofs();

    // The particles of the grown region, with every physics' unknowns from its FE field as it
    // was or their own (free particles); the kept broken bonds.
    adaptive.add_seeds(seeds);
    setup_particles(false);
    precrack_damage = damage_index(ps);
    for (unsigned int k = 0; k < physics.size(); ++k)
      carry_to_particles(*physics[k], lattice, carried[k]);
    {
      const auto &y     = ps.positions();
      auto       &bonds = ps.bonds();
      for (unsigned int i = 0; i < ps.n_owned(); ++i)
        for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
          if (bonds.intact[b] != 0 &&
              broken.count({lattice.key(y[i]), lattice.key(y[bonds.neighbor[b]])}))
            bonds.break_bond(b);
    }

    // Per physics, in the order of the set-up: its model on the new particles (the first
    // physics' in setup_particles()), the FE space without the cells that became PD only, the
    // coupling, the state with the carried unknowns and the postprocessors.
    for (unsigned int k = 0; k < physics.size(); ++k)
      {
        Physics<dim> &field = *physics[k];
        if (k > 0)
          field.with_entry_names([&field]() { field.pd.setup({}, {}, false); });
        field.fe.reweight(
          [&field, this](const Point<dim> &p) { return field.method().fe_weight(blending(p)); });
        field.method().initialize(coupled_regions(field));
        field.state().setup();
        restore(field, carried[k]);
        field.postprocessors().initialize(field.state());
      }
    // The temperature on the new particles and FE space (the first physics' solver renews its
    // forces with it).
    connect_temperature();

    if (is_root)
      log << when.str() << ": the PD region grew by " << seeds.size() << " disk"
          << (seeds.size() == 1 ? "" : "s") << " (" << adaptive.seed_points().size()
          << " in all): particles " << n_particles_before << " -> " << ps.n_global() << ", FE dofs "
          << n_dofs_before << " -> " << fe.n_dofs() << std::endl;

    // The other physics' solvers on the new regions (the first one's renews its own): their
    // masses or matrices, forces and steps; the change of the stored heat that the interpolation
    // makes is the conversion's, which the heat balance takes out (conversion_energy).
    for (unsigned int k = 1; k < physics.size(); ++k)
      {
        Physics<dim> &field = *physics[k];
        if (is_root)
          log << "  Physics " << field.name << ":" << std::endl;
        field.solver().renew_regions(field.state(), time);
        choose_sub_steps(k);
        if (!field.layout.has_temperature())
          continue;
        const double change = field.state().stored_heat() - stored_before[k];
        field.state().conversion_energy += change;
        if (is_root)
          log << "  stored heat before " << stored_before[k] << " J, after "
              << stored_before[k] + change << " J, change " << change << " J" << std::endl;
      }
    return true;
  }

  template bool
  CoupledProblem<2>::convert_regions(const unsigned int, const double);
  template bool
  CoupledProblem<3>::convert_regions(const unsigned int, const double);
} // namespace perideal
