// ---------------------------------------------------------------------
// PeriDeal: the thermal strain of the finite-element region (doc/theory/thermal_strain_fe.md):
// the temperature change it is given, the load f_th of the thermal strain with the constant c_th
// of the energy of the mechanical strain, 1/2 u.K.u - u.f_th + c_th, and the temperature change
// at the points of the output.
// ---------------------------------------------------------------------
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>

#include <perideal/fem/fe_region.h>

namespace perideal
{
  using namespace dealii;

  template <int dim>
  void
  FERegion<dim>::set_temperature_change(const TemperatureChange &delta_T)
  {
    temperature_change = delta_T;
  }

  template <int dim>
  template <typename Work>
  void
  FERegion<dim>::for_each_thermal_cell(const Work &work) const
  {
    FEValues<dim>       fe_values(fe_collection[0],
                            QGauss<dim>(degree + 1),
                            update_values | update_gradients | update_quadrature_points |
                              update_JxW_values);
    std::vector<double> weights;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && cell->active_fe_index() == 0)
        {
          fe_values.reinit(cell);
          quadrature_weights(fe_values, weights);
          work(cell, fe_values, weights);
        }
  }

  template <int dim>
  bool
  FERegion<dim>::has_thermal_strain() const
  {
    return temperature_change && physics_model->has_thermal_strain();
  }

  template <int dim>
  double
  FERegion<dim>::assemble_thermal_load(const double time, FEVector &f_th) const
  {
    f_th = 0.;
    if (!has_thermal_strain())
      return 0.;
    const unsigned int                   n = fe_collection[0].n_dofs_per_cell();
    dealii::Vector<double>               cell_rhs(n);
    std::vector<types::global_dof_index> dofs(n);
    std::vector<double>                  delta_T;
    double                               energy = 0.;
    for_each_thermal_cell(
      [&](const auto &cell, const FEValues<dim> &fe_values, const auto &weights) {
        delta_T.resize(fe_values.n_quadrature_points);
        temperature_change(fe_values, time, delta_T);
        cell_rhs = 0.;
        physics_model->add_cell_thermal_load(fe_values,
                                             cell->material_id(),
                                             weights,
                                             delta_T,
                                             cell_rhs);
        for (const unsigned int q : fe_values.quadrature_point_indices())
          energy +=
            weights[q] * physics_model->thermal_energy_density(cell->material_id(), delta_T[q]);
        cell->get_dof_indices(dofs);
        hanging_constraints.distribute_local_to_global(cell_rhs, dofs, f_th);
      });
    f_th.compress(VectorOperation::add);
    return Utilities::MPI::sum(energy, comm);
  }

  template <int dim>
  PointTemperatureChange<dim>
  FERegion<dim>::point_temperature_change(const double time) const
  {
    if (!has_thermal_strain())
      return {};
    return [this, time](const typename DoFHandler<dim>::cell_iterator &cell,
                        const std::vector<Point<dim>>                 &points,
                        std::vector<double>                           &delta_T) {
      // The points in the unit cell of the linear mapping that FEValues and DataOut use.
      const MappingQ1<dim>    mapping;
      std::vector<Point<dim>> unit(points.size());
      mapping.transform_points_real_to_unit_cell(cell, points, unit);
      FEValues<dim> fe_values(mapping,
                              fe_collection[0],
                              Quadrature<dim>(unit),
                              update_quadrature_points);
      fe_values.reinit(cell);
      temperature_change(fe_values, time, delta_T);
    };
  }

  template <int dim>
  void
  FERegion<dim>::thermoelastic_measure(const FEVector &u, const PointValues &add) const
  {
    dealii::Vector<double> cell_values(fe_collection[0].n_dofs_per_cell());
    std::vector<double>    measure;
    for_each_thermal_cell(
      [&](const auto &cell, const FEValues<dim> &fe_values, const auto &weights) {
        measure.resize(fe_values.n_quadrature_points);
        cell->get_dof_values(u, cell_values);
        physics_model->cell_thermoelastic_measure(fe_values,
                                                  cell->material_id(),
                                                  cell_values,
                                                  measure);
        for (const unsigned int q : fe_values.quadrature_point_indices())
          measure[q] *= weights[q];
        add(fe_values, measure);
      });
  }

  template <int dim>
  void
  FERegion<dim>::add_cell_vector(const typename DoFHandler<dim>::active_cell_iterator &cell,
                                 const dealii::Vector<double>                         &cell_vector,
                                 FEVector                                             &vector) const
  {
    std::vector<types::global_dof_index> dofs(cell->get_fe().n_dofs_per_cell());
    cell->get_dof_indices(dofs);
    hanging_constraints.distribute_local_to_global(cell_vector, dofs, vector);
  }

  // The members defined in this file (the class is instantiated in fe_region.cc).
#define PERIDEAL_INSTANTIATE(dim)                                                                  \
  template void   FERegion<dim>::set_temperature_change(const TemperatureChange &);                \
  template bool   FERegion<dim>::has_thermal_strain() const;                                       \
  template double FERegion<dim>::assemble_thermal_load(const double, FEVector &) const;            \
  template PointTemperatureChange<dim> FERegion<dim>::point_temperature_change(const double)       \
    const;                                                                                         \
  template void FERegion<dim>::thermoelastic_measure(const FEVector &, const PointValues &) const; \
  template void FERegion<dim>::add_cell_vector(                                                    \
    const typename DoFHandler<dim>::active_cell_iterator &,                                        \
    const dealii::Vector<double> &,                                                                \
    FEVector &) const;
  PERIDEAL_INSTANTIATE(2)
  PERIDEAL_INSTANTIATE(3)
#undef PERIDEAL_INSTANTIATE
} // namespace perideal
