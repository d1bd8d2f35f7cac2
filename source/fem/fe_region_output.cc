// ---------------------------------------------------------------------
// PeriDeal: what the finite-element region reports: its summary line, the physics' section
// integrals and the field output (the solution and the physics' derived quantities on the
// FE-carrying cells, with a thermal strain from the mechanical strain; HDF5/XDMF).
// ---------------------------------------------------------------------
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <perideal/base/hdf5_xdmf_writer.h>
#include <perideal/fem/fe_region.h>

#include <sstream>

#include <boost/serialization/vector.hpp>

namespace perideal
{
  using namespace dealii;

  namespace
  {
    // DataOut with the names and vector ranges of its point data in reach of
    // merged_step_data() (deal.II keeps them for its own writers).
    template <int dim>
    class FieldDataOut : public DataOut<dim>
    {
    public:
      using DataOut<dim>::get_dataset_names;
      using DataOut<dim>::get_nonscalar_data_ranges;
    };
  } // namespace

  template <int dim>
  std::vector<double>
  FERegion<dim>::section_integrals(const FEVector &u) const
  {
    std::vector<double> integrals(physics_model->integral_names().size(), 0.);
    if (integrals.empty() || n_dofs() == 0)
      return integrals;
    FEVector ghosted;
    initialize_vector(ghosted);
    ghosted = u;
    hanging_constraints.distribute(ghosted);
    ghosted.update_ghost_values();
    const auto            &fe = fe_collection[0];
    FEValues<dim>          fe_values(fe,
                            QGauss<dim>(degree + 1),
                            update_values | update_gradients | update_quadrature_points |
                              update_JxW_values);
    dealii::Vector<double> cell_values(fe.n_dofs_per_cell());
    std::vector<double>    weights;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && cell->active_fe_index() == 0)
        {
          fe_values.reinit(cell);
          // Per unit thickness: the integrals over the section.
          quadrature_weights(fe_values, weights);
          for (double &w : weights)
            w /= thickness;
          cell->get_dof_values(ghosted, cell_values);
          physics_model->add_cell_integrals(fe_values,
                                            cell->material_id(),
                                            weights,
                                            cell_values,
                                            integrals);
        }
    Utilities::MPI::sum(make_array_view(std::as_const(integrals)),
                        comm,
                        make_array_view(integrals));
    return integrals;
  }

  template <int dim>
  void
  FERegion<dim>::write_output(const std::string      &directory,
                              const std::string      &base_name,
                              const unsigned int      step,
                              const double            time,
                              const FEVector         &u,
                              std::vector<XDMFEntry> &records) const
  {
    if (n_dofs() == 0)
      return;
    // With a thermal strain, the stress of the mechanical strain and the temperature change
    // (without, point_temperature_change() is empty: the physics' postprocessor()).
    const auto derived = physics_model->thermal_postprocessor(point_temperature_change(time));
    FieldDataOut<dim> data_out;
    data_out.attach_dof_handler(dof_handler);
    // Only the locally owned cells that carry FE unknowns (not the FE_Nothing ones).
    using CellIterator       = typename Triangulation<dim>::cell_iterator;
    using ActiveCellIterator = typename Triangulation<dim>::active_cell_iterator;
    const auto selected      = [this](const ActiveCellIterator &cell) {
      return cell->is_locally_owned() &&
             typename DoFHandler<dim>::active_cell_iterator(&triangulation,
                                                            cell->level(),
                                                            cell->index(),
                                                            &dof_handler)
                 ->active_fe_index() == 0;
    };
    const auto next_selected = [selected](const Triangulation<dim> &tria, ActiveCellIterator cell) {
      while (cell != tria.end() && !selected(cell))
        ++cell;
      return cell == tria.end() ? tria.end() : CellIterator(cell);
    };
    data_out.set_cell_selection(
      [next_selected](const Triangulation<dim> &tria) {
        return next_selected(tria, tria.begin_active());
      },
      [next_selected](const Triangulation<dim> &tria, const CellIterator &cell) {
        ActiveCellIterator next(cell);
        return next_selected(tria, ++next);
      });
    // The translations as the vector 'displacement', every other component by its name
    // (output_names(): a temperature as 'temperature').
    std::vector<std::string>                                              names;
    std::vector<DataComponentInterpretation::DataComponentInterpretation> interpretation;
    for (unsigned int c = 0; c < layout.n_components(); ++c)
      {
        const bool translation = layout.kind(c) == ComponentKind::translation;
        names.push_back(output_names(layout[c])[0]);
        interpretation.push_back(translation ?
                                   DataComponentInterpretation::component_is_part_of_vector :
                                   DataComponentInterpretation::component_is_scalar);
      }
    data_out.add_data_vector(u, names, DataOut<dim>::type_dof_data, interpretation);
    data_out.add_data_vector(u, *derived);
    data_out.build_patches();
    write_hdf5_xdmf_step(merged_step_data(data_out.get_patches(),
                                          data_out.get_dataset_names(),
                                          data_out.get_nonscalar_data_ranges()),
                         comm,
                         directory,
                         base_name,
                         step,
                         time,
                         records);
  }

  template <int dim>
  std::string
  FERegion<dim>::summary() const
  {
    if (!has_mesh())
      return "FE region: none";
    std::ostringstream out;
    const auto         n_active = Utilities::MPI::sum<std::uint64_t>(
      [&] {
        std::uint64_t count = 0;
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned() && cell->active_fe_index() == 0)
            ++count;
        return count;
      }(),
      comm);
    out << "FE region: " << triangulation.n_global_active_cells() << " cells (" << n_active
        << " with FE_Q(" << degree << ")";
    if (layout.n_components() > 1)
      out << "^" << layout.n_components();
    out << "), " << dof_handler.n_dofs() << " dofs; " << physics_model->summary()
        << ", rho = " << density << " kg/m^3";
    return out.str();
  }

  // The members defined in this file (the class is instantiated in fe_region.cc).
#define PERIDEAL_INSTANTIATE(dim)                                                           \
  template void                FERegion<dim>::write_output(const std::string &,             \
                                            const std::string &,             \
                                            const unsigned int,              \
                                            const double,                    \
                                            const FEVector &,                \
                                            std::vector<XDMFEntry> &) const; \
  template std::string         FERegion<dim>::summary() const;                              \
  template std::vector<double> FERegion<dim>::section_integrals(const FEVector &) const;
  PERIDEAL_INSTANTIATE(2)
  PERIDEAL_INSTANTIATE(3)
#undef PERIDEAL_INSTANTIATE
} // namespace perideal
