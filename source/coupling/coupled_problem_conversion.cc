// ---------------------------------------------------------------------
// PeriDeal: the conversion of FE cells into particles when the adaptive PD region grows.
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>
#include <deal.II/lac/vector.h>

#include <perideal/base/parameter_utilities.h>
#include <perideal/coupling/coupled_problem.h>
#include <perideal/coupling/transfer_operator.h>
#include <perideal/pd/damage_model.h>
#include <perideal/pd/lattice.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <sstream>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

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

    /**
     * The state of the bonds that a conversion carries over, kept by the lattice points of the
     * two ends (the smaller key first: a row lists a bond between two owned particles from the
     * end of smaller local index, which the regeneration may change; the histories do not
     * depend on the bond's direction): whether it is broken, and its values of the model's bond
     * histories (MaterialModel::bond_history()). Only the bonds whose state differs from a new
     * bond's are kept, the broken ones and those with a history value other than 0 (a bond that
     * has not softened; a set-up starts every bond there): the others take that state from the
     * regeneration, and the map stays as small as the damage (a map of every bond would cost
     * about 100 B per bond of the PD zone at each conversion). Built from the owned rows, so
     * each rank keeps the bonds of its own particles (a particle keeps its rank in a
     * conversion, the particles are not balanced in an adaptive run,
     * CoupledProblem::setup_particles()).
     */
    template <int dim>
    class CarriedBonds
    {
    public:
      /// The bonds of @p ps's owned rows and their histories under @p model.
      CarriedBonds(const ParticleSystem<dim> &ps,
                   const MaterialModel<dim>  &model,
                   const Lattice<dim>        &lattice)
        : n_values(model.n_bond_history_values())
      {
        const auto               &x      = ps.positions();
        const auto               &bonds  = ps.bonds();
        const std::vector<double> values = model.bond_history(ps);
        for (unsigned int i = 0; i < ps.n_owned(); ++i)
          for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
            {
              const auto first  = values.begin() + std::size_t(b) * n_values;
              const bool broken = bonds.intact[b] == 0;
              if (!broken &&
                  std::all_of(first, first + n_values, [](const double v) { return v == 0.; }))
                continue;
              Record &record = records[pair(lattice, x[i], x[bonds.neighbor[b]])];
              record.broken  = broken;
              record.offset  = history.size();
              history.insert(history.end(), first, first + n_values);
              n_shares += bond_shares(ps, b);
            }
      }

      /**
       * Give the kept bonds of @p ps (regenerated, @p model initialized on it) their state:
       * break those that were broken and set their history values; the other bonds keep the
       * initial histories of the set-up. Every kept bond must exist again, on the same rank (a
       * particle's row lists all its bonds within the horizon): checked over all ranks.
       * Collective.
       */
      void
      restore(ParticleSystem<dim> &ps, MaterialModel<dim> &model, const Lattice<dim> &lattice) const
      {
        const auto         &y     = ps.positions();
        auto               &bonds = ps.bonds();
        std::vector<double> values;
        if (n_values > 0)
          {
            values = model.bond_history(ps);
            AssertThrow(values.size() == std::size_t(bonds.size()) * n_values,
                        ExcInternalError("The bond histories do not match the bond list."));
          }
        // A kept bond joins two particles that end kept bonds: the bonds of the others (most)
        // are passed over. Each end's kept bonds by the other end's key, sorted: one hash
        // lookup per particle, then a search in its own short list (a lookup of the pair per
        // bond took 2.6 % of the 1 mm plate's adaptive run, doc/benchmarks/performance).
        using Partner = std::pair<Key, const Record *>;
        std::unordered_map<Key, std::vector<Partner>, typename Lattice<dim>::KeyHash> partners;
        for (const auto &[ends_of_bond, record] : records)
          {
            partners[ends_of_bond.first].emplace_back(ends_of_bond.second, &record);
            partners[ends_of_bond.second].emplace_back(ends_of_bond.first, &record);
          }
        const auto by_key = [](const Partner &a, const Partner &b) { return a.first < b.first; };
        for (auto &[end, list] : partners)
          std::sort(list.begin(), list.end(), by_key);
        std::vector<Key>                          key(y.size());
        std::vector<const std::vector<Partner> *> kept(y.size(), nullptr);
        for (unsigned int i = 0; i < y.size(); ++i)
          {
            key[i]           = lattice.key(y[i]);
            const auto found = partners.find(key[i]);
            if (found != partners.end())
              kept[i] = &found->second;
          }
        std::uint64_t matched = 0;
        for (unsigned int i = 0; i < ps.n_owned(); ++i)
          if (kept[i] != nullptr)
            for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
              {
                const unsigned int j = bonds.neighbor[b];
                if (kept[j] == nullptr)
                  continue;
                const auto found = std::lower_bound(kept[i]->begin(),
                                                    kept[i]->end(),
                                                    Partner(key[j], nullptr),
                                                    by_key);
                if (found == kept[i]->end() || found->first != key[j])
                  continue;
                const Record &record = *found->second;
                matched += bond_shares(ps, b);
                if (record.broken && bonds.intact[b] != 0)
                  bonds.break_bond(b);
                std::copy(history.begin() + record.offset,
                          history.begin() + record.offset + n_values,
                          values.begin() + std::size_t(b) * n_values);
              }
        const MPI_Comm comm = ps.get_communicator();
        AssertThrow(Utilities::MPI::sum(matched, comm) == Utilities::MPI::sum(n_shares, comm),
                    ExcInternalError("A conversion lost bonds: " +
                                     std::to_string(Utilities::MPI::sum(n_shares, comm) / 2) +
                                     " broken or softened bonds before, of which " +
                                     std::to_string(Utilities::MPI::sum(matched, comm) / 2) +
                                     " are found again."));
        if (n_values > 0)
          model.set_bond_history(ps, values);
      }

    private:
      using Key = typename Lattice<dim>::Key;
      /// A bond's state: broken or not, and where its history values start in #history.
      struct Record
      {
        bool        broken = false;
        std::size_t offset = 0;
      };

      /// The key of the bond between @p a and @p b, the smaller lattice point first.
      static std::pair<Key, Key>
      pair(const Lattice<dim> &lattice, const Point<dim> &a, const Point<dim> &b)
      {
        return std::minmax(lattice.key(a), lattice.key(b));
      }

      /// Twice bond @p b's share in sums over unique bonds (ParticleSystem::bond_share()).
      static std::uint64_t
      bond_shares(const ParticleSystem<dim> &ps, const std::size_t b)
      {
        return ps.neighbor_is_owned(b) ? 2 : 1;
      }

      /// A hash of a bond's pair of keys.
      struct PairHash
      {
        std::size_t
        operator()(const std::pair<Key, Key> &keys) const
        {
          const typename Lattice<dim>::KeyHash hash;
          return hash(keys.first) * 1000003u ^ hash(keys.second);
        }
      };

      unsigned int                                              n_values;
      std::unordered_map<std::pair<Key, Key>, Record, PairHash> records;
      std::vector<double>                                       history;
      /// Twice the number of kept bonds over the ranks' shares (this rank's part).
      std::uint64_t n_shares = 0;
    };

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

    if (conversion_observer)
      conversion_observer(false);

    // The bonds the first physics broke since the other physics last advanced are recorded by
    // their index in the bond list, which the rebuild renumbers: share them now, while the
    // indices hold (a quasi-static run converts after its load step, before the other physics
    // advance to the next one; shared later, the old indices would break other bonds).
    exchange.share_broken_bonds(pd.particles().bonds());

    // What carries over, before anything changes: per physics the unknowns of the free
    // particles by lattice point (the others are slaved to the FE field and take it again) and
    // the FE dof values of each owned cell with unknowns (the mesh and its partition stay); the
    // bonds once, broken or not and their histories (a particle keeps its rank: ParticleSystem's
    // bins do not depend on which lattice points exist); the heat stored by the other physics.
    auto                          &ps = pd.particles();
    std::vector<CarriedState<dim>> carried;
    std::vector<double>            stored_before;
    for (const auto &field : physics)
      {
        carried.push_back(keep(*field, lattice));
        stored_before.push_back(field->layout.has_temperature() ? field->state().stored_heat() :
                                                                  0.);
      }
    const CarriedBonds<dim> carried_bonds(ps, pd.material(), lattice);
    const unsigned int      n_particles_before = ps.n_global();
    const auto              n_dofs_before      = fe.n_dofs();

    // The particles of the grown region, with every physics' unknowns from its FE field as it
    // was or their own (free particles); the kept bonds' states and histories (the new bonds
    // start at the model's initial histories, which setup_particles() gave every bond).
    adaptive.add_seeds(seeds);
    setup_particles(false);
    precrack_damage = damage_index(ps);
    for (unsigned int k = 0; k < physics.size(); ++k)
      carry_to_particles(*physics[k], lattice, carried[k]);
    carried_bonds.restore(ps, pd.material(), lattice);

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
    if (conversion_observer)
      conversion_observer(true);
    return true;
  }

  template <int dim>
  void
  CoupledProblem<dim>::observe_conversions(std::function<void(bool after)> observer)
  {
    conversion_observer = std::move(observer);
  }

  template void CoupledProblem<2>::observe_conversions(std::function<void(bool)>);
  template void CoupledProblem<3>::observe_conversions(std::function<void(bool)>);
  template bool
  CoupledProblem<2>::convert_regions(const unsigned int, const double);
  template bool
  CoupledProblem<3>::convert_regions(const unsigned int, const double);
} // namespace perideal
